#include "clitest.h"

#include "peer_datamap.h"

#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcess>
#include <QtNetwork/QTcpServer>

namespace mbscope::testcli {

QStringList sl(std::initializer_list<const char *> items)
{
    QStringList list;
    for (const char *i : items)
        list.append(QString::fromUtf8(i));
    return list;
}

QJsonObject CliResult::json() const
{
    return QJsonDocument::fromJson(out).object();
}

QByteArray CliResult::describe() const
{
    return "exit " + QByteArray::number(exitCode) + (finished ? "" : " (killed: did not finish)") + "\n--- stdout\n" + out
           + "\n--- stderr\n" + err;
}

QString mbscopePath()
{
    // MBSCOPE_UNDER_TEST runs the same tests against another build (say, main's, to show that a
    // new test fails there); the build's own executable otherwise.
    const QString other = qEnvironmentVariable("MBSCOPE_UNDER_TEST");
    return other.isEmpty() ? QStringLiteral(MBSCOPE_EXECUTABLE) : other;
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

CliResult runMbscope(const QStringList &arguments, int timeoutMs, const QProcessEnvironment &env)
{
    CliResult result;
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(mbscopePath(), arguments);
    if (!p.waitForStarted(30000)) {
        result.err = "cannot start " + mbscopePath().toUtf8() + ": " + p.errorString().toUtf8();
        return result;
    }
    p.closeWriteChannel();
    result.finished = p.waitForFinished(timeoutMs);
    if (!result.finished) {
        p.kill();
        p.waitForFinished(5000);
    }
    result.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    result.out = p.readAllStandardOutput();
    result.err = p.readAllStandardError();
    return result;
}

bool PymodbusTarget::start(const QString &mode, QString *error)
{
    if (!testpeers::pymodbusAvailable(error))
        return false;
    m_peer = std::make_unique<testpeers::PeerProcess>();
    if (!m_peer->start(testpeers::systemPython(), {testpeers::peersDir() + QStringLiteral("/pymodbus_server.py"), mode})) {
        *error = m_peer->error();
        return false;
    }
    m_url = QStringLiteral("%1://127.0.0.1:%2").arg(mode).arg(m_peer->port());
    return true;
}

quint16 closedPort()
{
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost, 0))
        return 0;
    const quint16 port = server.serverPort();
    server.close();
    return port;
}

quint16 holdingRegister(int address)
{
    return peer_holding_register(unsigned(address));
}

quint16 inputRegister(int address)
{
    return peer_input_register(unsigned(address));
}

bool coil(int address)
{
    return peer_coil(unsigned(address)) != 0;
}

} // namespace mbscope::testcli
