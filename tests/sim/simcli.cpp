#include "simcli.h"

#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>

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

namespace {

bool openssl(const QString &program, const QString &dir, const QStringList &arguments, QString *error)
{
    QProcess process;
    process.setWorkingDirectory(dir);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    if (!process.waitForFinished(60000) || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        *error = QStringLiteral("openssl %1 failed: %2").arg(arguments.join(QLatin1Char(' ')), QString::fromLocal8Bit(process.readAll()));
        return false;
    }
    return true;
}

} // namespace

bool makeTestCertificates(const QString &dir, QString *error)
{
    const QString program = QStandardPaths::findExecutable(QStringLiteral("openssl"));
    if (program.isEmpty()) {
        *error = QStringLiteral("openssl is not installed (Debian: openssl): no certificates to test TLS with");
        return false;
    }
    const QStringList ec = {QStringLiteral("-newkey"), QStringLiteral("ec"), QStringLiteral("-pkeyopt"),
                            QStringLiteral("ec_paramgen_curve:prime256v1"), QStringLiteral("-nodes")};
    if (!openssl(program, dir,
                 QStringList{QStringLiteral("req"), QStringLiteral("-x509")} + ec
                     + QStringList{QStringLiteral("-keyout"), QStringLiteral("ca.key"), QStringLiteral("-out"), QStringLiteral("ca.pem"),
                                   QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-subj"), QStringLiteral("/CN=mbscope test CA")},
                 error))
        return false;
    const QList<std::pair<QString, QByteArray>> leaves = {
        {QStringLiteral("server"), "subjectAltName=IP:127.0.0.1\nextendedKeyUsage=serverAuth\n"},
        {QStringLiteral("client"), "extendedKeyUsage=clientAuth\n"},
    };
    for (const auto &[name, extensions] : leaves) {
        QFile ext(QDir(dir).filePath(name + QStringLiteral(".ext")));
        if (!ext.open(QIODevice::WriteOnly) || ext.write(extensions) != extensions.size()) {
            *error = QStringLiteral("cannot write %1: %2").arg(ext.fileName(), ext.errorString());
            return false;
        }
        ext.close();
        if (!openssl(program, dir,
                     QStringList{QStringLiteral("req")} + ec
                         + QStringList{QStringLiteral("-keyout"), name + QStringLiteral(".key"), QStringLiteral("-out"),
                                       name + QStringLiteral(".csr"), QStringLiteral("-subj"), QStringLiteral("/CN=") + name},
                     error)
            || !openssl(program, dir,
                        {QStringLiteral("x509"), QStringLiteral("-req"), QStringLiteral("-in"), name + QStringLiteral(".csr"),
                         QStringLiteral("-CA"), QStringLiteral("ca.pem"), QStringLiteral("-CAkey"), QStringLiteral("ca.key"),
                         QStringLiteral("-CAcreateserial"), QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-extfile"),
                         name + QStringLiteral(".ext"), QStringLiteral("-out"), name + QStringLiteral(".pem")},
                        error))
            return false;
    }
    return true;
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
