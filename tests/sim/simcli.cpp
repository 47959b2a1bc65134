#include "simcli.h"

#include "testcertificates.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QRegularExpression>

#include <csignal>

namespace mbscope::simtest {

QString mbscopePath()
{
    return QStringLiteral(MBSCOPE_EXECUTABLE);
}

Run runProcess(const QString &program, const QStringList &args, int timeoutMs)
{
    QProcess p;
    p.start(program, args);
    Run r;
    if (!p.waitForStarted(10000)) {
        r.err = p.errorString().toUtf8();
        return r;
    }
    p.closeWriteChannel();
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished(5000);
        r.err = "timed out\n";
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out += p.readAllStandardOutput();
    r.err += p.readAllStandardError();
    return r;
}

Run runSimulate(const QStringList &args, int timeoutMs)
{
    return runProcess(mbscopePath(), QStringList{QStringLiteral("simulate")} + args, timeoutMs);
}

SimCli::~SimCli()
{
    if (m_process && m_process->state() != QProcess::NotRunning) {
        m_process->kill();
        m_process->waitForFinished(5000);
    }
}

bool SimCli::start(const QStringList &args, int endpoints, QString *error)
{
    m_process = std::make_unique<QProcess>();
    m_process->start(mbscopePath(), QStringList{QStringLiteral("simulate")} + args);
    if (!m_process->waitForStarted(10000)) {
        *error = m_process->errorString();
        return false;
    }
    QElapsedTimer timer;
    timer.start();
    while (m_listening.size() < endpoints && timer.elapsed() < 20000) {
        if (m_process->state() == QProcess::NotRunning)
            break;
        m_process->waitForReadyRead(200);
        m_out += m_process->readAllStandardOutput();
        m_listening.clear();
        for (const QByteArray &line : m_out.split('\n')) {
            if (line.startsWith("listening "))
                m_listening << QString::fromUtf8(line.mid(10));
        }
    }
    if (m_listening.size() < endpoints) {
        *error = QStringLiteral("no listening lines; stdout: %1 stderr: %2")
                     .arg(QString::fromUtf8(m_out), QString::fromUtf8(m_process->readAllStandardError()));
        return false;
    }
    return true;
}

quint16 SimCli::port(int index) const
{
    // "tcp://127.0.0.1:PORT (unit...", "tls://127.0.0.1:PORT?cert=... (unit..."
    static const QRegularExpression re(QStringLiteral("^[a-z-]+://[^/?:]+:(\\d+)"));
    return quint16(re.match(m_listening.value(index)).captured(1).toUInt());
}

bool SimCli::waitForOutput(const QByteArray &text, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!m_out.contains(text) && timer.elapsed() < timeoutMs && m_process->state() == QProcess::Running) {
        m_process->waitForReadyRead(100);
        m_out += m_process->readAllStandardOutput();
    }
    return m_out.contains(text);
}

int SimCli::stop()
{
    ::kill(pid_t(m_process->processId()), SIGINT);
    if (!m_process->waitForFinished(20000))
        return -1;
    m_out += m_process->readAllStandardOutput();
    m_err += m_process->readAllStandardError();
    return m_process->exitStatus() == QProcess::NormalExit ? m_process->exitCode() : -1;
}

bool makeTestCertificates(const QString &dir, QString *error)
{
    testing::TestCertificates certificates(dir);
    const bool made = certificates.makeCa(QStringLiteral("ca"), QStringLiteral("/CN=mbscope test CA"))
        && certificates.issue(QStringLiteral("server"), "subjectAltName=IP:127.0.0.1\nextendedKeyUsage=serverAuth\n", QStringLiteral("ca"))
        && certificates.issue(QStringLiteral("client"), "extendedKeyUsage=clientAuth\n", QStringLiteral("ca"));
    if (!made)
        *error = certificates.error();
    return made;
}

QMap<int, int> mbpollValues(const QByteArray &output)
{
    QMap<int, int> values;
    static const QRegularExpression re(QStringLiteral("^\\[(\\d+)\\]:\\s+(-?\\d+)"));
    for (const QByteArray &line : output.split('\n')) {
        const QRegularExpressionMatch m = re.match(QString::fromLatin1(line.trimmed()));
        if (m.hasMatch())
            values.insert(m.captured(1).toInt(), m.captured(2).toInt());
    }
    return values;
}

} // namespace mbscope::simtest
