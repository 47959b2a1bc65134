#include "peerprocess.h"

#include <QtCore/QDeadlineTimer>
#include <QtCore/QFileInfo>
#include <QtCore/QStandardPaths>
#include <QtCore/QThread>

namespace mbscope::testpeers {

namespace {

// Runs a short command to probe for a package; true when it exits with status 0.
bool probe(const QString &program, const QStringList &args)
{
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(30000)) {
        p.kill();
        p.waitForFinished(1000);
        return false;
    }
    return p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
}

} // namespace

QString peersDir()
{
    return QStringLiteral(MBSCOPE_PEERS_DIR);
}

QString libmodbusServerPath()
{
    return QStringLiteral(MBSCOPE_LIBMODBUS_SERVER);
}

QString libmodbusClientPath()
{
    return QStringLiteral(MBSCOPE_LIBMODBUS_CLIENT);
}

QString libmodbusManyClientsPath()
{
    return QStringLiteral(MBSCOPE_MANY_CLIENTS);
}

QString systemPython()
{
    return QStringLiteral("/usr/bin/python3");
}

bool pymodbusAvailable(QString *why)
{
    if (!QFileInfo(systemPython()).isExecutable()) {
        *why = QStringLiteral("/usr/bin/python3 is missing (Debian: apt-get install python3-pymodbus)");
        return false;
    }
    // Serial modes need pyserial-asyncio too; it comes with python3-pymodbus on Debian.
    if (!probe(systemPython(), {QStringLiteral("-c"), QStringLiteral("import pymodbus, serial_asyncio")})) {
        *why = QStringLiteral("pymodbus is not importable by /usr/bin/python3 (Debian: apt-get install "
                              "python3-pymodbus python3-serial-asyncio)");
        return false;
    }
    return true;
}

bool libmodbusPeersAvailable(QString *why)
{
    if (libmodbusServerPath().isEmpty() || !QFileInfo(libmodbusServerPath()).isExecutable()) {
        *why = QStringLiteral("the libmodbus peers were not built (Debian: apt-get install libmodbus-dev, "
                              "then configure again)");
        return false;
    }
    return true;
}

bool socatAvailable(QString *why)
{
    if (QStandardPaths::findExecutable(QStringLiteral("socat")).isEmpty()) {
        *why = QStringLiteral("socat is not installed (Debian: apt-get install socat)");
        return false;
    }
    return true;
}

PeerProcess::~PeerProcess()
{
    stop();
}

bool PeerProcess::start(const QString &program, const QStringList &args, int timeoutMs)
{
    stop();
    m_lines.clear();
    m_partial.clear();
    m_where.clear();
    m_error.clear();
    m_process = std::make_unique<QProcess>();
    m_process->setProgram(program);
    m_process->setArguments(args);
    m_process->start();
    if (!m_process->waitForStarted(timeoutMs)) {
        m_error = program + QStringLiteral(": could not start: ") + m_process->errorString();
        return false;
    }
    QByteArray line;
    if (!waitForLine("LISTENING ", timeoutMs, &line)) {
        m_error = program + QLatin1Char(' ') + args.join(QLatin1Char(' ')) + QStringLiteral(": no LISTENING line within ")
                  + QString::number(timeoutMs) + QStringLiteral(" ms; stderr: ") + QString::fromLocal8Bit(standardError());
        stop();
        return false;
    }
    m_where = QString::fromLocal8Bit(line.mid(int(qstrlen("LISTENING "))).trimmed());
    return true;
}

void PeerProcess::stop()
{
    if (!m_process)
        return;
    if (m_process->state() != QProcess::NotRunning) {
        m_process->closeWriteChannel(); // the peers leave when their stdin ends
        if (!m_process->waitForFinished(3000)) {
            m_process->kill();
            m_process->waitForFinished(3000);
        }
    }
    m_process.reset();
}

bool PeerProcess::isRunning() const
{
    return m_process && m_process->state() == QProcess::Running;
}

quint16 PeerProcess::port() const
{
    const int colon = int(m_where.lastIndexOf(QLatin1Char(':')));
    return colon < 0 ? 0 : quint16(m_where.mid(colon + 1).toUInt());
}

bool PeerProcess::takeLine(const QByteArray &prefix, QByteArray *line)
{
    m_partial += m_process->readAllStandardOutput();
    for (int nl = int(m_partial.indexOf('\n')); nl >= 0; nl = int(m_partial.indexOf('\n'))) {
        m_lines.append(m_partial.left(nl));
        m_partial.remove(0, nl + 1);
    }
    for (int i = 0; i < m_lines.size(); ++i) {
        if (m_lines.at(i).startsWith(prefix)) {
            if (line)
                *line = m_lines.at(i);
            m_lines.remove(0, i + 1); // lines before it are read past
            return true;
        }
    }
    return false;
}

bool PeerProcess::waitForLine(const QByteArray &prefix, int timeoutMs, QByteArray *line)
{
    if (!m_process)
        return false;
    QDeadlineTimer deadline(timeoutMs);
    while (!takeLine(prefix, line)) {
        if (deadline.hasExpired() || m_process->state() == QProcess::NotRunning)
            return false;
        // Short waits: data may have arrived on stderr only, which wakes no stdout wait.
        m_process->waitForReadyRead(int(qMin<qint64>(100, qMax<qint64>(1, deadline.remainingTime()))));
    }
    return true;
}

bool PeerProcess::command(const QByteArray &line, const QByteArray &expectPrefix, int timeoutMs)
{
    if (!isRunning()) {
        m_error = QStringLiteral("peer is not running");
        return false;
    }
    m_process->write(line + '\n');
    m_process->waitForBytesWritten(timeoutMs);
    QByteArray answer;
    if (!waitForLine(expectPrefix, timeoutMs, &answer)) {
        m_error = QStringLiteral("no '") + QString::fromLatin1(expectPrefix) + QStringLiteral("' after '")
                  + QString::fromLatin1(line) + QStringLiteral("'; stderr: ") + QString::fromLocal8Bit(standardError());
        return false;
    }
    return true;
}

QByteArray PeerProcess::standardError()
{
    return m_process ? m_process->readAllStandardError() : QByteArray();
}

PtyPair::~PtyPair()
{
    if (m_socat && m_socat->state() != QProcess::NotRunning) {
        m_socat->terminate();
        if (!m_socat->waitForFinished(3000)) {
            m_socat->kill();
            m_socat->waitForFinished(3000);
        }
    }
}

bool PtyPair::start(int timeoutMs)
{
    m_dir = std::make_unique<QTemporaryDir>();
    if (!m_dir->isValid()) {
        m_error = QStringLiteral("no temporary directory: ") + m_dir->errorString();
        return false;
    }
    m_a = m_dir->filePath(QStringLiteral("peer"));
    m_b = m_dir->filePath(QStringLiteral("mbscope"));
    m_socat = std::make_unique<QProcess>();
    m_socat->setReadChannel(QProcess::StandardError); // socat -d -d reports on stderr
    // raw, no echo: bytes pass unchanged both ways, as on a serial line.
    m_socat->start(QStringLiteral("socat"),
                   {QStringLiteral("-d"), QStringLiteral("-d"),
                    QStringLiteral("pty,raw,echo=0,link=") + m_a, QStringLiteral("pty,raw,echo=0,link=") + m_b});
    QDeadlineTimer deadline(timeoutMs);
    QByteArray log;
    while (!log.contains("starting data transfer loop")) {
        if (deadline.hasExpired() || m_socat->state() == QProcess::NotRunning) {
            m_error = QStringLiteral("socat did not make a pty pair: ") + QString::fromLocal8Bit(log);
            return false;
        }
        m_socat->waitForReadyRead(100);
        log += m_socat->readAllStandardError();
    }
    if (!QFileInfo::exists(m_a) || !QFileInfo::exists(m_b)) {
        m_error = QStringLiteral("socat made no links ") + m_a + QStringLiteral(", ") + m_b;
        return false;
    }
    return true;
}

} // namespace mbscope::testpeers
