#pragma once

#include "peerprocess.h"

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtCore/QProcessEnvironment>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <csignal>
#include <initializer_list>
#include <memory>

namespace mbscope::testcli {

// What one run of the mbscope executable left.
struct CliResult {
    bool finished = false; // within the time allowed (else it was killed)
    int exitCode = -1;
    QByteArray out;
    QByteArray err;

    [[nodiscard]] QString outText() const { return QString::fromUtf8(out); }
    [[nodiscard]] QString errText() const { return QString::fromUtf8(err); }
    // Standard output parsed as a JSON object (empty when it is not one).
    [[nodiscard]] QJsonObject json() const;
    // For failure messages: exit status and both streams.
    [[nodiscard]] QByteArray describe() const;
};

// An argument list from C strings: sl({"read", "-r", "121"}).
[[nodiscard]] QStringList sl(std::initializer_list<const char *> items);

// The mbscope executable under test (the build's, passed in by CMake).
[[nodiscard]] QString mbscopePath();

// Runs mbscope with arguments and waits for it (killed after timeoutMs). env: the test's own by default.
[[nodiscard]] CliResult runMbscope(const QStringList &arguments, int timeoutMs = 120000,
                                   const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment());

// Writes bytes to path (created or replaced): false when it cannot.
[[nodiscard]] bool writeFile(const QString &path, const QByteArray &bytes);

// A pymodbus server (tests/peers/pymodbus_server.py) in one mode ("tcp", "udp", "rtu-tcp",
// "ascii-tcp"), on a port it chooses, stopped when the object goes.
class PymodbusTarget
{
public:
    [[nodiscard]] bool start(const QString &mode, QString *error);
    // "tcp://127.0.0.1:PORT"
    [[nodiscard]] QString url() const { return m_url; }
    [[nodiscard]] bool isRunning() const { return m_peer && m_peer->isRunning(); }

private:
    std::unique_ptr<testpeers::PeerProcess> m_peer;
    QString m_url;
};

// A port on 127.0.0.1 where nothing listens: bound by the OS's choice, then released.
[[nodiscard]] quint16 closedPort();

// Big-endian registers in hex ("03E8 03EB") from the peers' data map (peer_datamap.h).
[[nodiscard]] quint16 holdingRegister(int address);
[[nodiscard]] quint16 inputRegister(int address);
[[nodiscard]] bool coil(int address);

// A long-running mbscope subcommand (simulate, replay --serve): started, its "listening URL"
// line read, stopped with SIGINT as Ctrl-C stops it.
class Background
{
public:
    ~Background() { stop(); }
    bool start(const QStringList &arguments, QString *error)
    {
        m_process = std::make_unique<QProcess>();
        m_process->start(mbscopePath(), arguments);
        if (!m_process->waitForStarted(30000)) {
            *error = QStringLiteral("cannot start mbscope: ") + m_process->errorString();
            return false;
        }
        QByteArray seen;
        while (m_process->waitForReadyRead(30000)) {
            seen += m_process->readAllStandardOutput();
            const qsizetype at = seen.indexOf("listening ");
            const qsizetype end = at < 0 ? -1 : seen.indexOf('\n', at);
            if (end > at) {
                m_url = QString::fromUtf8(seen.mid(at + 10, end - at - 10)).section(QLatin1Char(' '), 0, 0);
                m_out = seen;
                return true;
            }
        }
        *error = QStringLiteral("no 'listening' line from mbscope %1: %2 %3")
                     .arg(arguments.join(QLatin1Char(' ')), QString::fromUtf8(seen), QString::fromUtf8(m_process->readAllStandardError()));
        return false;
    }
    [[nodiscard]] QString url() const { return m_url; }
    [[nodiscard]] qint64 pid() const { return m_process ? m_process->processId() : 0; }
    [[nodiscard]] bool isRunning() const { return m_process && m_process->state() == QProcess::Running; }
    // Standard output and error once stopped.
    QByteArray stop(QByteArray *err = nullptr)
    {
        if (m_process && m_process->state() != QProcess::NotRunning) {
            ::kill(pid_t(m_process->processId()), SIGINT);
            if (!m_process->waitForFinished(10000))
                m_process->kill();
            m_out += m_process->readAllStandardOutput();
            m_err += m_process->readAllStandardError();
        }
        if (err)
            *err = m_err;
        return m_out;
    }

private:
    std::unique_ptr<QProcess> m_process;
    QString m_url;
    QByteArray m_out;
    QByteArray m_err;
};

} // namespace mbscope::testcli
