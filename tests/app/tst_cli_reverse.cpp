// Reverse connections end to end (issue 27): a device that dials out to mbscope, which listens
// (--target URL?mode=listen) and is master on the connection the device opens. The "device" is
// socat dialling mbscope's port and relaying to `mbscope simulate` (as the guide's example does),
// or tests/peers/dialout_device.py, which closes its connection after a number of answers and
// dials again. Every command that takes --target gets the link the same way (Link::create).

#include "clitest.h"

#include <QtCore/QJsonArray>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace mbscope::testcli;

namespace {

const QString kRequest = QStringLiteral("01 03 00 79 00 16 15 DD"); // the RosRao gamma detector's read

quint16 portOf(const QString &url)
{
    return quint16(url.section(QLatin1Char(':'), -1).toUInt());
}

// socat as a device that dials out: connects to mbscope's listening port (trying again every
// 50 ms until it listens) and relays to the simulator. It ends when mbscope closes.
class Dialler
{
public:
    ~Dialler()
    {
        if (m_process.state() != QProcess::NotRunning) {
            m_process.kill();
            m_process.waitForFinished(5000);
        }
    }
    bool start(quint16 listenPort, quint16 simulatorPort, QString *error)
    {
        m_process.start(QStringLiteral("socat"), {QStringLiteral("TCP:127.0.0.1:%1,retry=600,interval=0.05").arg(listenPort),
                                                  QStringLiteral("TCP:127.0.0.1:%1").arg(simulatorPort)});
        if (!m_process.waitForStarted(10000)) {
            *error = QStringLiteral("cannot start socat: ") + m_process.errorString();
            return false;
        }
        return true;
    }
    // socat leaves when mbscope has closed the connection.
    bool waitForEnd() { return m_process.waitForFinished(30000); }

private:
    QProcess m_process;
};

} // namespace

class TestCliReverse : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    Background m_simulator; // rosrao-gamma on rtu-tcp
    QString m_simulatorUrl;
    QString m_skip;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        if (!mbscope::testpeers::socatAvailable(&m_skip))
            return;
        QVERIFY2(m_simulator.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"),
                                    QStringLiteral("--listen"), QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                                   &m_skip),
                 qPrintable(m_skip));
        m_simulatorUrl = m_simulator.url();
    }
    void init()
    {
        if (m_simulatorUrl.isEmpty())
            QSKIP(qPrintable(m_skip));
    }

    // Each command, through a listening target the device dials: the same answer as directly.
    void everyCommand_data()
    {
        QTest::addColumn<QStringList>("arguments"); // TARGET stands for the URL
        QTest::addColumn<QString>("expected");      // in standard output
        const QString target = QStringLiteral("TARGET");
        QTest::newRow("read") << QStringList{QStringLiteral("read"), QStringLiteral("--target"), target, QStringLiteral("--unit"),
                                             QStringLiteral("1"), QStringLiteral("--function"), QStringLiteral("3"),
                                             QStringLiteral("--address"), QStringLiteral("0x79"), QStringLiteral("--quantity"),
                                             QStringLiteral("22"), QStringLiteral("--json")}
                              << QStringLiteral("\"values\"");
        QTest::newRow("send") << QStringList{QStringLiteral("send"), QStringLiteral("--target"), target, QStringLiteral("--hex"), kRequest}
                              << QStringLiteral("Read Holding Registers");
        QTest::newRow("poll") << QStringList{QStringLiteral("poll"), QStringLiteral("--target"), target, QStringLiteral("--hex"), kRequest,
                                             QStringLiteral("--interval"), QStringLiteral("10ms"), QStringLiteral("--count"),
                                             QStringLiteral("5")}
                              << QStringLiteral("transactions         5  ok 5 (100.0 %)  failed 0");
        QTest::newRow("scan") << QStringList{QStringLiteral("scan"), QStringLiteral("--target"), target, QStringLiteral("--units"),
                                             QStringLiteral("1-3")}
                              << QStringLiteral("found 2 device(s); completed");
        QTest::newRow("run") << QStringList{QStringLiteral("run"),
                                            QStringLiteral(MBSCOPE_SOURCE_DIR "/docs/examples/rosrao-gamma.mbscope.json"),
                                            QStringLiteral("--target"), target}
                             << QStringLiteral("pass");
    }
    void everyCommand()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, expected);
        const quint16 port = closedPort();
        const QString reverse = QStringLiteral("rtu-tcp://127.0.0.1:%1?mode=listen&connect_timeout=20s").arg(port);
        QStringList reversed = arguments;
        reversed.replace(reversed.indexOf(QStringLiteral("TARGET")), reverse);
        QStringList direct = arguments;
        direct.replace(direct.indexOf(QStringLiteral("TARGET")), m_simulatorUrl);

        const CliResult straight = runMbscope(direct);
        QVERIFY2(straight.exitCode == 0, straight.describe());
        QVERIFY2(straight.outText().contains(expected), straight.describe());
        Dialler device;
        QString why;
        QVERIFY2(device.start(port, portOf(m_simulatorUrl), &why), qPrintable(why));
        const CliResult r = runMbscope(reversed);
        QVERIFY2(r.exitCode == 0, r.describe());
        QVERIFY2(r.outText().contains(expected), r.describe());
        if (arguments.first() == QStringLiteral("read")) {
            // The simulator's values, as a direct read gets them.
            QCOMPARE(r.json().value(QStringLiteral("values")), straight.json().value(QStringLiteral("values")));
            QCOMPARE(r.json().value(QStringLiteral("target")).toString(),
                     QStringLiteral("rtu-tcp://127.0.0.1:%1?connect_timeout=20000ms&mode=listen").arg(port));
        }
        QVERIFY(device.waitForEnd());
    }

    // Nobody dials in: a clear message and the exit status of any unreachable target.
    void noDeviceConnects()
    {
        const quint16 port = closedPort();
        const QString url = QStringLiteral("rtu-tcp://127.0.0.1:%1?connect_timeout=300ms&mode=listen").arg(port);
        const CliResult r = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), url, QStringLiteral("--address"),
                                        QStringLiteral("0x79"), QStringLiteral("--quantity"), QStringLiteral("2")});
        const CliResult refused = runMbscope({QStringLiteral("read"), QStringLiteral("--target"),
                                              QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(port), QStringLiteral("--address"),
                                              QStringLiteral("0x79"), QStringLiteral("--quantity"), QStringLiteral("2")});
        QVERIFY2(r.finished && r.exitCode == 2, r.describe());
        QCOMPARE(r.exitCode, refused.exitCode);
        const QString said = QStringLiteral("rtu-tcp://127.0.0.1:%1?connect_timeout=300ms&mode=listen: no device connected to "
                                            "127.0.0.1:%1 within 300 ms (connect timeout): the device must connect to this "
                                            "address and port")
                                 .arg(port);
        QVERIFY2(r.errText().contains(said) || r.outText().contains(said), r.describe());
    }

    // The device hangs up on the 5th request and dials again: the poll goes on over the new
    // connection, and every request but the one it hung up on is answered.
    void deviceDialsAgain()
    {
        const quint16 port = closedPort();
        QProcess device;
        device.start(mbscope::testpeers::systemPython(),
                     {mbscope::testpeers::peersDir() + QStringLiteral("/dialout_device.py"), QString::number(port),
                      QString::number(portOf(m_simulatorUrl)), QStringLiteral("--answers"), QStringLiteral("4"),
                      QStringLiteral("--connections"), QStringLiteral("2"), QStringLiteral("--hang-up-on-request")});
        QVERIFY2(device.waitForStarted(10000), qPrintable(device.errorString()));
        const CliResult r = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"),
                                        QStringLiteral("rtu-tcp://127.0.0.1:%1?mode=listen&connect_timeout=20s").arg(port),
                                        QStringLiteral("--hex"), kRequest, QStringLiteral("--interval"), QStringLiteral("100ms"),
                                        QStringLiteral("--count"), QStringLiteral("9"), QStringLiteral("--json"), QStringLiteral("--stats")});
        device.closeWriteChannel();
        QVERIFY(device.waitForFinished(10000));
        const QString log = QString::fromUtf8(device.readAllStandardOutput());
        QVERIFY2(log.contains(QStringLiteral("DROPPED 1")), qPrintable(log));
        QVERIFY2(log.contains(QStringLiteral("CONNECTED 2")), qPrintable(log));
        QVERIFY2(log.contains(QStringLiteral("ANSWERED 2 4")), qPrintable(log)); // 4 + the one dropped + 4
        // The 5th request met the hang-up: one link error, said as such, and the exit status says
        // the run was not clean; the other 8 were answered over two connections.
        QVERIFY2(r.exitCode == 1, r.describe());
        const QJsonObject o = r.json();
        QCOMPARE(o.value(QStringLiteral("count")).toDouble(), 9.0);
        QCOMPARE(o.value(QStringLiteral("ok")).toDouble(), 8.0);
        const QJsonObject engine = o.value(QStringLiteral("engine")).toObject();
        QCOMPARE(engine.value(QStringLiteral("connects")).toDouble(), 2.0);
        QCOMPARE(engine.value(QStringLiteral("requests_sent")).toDouble(), 9.0);
        QVERIFY2(engine.value(QStringLiteral("link_errors")).toDouble() >= 1.0, r.describe());
    }

    // A URL mistake is said before anything listens.
    void badUrls_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("said");
        QTest::newRow("udp") << QStringLiteral("udp://0.0.0.0:5020?mode=listen")
                             << QStringLiteral("mbscope read: --target: udp://0.0.0.0:5020?mode=listen: 'mode' is an option of "
                                               "stream links (tcp, rtu-tcp, ascii-tcp, tls), not of udp links");
        QTest::newRow("host name") << QStringLiteral("tcp://plc.local:5020?mode=listen")
                                   << QStringLiteral("mbscope read: --target: tcp://plc.local:5020?mode=listen: mode=listen needs "
                                                     "an address of this machine to listen on, not the host name 'plc.local'");
        QTest::newRow("busy alone") << QStringLiteral("tcp://127.0.0.1:5020?busy=queue")
                                    << QStringLiteral("mbscope read: --target: tcp://127.0.0.1:5020?busy=queue: 'busy' needs "
                                                      "mode=listen");
    }
    void badUrls()
    {
        QFETCH(QString, url);
        QFETCH(QString, said);
        const CliResult r = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), url, QStringLiteral("--address"),
                                        QStringLiteral("0")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.errText().contains(said), r.describe());
    }
};

QTEST_GUILESS_MAIN(TestCliReverse)
#include "tst_cli_reverse.moc"
