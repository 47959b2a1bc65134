// The simulator playing particular devices, seen by real clients through `mbscope simulate`:
// the shipped profile libmodbus-unit-test (libmodbus's unit-test server: special answers to
// exact requests, every unit id answered over TCP) against mbpoll, libmodbus, pymodbus, a raw
// socket and mbscope's own engine (mbscope read); device limits from a profile file.
#include "peerprocess.h"
#include "simcli.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QStandardPaths>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>

using namespace mbscope::simtest;
using namespace mbscope::testpeers;

namespace {

QStringList args(std::initializer_list<const char *> list)
{
    QStringList out;
    for (const char *a : list)
        out << QString::fromLatin1(a);
    return out;
}

// A faults file without rules: scada-rs485's noisy bus made quiet, for tests of the protocol.
QString quietFaults(const QTemporaryDir &dir)
{
    const QString path = dir.filePath(QStringLiteral("quiet.json"));
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(R"({"rules": []})");
    return path;
}

QString mbpollPath()
{
    return QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
}

// mbpoll reading holding registers (1-based reference) once.
Run mbpoll(quint16 port, int unit, int reference, int count)
{
    return runProcess(mbpollPath(), {QStringLiteral("-m"), QStringLiteral("tcp"), QStringLiteral("-p"), QString::number(port),
                                     QStringLiteral("-a"), QString::number(unit), QStringLiteral("-r"), QString::number(reference),
                                     QStringLiteral("-c"), QString::number(count), QStringLiteral("-t"), QStringLiteral("4"),
                                     QStringLiteral("-o"), QStringLiteral("1"), QStringLiteral("-1"), QStringLiteral("127.0.0.1")});
}

} // namespace

class tst_SimulateDevices : public QObject
{
    Q_OBJECT
private:
    SimCli m_sim;
    quint16 m_port = 0;

private Q_SLOTS:
    void initTestCase()
    {
        QString why;
        QVERIFY2(m_sim.start(args({"--profile", "libmodbus-unit-test", "--listen", "tcp://127.0.0.1:0", "--quiet"}), 1, &why),
                 qPrintable(why));
        m_port = m_sim.port(0);
    }
    void cleanupTestCase() { QCOMPARE(m_sim.stop(), 0); }

    void mbpollExactStart();
    void libmodbusExactQuantity();
    void pymodbusExactQuantity();
    void byteByByte();
    void ownEngine();
    void unknownUnitFirst();
    void limitsFromProfile();
    void limitRefusalsSayWhich();
    void delimitedOverTcp();
    void delimitedOverSerial();
    void delimitedNeedsATable();
};

// A read starting at 0x170 gets exception 06; a read of 0x160-0x17F, which meets 0x170, does not.
void tst_SimulateDevices::mbpollExactStart()
{
    if (mbpollPath().isEmpty())
        QSKIP("mbpoll is not installed (Debian: mbpoll)");
    const Run busy = mbpoll(m_port, 17, 0x170 + 1, 1);
    QVERIFY2(busy.exitCode != 0, busy.out.constData());
    QVERIFY2((busy.out + busy.err).contains("busy"), (busy.out + busy.err).constData());
    const Run all = mbpoll(m_port, 17, 0x160 + 1, 32);
    QVERIFY2(all.exitCode == 0, (all.out + all.err).constData());
    const QMap<int, int> values = mbpollValues(all.out);
    QCOMPARE(values.value(0x160 + 1), 0x022B);
    QCOMPARE(values.value(0x162 + 1), 0x0064);
    QCOMPARE(values.size(), 32);
}

// libmodbus checks the quantity of an answer: a read of exactly two registers gets one back and
// fails; three are answered.
void tst_SimulateDevices::libmodbusExactQuantity()
{
    QString why;
    if (!libmodbusPeersAvailable(&why))
        QSKIP(qPrintable(why));
    const auto client = [this](int quantity) {
        return runProcess(libmodbusClientPath(), {QStringLiteral("tcp"), QStringLiteral("127.0.0.1"), QString::number(m_port),
                                                  QStringLiteral("--count"), QStringLiteral("1"), QStringLiteral("--unit"),
                                                  QStringLiteral("17"), QStringLiteral("--address"), QString::number(0x160),
                                                  QStringLiteral("--quantity"), QString::number(quantity)});
    };
    const Run two = client(2);
    QVERIFY2(two.exitCode == 1, (two.out + two.err).constData());
    QVERIFY2(two.out.contains("1 errors"), (two.out + two.err).constData());
    const Run three = client(3);
    QVERIFY2(three.exitCode == 0, (three.out + three.err).constData());
}

void tst_SimulateDevices::pymodbusExactQuantity()
{
    QString why;
    if (!pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    const QString script = QStringLiteral(
        "import sys\n"
        "from pymodbus.client import ModbusTcpClient\n"
        "c = ModbusTcpClient('127.0.0.1', port=%1, timeout=3)\n"
        "c.connect()\n"
        "r = c.read_holding_registers(0x160, 2, slave=17)\n"
        "print('two', [] if r.isError() else list(r.registers))\n"
        "r = c.read_holding_registers(0x160, 3, slave=17)\n"
        "print('three', [] if r.isError() else list(r.registers))\n"
        "r = c.read_holding_registers(0x170, 1, slave=17)\n"
        "print('special', getattr(r, 'exception_code', None))\n")
                               .arg(m_port);
    const Run r = runProcess(systemPython(), {QStringLiteral("-c"), script});
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    QVERIFY2(r.out.contains("two [555]\n"), r.out.constData());
    QVERIFY2(r.out.contains("three [555, 1, 100]\n"), r.out.constData());
    QVERIFY2(r.out.contains("special 6\n"), r.out.constData());
}

// 0x173: the answer leaves one byte at a time, 5 ms apart; a raw socket sees it arrive in pieces
// and whole in the end.
void tst_SimulateDevices::byteByByte()
{
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), m_port);
    QVERIFY(socket.waitForConnected(5000));
    socket.write(QByteArray::fromHex("000700000006110301730001"));
    QByteArray answer;
    int pieces = 0;
    QElapsedTimer clock;
    clock.start();
    while (answer.size() < 11 && clock.elapsed() < 10000) {
        if (socket.waitForReadyRead(1000)) {
            answer += socket.readAll();
            ++pieces;
        }
    }
    QCOMPARE(answer.toHex(' '), QByteArray("00 07 00 00 00 05 11 03 02 00 00"));
    QVERIFY2(pieces >= 3, qPrintable(QStringLiteral("%1 pieces").arg(pieces)));
}

// mbscope's own engine reassembles the trickled answer and reports exception 06 at 0x170.
void tst_SimulateDevices::ownEngine()
{
    const QString target = QStringLiteral("tcp://127.0.0.1:%1").arg(m_port);
    const Run trickled = runProcess(mbscopePath(), {QStringLiteral("read"), QStringLiteral("--target"), target,
                                                    QStringLiteral("--unit"), QStringLiteral("17"), QStringLiteral("--address"),
                                                    QStringLiteral("0x173"), QStringLiteral("--quantity"), QStringLiteral("1")});
    QVERIFY2(trickled.exitCode == 0, (trickled.out + trickled.err).constData());
    const Run busy = runProcess(mbscopePath(), {QStringLiteral("read"), QStringLiteral("--target"), target,
                                                QStringLiteral("--unit"), QStringLiteral("17"), QStringLiteral("--address"),
                                                QStringLiteral("0x170"), QStringLiteral("--quantity"), QStringLiteral("1")});
    QCOMPARE(busy.exitCode, 1);
    QVERIFY2(busy.out.contains("06"), busy.out.constData());
}

// "unknownUnit": "first": any unit id is answered as unit 17, as libmodbus's TCP server does.
void tst_SimulateDevices::unknownUnitFirst()
{
    if (mbpollPath().isEmpty())
        QSKIP("mbpoll is not installed (Debian: mbpoll)");
    const Run r = mbpoll(m_port, 99, 0x160 + 1, 3);
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    QCOMPARE(mbpollValues(r.out).value(0x161 + 1), 1);
}

// A profile file with device limits, served and asked by mbpoll and mbscope: more than 4
// registers get exception 03, a second request sooner than 300 ms gets exception 06.
void tst_SimulateDevices::limitsFromProfile()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("limited.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"name": "limited", "unknownUnit": "silent",
                   "limits": {"maxQuantity": {"0x03": 4}, "minGapMs": 300, "tooSoon": "busy"},
                   "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 10}]}}]})");
    file.close();
    SimCli sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("--profile"), path, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")}, 1, &why),
             qPrintable(why));
    const QString target = QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port(0));
    const auto read = [&](int quantity, int unit = 1) {
        return runProcess(mbscopePath(), {QStringLiteral("read"), QStringLiteral("--target"), target, QStringLiteral("--unit"),
                                          QString::number(unit), QStringLiteral("--quantity"), QString::number(quantity),
                                          QStringLiteral("--timeout"), QStringLiteral("400ms")});
    };
    const Run tooMany = read(5);
    QCOMPARE(tooMany.exitCode, 1);
    QVERIFY2(tooMany.out.contains("03"), tooMany.out.constData());
    QTest::qWait(350);
    const Run four = read(4);
    QVERIFY2(four.exitCode == 0, (four.out + four.err).constData());
    // The unit this profile does not list: silence (a timeout), not 0B.
    QTest::qWait(350);
    const Run unknown = read(1, 9);
    QCOMPARE(unknown.exitCode, 1);
    QVERIFY2(unknown.out.contains("timeout") || unknown.out.contains("Timeout") || unknown.out.contains("no answer"),
             unknown.out.constData());
    // Two requests in one segment arrive together: the second is under the gap, exception 06.
    QTest::qWait(350);
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), sim.port(0));
    QVERIFY(socket.waitForConnected(5000));
    socket.write(QByteArray::fromHex("000100000006010300000001" "000200000006010300000001"));
    QByteArray answers;
    QElapsedTimer clock;
    clock.start();
    while (answers.size() < 11 + 9 && clock.elapsed() < 10000) {
        if (socket.waitForReadyRead(1000))
            answers += socket.readAll();
    }
    QCOMPARE(answers.toHex(' '), QByteArray("00 01 00 00 00 05 01 03 02 00 00 00 02 00 00 00 03 01 83 06"));
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("exception 06"), sim.output().constData());
}

// Each request a device limit refuses says, on simulate's line, which limit and by how much: the
// warm-up, the gap (two requests in one segment), the quantity and the client count.
void tst_SimulateDevices::limitRefusalsSayWhich()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("limited.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"name": "limited", "limits": {"maxQuantity": {"0x03": 4}, "minGapMs": 50, "warmUpMs": 200, "maxClients": 1},
                   "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 10}]}}]})");
    file.close();
    SimCli sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("--profile"), path, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")}, 1, &why),
             qPrintable(why));
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), sim.port(0));
    QVERIFY(socket.waitForConnected(5000));
    socket.write(QByteArray::fromHex("000100000006010300000001")); // within the warm-up
    QVERIFY(socket.waitForBytesWritten(5000));
    QVERIFY2(sim.waitForOutput("refused by warmUpMs", 10000), sim.output().constData());
    QTest::qWait(250);
    socket.write(QByteArray::fromHex("000200000006010300000001" "000300000006010300000001")); // the second too soon
    QVERIFY(socket.waitForBytesWritten(5000));
    QVERIFY2(sim.waitForOutput("refused by minGapMs", 10000), sim.output().constData());
    QTest::qWait(100);
    socket.write(QByteArray::fromHex("000400000006010300000005")); // 5 registers, 4 at most
    QVERIFY(socket.waitForBytesWritten(5000));
    QVERIFY2(sim.waitForOutput("refused by maxQuantity", 10000), sim.output().constData());
    QTcpSocket second;
    second.connectToHost(QStringLiteral("127.0.0.1"), sim.port(0));
    QVERIFY(second.waitForConnected(5000));
    QVERIFY2(sim.waitForOutput("refused by maxClients", 10000), sim.output().constData());
    QCOMPARE(sim.stop(), 0);
    const QString out = QString::fromUtf8(sim.output());
    const auto has = [&out](const QString &pattern) {
        return QRegularExpression(pattern, QRegularExpression::MultilineOption).match(out).hasMatch();
    };
    QVERIFY2(has(QStringLiteral("unit 1  03 Read Holding Registers  no answer \\(refused by warmUpMs: [0-9.]+ ms after "
                                "connecting, warmUpMs is 200\\)$")),
             qPrintable(out));
    QVERIFY2(has(QStringLiteral("03 Read Holding Registers  exception 06 Server Device Busy \\(refused by minGapMs: [0-9.]+ ms "
                                "after the last request taken, minGapMs is 50\\)$")),
             qPrintable(out));
    QVERIFY2(has(QStringLiteral("03 Read Holding Registers  exception 03 Illegal Data Value \\(refused by maxQuantity: "
                                "quantity 5 of function 03, maxQuantity is 4\\)$")),
             qPrintable(out));
    QVERIFY2(has(QStringLiteral("  connection refused by maxClients: 1 client\\(s\\) connected already, maxClients is 1$")),
             qPrintable(out));
}

// The SCADA lab's '$' ... '#' protocol (shipped profile scada-rs485) over TCP: mbscope's own
// engine sends the published request and gets the published answer; a write switches a lamp and
// a read shows it; pymodbus cannot speak it, so the raw socket is the other client.
void tst_SimulateDevices::delimitedOverTcp()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    SimCli sim;
    QString why;
    QVERIFY2(sim.start(args({"--profile", "scada-rs485", "--listen", "tcp://127.0.0.1:0?framing=delimited&start=24&end=23"})
                           << QStringLiteral("--faults") << quietFaults(dir),
                       1, &why),
             qPrintable(why));
    const QString target = QStringLiteral("tcp://127.0.0.1:%1?framing=delimited&start=24&end=23").arg(sim.port(0));
    const Run read = runProcess(mbscopePath(), {QStringLiteral("send"), QStringLiteral("--target"), target, QStringLiteral("--hex"),
                                                QStringLiteral("24 30 31 52 23")});
    QVERIFY2(read.exitCode == 0, (read.out + read.err).constData());
    QVERIFY2(read.out.contains("text  $01 293 295 363 353 342 335 329 347 0 1 0 0 0 1 0 0 #"), read.out.constData());

    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), sim.port(0));
    QVERIFY(socket.waitForConnected(5000));
    const auto ask = [&socket](const QByteArray &request) {
        socket.write(request);
        QByteArray answer;
        QElapsedTimer clock;
        clock.start();
        while (!answer.endsWith('#') && clock.elapsed() < 5000) {
            if (socket.waitForReadyRead(500))
                answer += socket.readAll();
        }
        return answer;
    };
    // Lamps 0 1 0 0 0 1 0 0: bit 0 on, bit 1 off.
    QCOMPARE(ask("$01WB01#"), QByteArray("$01WB01#"));
    QCOMPARE(ask("$01WB10#"), QByteArray("$01WB10#"));
    QCOMPARE(ask("$01R#"), QByteArray("$01 293 295 363 353 342 335 329 347 1 0 0 0 0 1 0 0 #"));
    QCOMPARE(ask("$03R#"), QByteArray("$03 0 0 0 0 0 0 0 0 #"));
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("$01R# -> $01 293 295"), sim.output().constData());
}

// The same protocol on a serial line (a socat pty pair), as the lab's RS485 bus.
void tst_SimulateDevices::delimitedOverSerial()
{
    QString why;
    if (!socatAvailable(&why))
        QSKIP(qPrintable(why));
    PtyPair pty;
    QVERIFY2(pty.start(), qPrintable(pty.error()));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("scada-rs485"), QStringLiteral("--listen"),
                        QStringLiteral("rtu://%1?baud=9600&parity=N&framing=delimited&start=24&end=23").arg(pty.ourEnd()),
                        QStringLiteral("--faults"), quietFaults(dir)},
                       1, &why),
             qPrintable(why));
    const Run read = runProcess(mbscopePath(), {QStringLiteral("send"), QStringLiteral("--target"),
                                                QStringLiteral("rtu://%1?baud=9600&parity=N&framing=delimited&start=24&end=23")
                                                    .arg(pty.peerEnd()),
                                                QStringLiteral("--hex"), QStringLiteral("24 30 32 52 23")});
    QVERIFY2(read.exitCode == 0, (read.out + read.err).constData());
    QVERIFY2(read.out.contains("text  $02 293 295 363 353 342 335 329 347 0 1 0 0 0 1 0 0 #"), read.out.constData());
    QCOMPARE(sim.stop(), 0);
}

// A delimited endpoint without a table of requests is refused with what to do.
void tst_SimulateDevices::delimitedNeedsATable()
{
    const Run r = runSimulate(args({"--profile", "conformance", "--listen", "tcp://127.0.0.1:0?framing=delimited&end=23",
                                    "--duration", "1s"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("framing=delimited needs a profile with a 'delimited' table of requests and answers"), r.err.constData());
}

QTEST_GUILESS_MAIN(tst_SimulateDevices)
#include "tst_simulate_devices.moc"
