#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QProcess>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QTemporaryDir>

#include <memory>

namespace mbscope::testpeers {

// Where the peers live: the Python ones in the source tree, the libmodbus ones in the build tree
// (empty when libmodbus was not found at configure time).
[[nodiscard]] QString peersDir();
[[nodiscard]] QString libmodbusServerPath();
[[nodiscard]] QString libmodbusClientPath();
// N libmodbus masters as threads (libmodbus_many_clients.c): one line of figures.
[[nodiscard]] QString libmodbusManyClientsPath();
// Debian's interpreter, which has python3-pymodbus (the python3 on PATH may be another one).
[[nodiscard]] QString systemPython();

// Whether a peer can run here; when not, why (for QSKIP): the package to install.
[[nodiscard]] bool pymodbusAvailable(QString *why);
[[nodiscard]] bool libmodbusPeersAvailable(QString *why);
[[nodiscard]] bool socatAvailable(QString *why);

// A peer process started by a test: waits for its "LISTENING where" line, answers control
// commands, and is stopped when the object goes (also when a test fails half-way: a QVERIFY
// returns, the destructor runs). Closing the peer's standard input is how it is told to leave;
// every peer also exits by itself when its parent dies (its stdin closes) or after its lifetime.
class PeerProcess
{
public:
    PeerProcess() = default;
    ~PeerProcess();
    PeerProcess(const PeerProcess &) = delete;
    PeerProcess &operator=(const PeerProcess &) = delete;

    // Starts program with args and waits up to timeoutMs for "LISTENING ..." on its stdout.
    [[nodiscard]] bool start(const QString &program, const QStringList &args, int timeoutMs = 20000);
    void stop();

    [[nodiscard]] bool isRunning() const;
    // What came after "LISTENING ": "127.0.0.1:PORT" or a device path.
    [[nodiscard]] const QString &where() const { return m_where; }
    [[nodiscard]] quint16 port() const;
    // Why start() or command() failed, with the peer's stderr.
    [[nodiscard]] const QString &error() const { return m_error; }

    // Writes a line to the peer's stdin and waits for a stdout line starting with expectPrefix.
    [[nodiscard]] bool command(const QByteArray &line, const QByteArray &expectPrefix, int timeoutMs = 5000);
    // Waits for a stdout line starting with prefix (lines read before and not matched are kept
    // for later calls).
    [[nodiscard]] bool waitForLine(const QByteArray &prefix, int timeoutMs, QByteArray *line = nullptr);
    [[nodiscard]] QByteArray standardError();

private:
    bool takeLine(const QByteArray &prefix, QByteArray *line);

    std::unique_ptr<QProcess> m_process;
    QList<QByteArray> m_lines;
    QByteArray m_partial;
    QString m_where;
    QString m_error;
};

// Two connected pseudo-terminals made by socat: the peer opens one end, mbscope the other.
// The links are named inside a temporary directory that goes with the object.
class PtyPair
{
public:
    PtyPair() = default;
    ~PtyPair();
    PtyPair(const PtyPair &) = delete;
    PtyPair &operator=(const PtyPair &) = delete;

    [[nodiscard]] bool start(int timeoutMs = 10000);
    [[nodiscard]] QString peerEnd() const { return m_a; }
    [[nodiscard]] QString ourEnd() const { return m_b; }
    [[nodiscard]] const QString &error() const { return m_error; }

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<QProcess> m_socat;
    QString m_a;
    QString m_b;
    QString m_error;
};

} // namespace mbscope::testpeers
