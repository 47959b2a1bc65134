// mbscope monitor (issue 13, item 5): a listen-only tap on a bus another master drives. Against
// real peers on a simulated RS485 bus (tests/peers/bus_harness.py: three ptys; the master's and
// the slave's bytes relayed to each other and copied, in order, to the monitor's, with noise
// applied on the line): mbpoll as the master, `mbscope simulate --profile arduino-rs485` as the
// slave. The monitor's counts equal the master's, its CRC errors equal the bits flipped, its cut
// frames the bytes dropped, and it wrote nothing (the harness counts every byte the monitor's pty
// receives). `mbscope poll` as an ASCII master checks the ASCII framing the same way, and the
// recorded journal is read back by analyze.

#include "clitest.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QTest>

#include <csignal>
#include <memory>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

// The three ptys of a bus_harness.py run.
struct Bus {
    testpeers::PeerProcess harness;
    QString master;
    QString slave;
    QString monitor;

    bool start(const QStringList &noise, QString *error)
    {
        if (!harness.start(testpeers::systemPython(),
                           QStringList{testpeers::peersDir() + QStringLiteral("/bus_harness.py")} + noise)) {
            *error = harness.error();
            return false;
        }
        const QRegularExpression paths(QStringLiteral("master=(\\S+) slave=(\\S+) monitor=(\\S+)"));
        const QRegularExpressionMatch m = paths.match(harness.where());
        if (!m.hasMatch()) {
            *error = QStringLiteral("unexpected harness line: ") + harness.where();
            return false;
        }
        master = m.captured(1);
        slave = m.captured(2);
        monitor = m.captured(3);
        return true;
    }
};

QMap<QString, int> parseStats(const QByteArray &line)
{
    QMap<QString, int> values;
    const QRegularExpression pair(QStringLiteral("(\\w+)=(\\d+)"));
    auto it = pair.globalMatch(QString::fromUtf8(line));
    while (it.hasNext()) {
        const QRegularExpressionMatch m = it.next();
        values.insert(m.captured(1), m.captured(2).toInt());
    }
    return values;
}

// A running `mbscope monitor`: started, its "listening on" line waited for on stderr.
class Monitor
{
public:
    ~Monitor()
    {
        if (m_process && m_process->state() != QProcess::NotRunning) {
            m_process->kill();
            m_process->waitForFinished(5000);
        }
    }
    bool start(const QStringList &arguments, QString *error)
    {
        m_process = std::make_unique<QProcess>();
        m_process->start(mbscopePath(), QStringList{QStringLiteral("monitor")} + arguments);
        if (!m_process->waitForStarted(30000)) {
            *error = m_process->errorString();
            return false;
        }
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 30000) {
            m_process->waitForReadyRead(100);
            m_err += m_process->readAllStandardError();
            m_out += m_process->readAllStandardOutput();
            if (m_err.contains("listening on"))
                return true;
            if (m_process->state() == QProcess::NotRunning)
                break;
        }
        *error = QStringLiteral("no 'listening on' from mbscope monitor: ") + QString::fromUtf8(m_err);
        return false;
    }
    // Waits for it to end by itself (--count); false when it did not within timeoutMs.
    bool wait(int timeoutMs)
    {
        // Already ended while the test ran the event loop (waitForFinished() is false then).
        const bool finished = m_process->state() == QProcess::NotRunning || m_process->waitForFinished(timeoutMs);
        m_out += m_process->readAllStandardOutput();
        m_err += m_process->readAllStandardError();
        return finished;
    }
    void interrupt()
    {
        ::kill(pid_t(m_process->processId()), SIGINT);
    }
    [[nodiscard]] int exitCode() const { return m_process->exitCode(); }
    [[nodiscard]] const QByteArray &out() const { return m_out; }
    [[nodiscard]] const QByteArray &err() const { return m_err; }
    [[nodiscard]] QJsonObject json() const { return QJsonDocument::fromJson(m_out).object(); }
    [[nodiscard]] QByteArray describe() const
    {
        return "exit " + QByteArray::number(m_process->exitCode()) + "\nstdout:\n" + m_out + "\nstderr:\n" + m_err;
    }

private:
    std::unique_ptr<QProcess> m_process;
    QByteArray m_out;
    QByteArray m_err;
};

QString serialUrl(const QString &scheme, const QString &device, const QString &settings = QStringLiteral("baud=9600&parity=N&data=8&stop=1"))
{
    return QStringLiteral("%1://%2?%3").arg(scheme, device, settings);
}

} // namespace

class TestCliMonitor : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void rtuBusWithNoise();
    void pollAndMonitorAgree();
    void asciiBus();
    void deviceServerPort();
    void stopsOnInterrupt();
    void refusesWhatItCannotMonitor_data();
    void refusesWhatItCannotMonitor();
    void missingDevice();
    void nothingHeardHasItsOwnStatus();

private:
    QTemporaryDir m_dir;
};

void TestCliMonitor::initTestCase()
{
    QVERIFY(m_dir.isValid());
    if (!QFileInfo(testpeers::systemPython()).isExecutable())
        QSKIP("no /usr/bin/python3 for the bus harness");
}

void TestCliMonitor::rtuBusWithNoise()
{
    const QString mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
    if (mbpoll.isEmpty())
        QSKIP("mbpoll is not installed (Debian package mbpoll)");
    // Answers 3 and 7 get a bit flipped on the line, answer 10 loses its last byte.
    Bus bus;
    QString error;
    QVERIFY2(bus.start({QStringLiteral("--flip"), QStringLiteral("3,7"), QStringLiteral("--drop"), QStringLiteral("10")}, &error),
             qPrintable(error));
    Background sim;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("arduino-rs485"), QStringLiteral("--listen"),
                        serialUrl(QStringLiteral("rtu"), bus.slave)},
                       &error),
             qPrintable(error));
    const int polls = 12;
    const QString journal = m_dir.filePath(QStringLiteral("bus.mbscope.journal"));
    Monitor monitor;
    QVERIFY2(monitor.start({serialUrl(QStringLiteral("rtu"), bus.monitor), QStringLiteral("--count"), QString::number(polls),
                            QStringLiteral("--duration"), QStringLiteral("60s"), QStringLiteral("--json"), QStringLiteral("--record"), journal},
                           &error),
             qPrintable(error));

    // The master: one mbpoll run per transaction (-1), 8N1, a 0.5 s timeout; its exit status
    // says whether the read succeeded.
    int masterOk = 0;
    int masterFailed = 0;
    QByteArray masterOutput;
    for (int i = 0; i < polls; ++i) {
        QProcess master;
        master.start(mbpoll, {QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-b"), QStringLiteral("9600"), QStringLiteral("-P"),
                              QStringLiteral("none"), QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-r"), QStringLiteral("1"),
                              QStringLiteral("-c"), QStringLiteral("2"), QStringLiteral("-t"), QStringLiteral("4"), QStringLiteral("-1"),
                              QStringLiteral("-o"), QStringLiteral("0.5"), bus.master});
        QVERIFY(master.waitForFinished(20000));
        masterOutput += master.readAll();
        (master.exitCode() == 0 ? masterOk : masterFailed)++;
    }
    QCOMPARE(masterOk + masterFailed, polls);
    QVERIFY2(masterFailed == 3, masterOutput.constData()); // two flips, one drop

    QVERIFY2(monitor.wait(30000), monitor.describe().constData());
    QVERIFY2(monitor.exitCode() == 1, monitor.describe().constData()); // failures were seen
    const QJsonObject o = monitor.json();
    QVERIFY2(!o.isEmpty(), monitor.describe().constData());
    QCOMPARE(o.value(QStringLiteral("stopped")).toString(), QStringLiteral("count"));
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), polls);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), masterOk);
    QCOMPARE(o.value(QStringLiteral("count")).toInt() - o.value(QStringLiteral("ok")).toInt(), masterFailed);
    QCOMPARE(o.value(QStringLiteral("crc_errors")).toInt(), 2);
    QCOMPARE(o.value(QStringLiteral("malformed")).toInt(), 1); // the answer cut short
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), 0);
    const QJsonObject line = o.value(QStringLiteral("bus")).toObject();
    QCOMPARE(line.value(QStringLiteral("crc_errors")).toInt(), 2);
    QCOMPARE(line.value(QStringLiteral("truncated")).toInt(), 1);
    QCOMPARE(line.value(QStringLiteral("requests")).toInt(), polls);
    QCOMPARE(line.value(QStringLiteral("responses")).toInt(), polls); // the damaged two are answers too (tryout 8, item 5)
    QCOMPARE(line.value(QStringLiteral("skipped_bytes")).toInt(), 0);
    QCOMPARE(line.value(QStringLiteral("unmatched_responses")).toInt(), 0);
    QVERIFY(o.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("count")).toInt() == masterOk);

    // command() swallows the line it waits for: wait for another prefix, then read the line.
    QByteArray statsLine;
    QVERIFY(!bus.harness.command("stats", "NEVER", 300));
    QVERIFY(bus.harness.waitForLine("STATS", 5000, &statsLine));
    const QMap<QString, int> stats = parseStats(statsLine);
    QCOMPARE(stats.value(QStringLiteral("monitor_wrote"), -1), 0); // listen-only: not one byte
    QCOMPARE(stats.value(QStringLiteral("flipped")), 2);
    QCOMPARE(stats.value(QStringLiteral("dropped")), 1);
    QCOMPARE(stats.value(QStringLiteral("requests")), polls);
    QCOMPARE(stats.value(QStringLiteral("answers")), polls);

    // The journal holds what the monitor saw: analyze finds the same exchanges.
    QVERIFY2(monitor.err().contains("recorded "), monitor.err().constData());
    const CliResult analyzed = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    const QJsonObject a = analyzed.json();
    QVERIFY2(!a.isEmpty(), analyzed.describe().constData());
    QCOMPARE(a.value(QStringLiteral("count")).toInt(), polls);
    QCOMPARE(a.value(QStringLiteral("ok")).toInt(), masterOk);
    QCOMPARE(a.value(QStringLiteral("crc_errors")).toInt(), 2);
    QCOMPARE(a.value(QStringLiteral("malformed")).toInt(), 1);
}

void TestCliMonitor::pollAndMonitorAgree()
{
    // Tryout 8, item 5: with mbscope poll as the master, the answer the line cut short was a
    // "crc error" to poll and "malformed" to the monitor; the monitor's bus line counted the
    // CRC-damaged answers as skipped bytes, not answers; and its latency was said to be "from the
    // request's write", which a monitor never makes.
    Bus bus;
    QString error;
    QVERIFY2(bus.start({QStringLiteral("--flip"), QStringLiteral("2"), QStringLiteral("--drop"), QStringLiteral("4")}, &error), qPrintable(error));
    Background sim;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("arduino-rs485"), QStringLiteral("--listen"),
                        serialUrl(QStringLiteral("rtu"), bus.slave)},
                       &error),
             qPrintable(error));
    const int polls = 5;
    Monitor monitor;
    QVERIFY2(monitor.start({serialUrl(QStringLiteral("rtu"), bus.monitor), QStringLiteral("--count"), QString::number(polls),
                            QStringLiteral("--duration"), QStringLiteral("60s")},
                           &error),
             qPrintable(error));
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), serialUrl(QStringLiteral("rtu"), bus.master),
                                       QStringLiteral("--function"), QStringLiteral("3"), QStringLiteral("--address"), QStringLiteral("0"),
                                       QStringLiteral("--quantity"), QStringLiteral("2"), QStringLiteral("--interval"), QStringLiteral("50ms"),
                                       QStringLiteral("--timeout"), QStringLiteral("500ms"), QStringLiteral("--count"), QString::number(polls),
                                       QStringLiteral("--json")});
    QVERIFY2(poll.exitCode == 1, poll.describe().constData());
    const QJsonObject p = poll.json();
    QCOMPARE(p.value(QStringLiteral("count")).toInt(), polls);
    QCOMPARE(p.value(QStringLiteral("ok")).toInt(), polls - 2);
    QCOMPARE(p.value(QStringLiteral("crc_errors")).toInt(), 1);
    QCOMPARE(p.value(QStringLiteral("malformed")).toInt(), 1); // the answer cut short, as the monitor says

    QVERIFY2(monitor.wait(30000), monitor.describe().constData());
    const QString text = QString::fromUtf8(monitor.out());
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("\\n +4  unit 1 +0x03 Read Holding Registers +malformed .*cut short"))), qPrintable(text));
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("\\n +2  unit 1 +0x03 Read Holding Registers +crc_error "))), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("bus           bytes %1  frames %2  requests %3  answers %3\n").arg(polls * 17 - 1).arg(polls * 2).arg(polls)),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("damaged       crc errors 1  truncated 1  malformed 0  skipped bytes 0  unmatched answers 0\n")),
             qPrintable(text));
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("\\ncrc errors +1\\n"))) && text.contains(QRegularExpression(QStringLiteral("\\nmalformed +1\\n"))),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("latency from  the request's last byte as read off the line to the answer's last byte\n")),
             qPrintable(text));
    QVERIFY2(!text.contains(QStringLiteral("write")), qPrintable(text));
}

void TestCliMonitor::asciiBus()
{
    // mbscope poll as an ASCII master (7E1 by the spec's default; 9600 baud) against simulate.
    Bus bus;
    QString error;
    QVERIFY2(bus.start({}, &error), qPrintable(error));
    const QString settings = QStringLiteral("baud=9600&parity=E&data=7&stop=1");
    Background sim;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("arduino-rs485"), QStringLiteral("--listen"),
                        serialUrl(QStringLiteral("ascii"), bus.slave, settings)},
                       &error),
             qPrintable(error));
    const int polls = 5;
    Monitor monitor;
    QVERIFY2(monitor.start({serialUrl(QStringLiteral("ascii"), bus.monitor, settings), QStringLiteral("--count"), QString::number(polls)}, &error),
             qPrintable(error));
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), serialUrl(QStringLiteral("ascii"), bus.master, settings),
                                       QStringLiteral("--unit"), QStringLiteral("1"), QStringLiteral("--function"), QStringLiteral("3"),
                                       QStringLiteral("--address"), QStringLiteral("0"), QStringLiteral("--quantity"), QStringLiteral("4"),
                                       QStringLiteral("--interval"), QStringLiteral("20ms"), QStringLiteral("--count"), QString::number(polls),
                                       QStringLiteral("--json")});
    QVERIFY2(poll.exitCode == 0, poll.describe().constData());
    QCOMPARE(poll.json().value(QStringLiteral("ok")).toInt(), polls);
    QVERIFY2(monitor.wait(30000), monitor.describe().constData());
    QVERIFY2(monitor.exitCode() == 0, monitor.describe().constData());
    // One line per exchange, then the statistics as poll prints them.
    const QString text = QString::fromUtf8(monitor.out());
    QCOMPARE(text.count(QRegularExpression(QStringLiteral("unit 1 +0x03 Read Holding Registers +ok "))), polls);
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("transactions +%1 +ok %1 ").arg(polls))), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("crc errors 0  truncated 0")), qPrintable(text));
}

void TestCliMonitor::deviceServerPort()
{
    // A serial device server's port (rtu-tcp://): it sends what the line carries, a read, its
    // answer and an exception to another read; the monitor connects, reads and writes nothing.
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    Monitor monitor;
    QString error;
    QVERIFY2(monitor.start({QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(server.serverPort()), QStringLiteral("--count"), QStringLiteral("2"),
                            QStringLiteral("--json")},
                           &error),
             qPrintable(error));
    QVERIFY(server.waitForNewConnection(10000));
    QTcpSocket *line = server.nextPendingConnection();
    const auto frame = [](const char *hex) {
        QByteArray bytes = QByteArray::fromHex(hex);
        quint16 crc = 0xFFFF;
        for (const char c : bytes) {
            crc ^= quint8(c);
            for (int bit = 0; bit < 8; ++bit)
                crc = (crc & 1) ? quint16((crc >> 1) ^ 0xA001) : quint16(crc >> 1);
        }
        return bytes + char(crc & 0xff) + char(crc >> 8);
    };
    for (const QByteArray &bytes : {frame("010300000002"), frame("01030400450046"), frame("110300100001"), frame("118302")}) {
        line->write(bytes);
        QVERIFY(line->waitForBytesWritten(5000));
        QTest::qWait(30);
    }
    QVERIFY2(monitor.wait(20000), monitor.describe().constData());
    QVERIFY2(monitor.exitCode() == 1, monitor.describe().constData()); // an exception is a failure
    const QJsonObject o = monitor.json();
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 2);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("exceptions")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("bus")).toObject().value(QStringLiteral("silence_us")).toDouble(), 20000.0);
    line->waitForReadyRead(200);
    QCOMPARE(line->readAll(), QByteArray()); // listen-only: not one byte to the device server
}

void TestCliMonitor::stopsOnInterrupt()
{
    // A quiet bus: Ctrl-C stops the monitor, which still prints its (empty) statistics.
    Bus bus;
    QString error;
    QVERIFY2(bus.start({}, &error), qPrintable(error));
    Monitor monitor;
    QVERIFY2(monitor.start({serialUrl(QStringLiteral("rtu"), bus.monitor), QStringLiteral("--json")}, &error), qPrintable(error));
    monitor.interrupt();
    QVERIFY2(monitor.wait(10000), monitor.describe().constData());
    QVERIFY2(monitor.exitCode() == 3, monitor.describe().constData()); // nothing heard (issue 26 item 10)
    QCOMPARE(monitor.json().value(QStringLiteral("stopped")).toString(), QStringLiteral("interrupted"));
    QCOMPARE(monitor.json().value(QStringLiteral("count")).toInt(), 0);

    // --duration stops it by itself.
    const CliResult timed = runMbscope({QStringLiteral("monitor"), serialUrl(QStringLiteral("rtu"), bus.monitor), QStringLiteral("--duration"),
                                        QStringLiteral("300ms"), QStringLiteral("--json")},
                                       30000);
    QVERIFY2(timed.exitCode == 3, timed.describe().constData());
    QCOMPARE(timed.json().value(QStringLiteral("stopped")).toString(), QStringLiteral("duration"));
}

// Issue 26 item 10: a monitor that heard nothing at all ended with exit status 0, as if every
// exchange had been fine. It says so and ends with 3; a device server's port that sends one good
// exchange ends with 0, and one damaged frame with 1.
void TestCliMonitor::nothingHeardHasItsOwnStatus()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    const QString url = QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(server.serverPort());
    const CliResult quiet = runMbscope({QStringLiteral("monitor"), url, QStringLiteral("--duration"), QStringLiteral("300ms")}, 30000);
    QVERIFY2(quiet.finished && quiet.exitCode == 3, quiet.describe().constData());
    QVERIFY2(quiet.errText().contains(QStringLiteral("mbscope monitor: nothing was heard: not one byte came from %1 in ").arg(url)),
             quiet.describe().constData());
    // Its connection, which the kernel accepted, is taken off the queue: the next is the next run's.
    QVERIFY(server.waitForNewConnection(10000));
    delete server.nextPendingConnection();

    const auto run = [&](const QList<QByteArray> &frames) {
        Monitor monitor;
        QString error;
        if (!monitor.start({url, QStringLiteral("--duration"), QStringLiteral("1s"), QStringLiteral("--quiet")}, &error))
            return -100;
        if (!server.waitForNewConnection(10000))
            return -101;
        QTcpSocket *line = server.nextPendingConnection();
        for (const QByteArray &bytes : frames) {
            line->write(bytes);
            line->waitForBytesWritten(5000);
            QTest::qWait(50); // the silence that ends a frame on a device server's port is 20 ms
        }
        if (!monitor.wait(20000))
            return -102;
        delete line;
        return monitor.exitCode();
    };
    // 01 03 00 00 00 01 84 0A, answered 01 03 02 00 2A 39 9B: one good exchange.
    QCOMPARE(run({QByteArray::fromHex("010300000001840A"), QByteArray::fromHex("010302002A399B")}), 0);
    QCOMPARE(run({QByteArray::fromHex("010300000001840B")}), 1); // a CRC error
}

void TestCliMonitor::refusesWhatItCannotMonitor_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("tcp") << QStringList{QStringLiteral("tcp://127.0.0.1:502")} << QStringLiteral("not a bus another master drives");
    QTest::newRow("udp") << QStringList{QStringLiteral("udp://127.0.0.1:502")} << QStringLiteral("not a bus another master drives");
    QTest::newRow("no url") << QStringList{} << QStringLiteral("no URL given");
    QTest::newRow("bad count") << QStringList{QStringLiteral("rtu:///dev/null"), QStringLiteral("--count"), QStringLiteral("0")}
                               << QStringLiteral("--count '0' is not a whole number above zero");
    QTest::newRow("bad duration") << QStringList{QStringLiteral("rtu:///dev/null"), QStringLiteral("--duration"), QStringLiteral("soon")}
                                  << QStringLiteral("--duration: ");
}

void TestCliMonitor::refusesWhatItCannotMonitor()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const CliResult r = runMbscope(QStringList{QStringLiteral("monitor")} + arguments, 30000);
    QVERIFY2(r.exitCode == 2, r.describe().constData());
    QVERIFY2(r.errText().contains(message), r.describe().constData());
    QVERIFY(r.out.isEmpty());
}

void TestCliMonitor::missingDevice()
{
    const CliResult r = runMbscope({QStringLiteral("monitor"), QStringLiteral("rtu:///dev/mbscope-no-such-port?baud=9600")}, 30000);
    QVERIFY2(r.exitCode == 2, r.describe().constData());
    QVERIFY2(r.errText().contains(QStringLiteral("/dev/mbscope-no-such-port")), r.describe().constData());
}

QTEST_GUILESS_MAIN(TestCliMonitor)
#include "tst_cli_monitor.moc"
