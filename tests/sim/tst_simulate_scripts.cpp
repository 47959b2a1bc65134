// Device scripts (docs/profiles.md, "Scripts") through `mbscope simulate`, seen by real clients:
// the shipped scripted-meter against mbpoll and pymodbus (a register counted up by onTick, an
// exception computed from the request); a user profile whose script answers every kind of answer
// to pymodbus; an endless loop interrupted with the simulator staying up; runtime errors in the
// log with file and line; a syntax error refused at load with file, line and column; a delimited
// protocol served by onFrame to a raw socket.
#include "peerprocess.h"
#include "simcli.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>

using namespace mbscope::simtest;
using namespace mbscope::testpeers;

namespace {

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &text)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(text);
    return path;
}

// A unit 1 with holding registers 0-9 (0, 10, 20...) and a script.
QByteArray profileWith(const QByteArray &script)
{
    return R"({"name": "scripted", "units": [{"id": 1, "script": )" + script
           + R"(, "tables": {"holding": [{"address": 0, "values": [0, 10, 20, 30, 40, 50, 60, 70, 80, 90]}]}}]})";
}

Run mbpoll(quint16 port, int reference, int count)
{
    return runProcess(QStandardPaths::findExecutable(QStringLiteral("mbpoll")),
                      {QStringLiteral("-m"), QStringLiteral("tcp"), QStringLiteral("-p"), QString::number(port),
                       QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-r"), QString::number(reference),
                       QStringLiteral("-c"), QString::number(count), QStringLiteral("-t"), QStringLiteral("4"),
                       QStringLiteral("-o"), QStringLiteral("1"), QStringLiteral("-1"), QStringLiteral("127.0.0.1")});
}

Run python(const QString &script)
{
    return runProcess(systemPython(), {QStringLiteral("-c"), script});
}

} // namespace

class tst_SimulateScripts : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void shippedMeterWithMbpoll();
    void shippedMeterCountsOnTicks();
    void answersOfEveryKindToPymodbus();
    void endlessLoopInterrupted();
    void runtimeErrorLoggedWithLine();
    void syntaxErrorRefusedAtLoad();
    void delimitedServedByScript();
    void topLevelLogAfterHeader();
};

// Reads of the calibration block at 100: exception 03 over four registers, else 02, each logged
// by the script with the client that asked.
void tst_SimulateScripts::shippedMeterWithMbpoll()
{
    if (QStandardPaths::findExecutable(QStringLiteral("mbpoll")).isEmpty())
        QSKIP("mbpoll is not installed (Debian: mbpoll)");
    SimCli sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("scripted-meter"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0")},
                       1, &why),
             qPrintable(why));
    const Run six = mbpoll(sim.port(0), 101, 6);
    QVERIFY2(six.exitCode != 0 && (six.out + six.err).contains("Illegal data value"), (six.out + six.err).constData());
    const Run two = mbpoll(sim.port(0), 101, 2);
    QVERIFY2(two.exitCode != 0 && (two.out + two.err).contains("Illegal data address"), (two.out + two.err).constData());
    const Run setpoint = mbpoll(sim.port(0), 4, 1);
    QVERIFY2(setpoint.exitCode == 0, (setpoint.out + setpoint.err).constData());
    QCOMPARE(mbpollValues(setpoint.out).value(4), 250);
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("script unit 1: scripted-meter.js  log: calibration block read at 100 x6 by 127.0.0.1:"),
             sim.output().constData());
    QVERIFY2(sim.output().contains("-> exception 3\n"), sim.output().constData());
    QVERIFY2(sim.output().contains("exception 03 Illegal Data Value"), sim.output().constData());
    QVERIFY2(sim.output().contains("exception 02 Illegal Data Address"), sim.output().constData());
}

// Holding 0 counts up on the script's ticks (every 500 ms); holding 1 counts the requests.
void tst_SimulateScripts::shippedMeterCountsOnTicks()
{
    QString why;
    if (!pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("scripted-meter"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       1, &why),
             qPrintable(why));
    const Run r = python(QStringLiteral(
        "import time\n"
        "from pymodbus.client import ModbusTcpClient\n"
        "c = ModbusTcpClient('127.0.0.1', port=%1, timeout=3)\n"
        "c.connect()\n"
        "first = c.read_holding_registers(0, 2, slave=1).registers\n"
        "deadline = time.time() + 20\n"
        "now = first\n"
        "while now[0] < first[0] + 2 and time.time() < deadline:\n"
        "    time.sleep(0.1)\n"
        "    now = c.read_holding_registers(0, 2, slave=1).registers\n"
        "print('pulses', now[0] >= first[0] + 2, 'requests', now[1] > first[1] and first[1] == 1)\n")
                             .arg(sim.port(0)));
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    QVERIFY2(r.out.contains("pulses True requests True"), r.out.constData());
    QCOMPARE(sim.stop(), 0);
}

// Values computed from the request, an exception, silence, a PDU, exact bytes, a delay, a write
// the script keeps, and the profile's answer.
void tst_SimulateScripts::answersOfEveryKindToPymodbus()
{
    QString why;
    if (!pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir, QStringLiteral("kinds.js"),
              "function onRequest(r) {\n"
              "  if (r.function === 6 && r.address === 9) { unit.write('holding', 9, r.values[0] * 2); return {pdu: r.pdu}; }\n"
              "  if (r.function === 6) return {exception: 1};\n"
              "  if (r.function !== 3) return undefined;\n"
              "  switch (r.address) {\n"
              "  case 100: return [r.quantity, r.address, r.unit];\n"
              "  case 101: return {exception: r.quantity};\n"
              "  case 102: return null;\n"
              "  case 103: return {pdu: [3, 2, 0x12, 0x34]};\n"
              "  case 104: return {adu: [0, r.transactionId, 0, 0, 0, 5, 1, 3, 2, 0xAB, 0xCD]};\n"
              "  case 105: return {delay: 300.5, values: [7]};\n"
              "  }\n"
              "}\n");
    const QString profile = writeFile(dir, QStringLiteral("kinds.json"), profileWith(R"("kinds.js")"));
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), profile, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")}, 1,
                       &why),
             qPrintable(why));
    const Run r = python(QStringLiteral(
        "import time\n"
        "from pymodbus.client import ModbusTcpClient\n"
        "c = ModbusTcpClient('127.0.0.1', port=%1, timeout=1, retries=0)\n"
        "c.connect()\n"
        "def rd(a, n):\n"
        "    try:\n"
        "        r = c.read_holding_registers(a, n, slave=1)\n"
        "    except Exception as e:\n"
        "        return 'none'\n"
        "    return ('x%d' % r.exception_code) if r.isError() and hasattr(r, 'exception_code') else ('none' if r.isError() else r.registers)\n"
        "print('values', rd(100, 3))\n"
        "print('exception', rd(101, 4))\n"
        "print('silence', rd(102, 1))\n"
        "c.close(); c.connect()\n"
        "print('pdu', rd(103, 1))\n"
        "print('adu', rd(104, 1))\n"
        "t = time.time(); v = rd(105, 1); late = time.time() - t\n"
        "print('delay', v, late >= 0.3)\n"
        "print('profile', rd(2, 2))\n"
        "w = c.write_register(9, 21, slave=1)\n"
        "print('write', w.isError(), rd(9, 1))\n"
        "w = c.write_register(1, 5, slave=1)\n"
        "print('refused', getattr(w, 'exception_code', None), rd(1, 1))\n")
                             .arg(sim.port(0)));
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    const QByteArray out = r.out;
    QVERIFY2(out.contains("values [3, 100, 1]\n"), out.constData());
    QVERIFY2(out.contains("exception x4\n"), out.constData());
    QVERIFY2(out.contains("silence none\n"), out.constData());
    QVERIFY2(out.contains("pdu [4660]\n"), out.constData());
    QVERIFY2(out.contains("adu [43981]\n"), out.constData());
    QVERIFY2(out.contains("delay [7] True\n"), out.constData());
    QVERIFY2(out.contains("profile [20, 30]\n"), out.constData());
    QVERIFY2(out.contains("write False [42]\n"), out.constData());
    QVERIFY2(out.contains("refused 1 [10]\n"), out.constData());
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("no answer (script: no answer)"), sim.output().constData());
}

// A call that never ends is interrupted after timeoutMs: that request gets exception 04, the log
// says so, and the next request is answered.
void tst_SimulateScripts::endlessLoopInterrupted()
{
    QString why;
    if (!pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir, QStringLiteral("loop.js"),
              "function onRequest(r) {\n"
              "  while (r.address === 5) {}\n"
              "}\n");
    const QString profile = writeFile(dir, QStringLiteral("loop.json"), profileWith(R"({"file": "loop.js", "timeoutMs": 50})"));
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), profile, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")}, 1,
                       &why),
             qPrintable(why));
    const Run r = python(QStringLiteral(
        "from pymodbus.client import ModbusTcpClient\n"
        "c = ModbusTcpClient('127.0.0.1', port=%1, timeout=3, retries=0)\n"
        "c.connect()\n"
        "r = c.read_holding_registers(5, 1, slave=1)\n"
        "print('stuck', getattr(r, 'exception_code', None))\n"
        "print('next', c.read_holding_registers(4, 2, slave=1).registers)\n")
                             .arg(sim.port(0)));
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    QVERIFY2(r.out.contains("stuck 4\n"), r.out.constData());
    QVERIFY2(r.out.contains("next [40, 50]\n"), r.out.constData());
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("script unit 1: loop.js  error: loop.js: onRequest ran longer than 50 ms: interrupted"),
             sim.output().constData());
}

// An error thrown per request is logged with file and line; "onError": "silence" leaves it
// unanswered, and the simulator goes on.
void tst_SimulateScripts::runtimeErrorLoggedWithLine()
{
    QString why;
    if (!pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir, QStringLiteral("err.js"),
              "function onRequest(r) {\n"
              "  if (r.address === 0)\n"
              "    return notDefined + 1;\n"
              "}\n");
    const QString profile = writeFile(dir, QStringLiteral("err.json"), profileWith(R"({"file": "err.js", "onError": "silence"})"));
    SimCli sim;
    QVERIFY2(sim.start({QStringLiteral("--profile"), profile, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")}, 1,
                       &why),
             qPrintable(why));
    const Run r = python(QStringLiteral(
        "from pymodbus.client import ModbusTcpClient\n"
        "c = ModbusTcpClient('127.0.0.1', port=%1, timeout=1, retries=0)\n"
        "c.connect()\n"
        "try:\n"
        "    r = c.read_holding_registers(0, 1, slave=1)\n"
        "    print('first', 'none' if r.isError() else r.registers)\n"
        "except Exception:\n"
        "    print('first none')\n"
        "c.close(); c.connect()\n"
        "print('next', c.read_holding_registers(1, 1, slave=1).registers)\n")
                             .arg(sim.port(0)));
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    QVERIFY2(r.out.contains("first none\n"), r.out.constData());
    QVERIFY2(r.out.contains("next [10]\n"), r.out.constData());
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("script unit 1: err.js  error: err.js:3: ReferenceError: notDefined is not defined"),
             sim.output().constData());
}

void tst_SimulateScripts::syntaxErrorRefusedAtLoad()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir, QStringLiteral("gamma.js"), "var a = 1;\n\nfunction onRequest(r {\n}\n");
    const QString profile = writeFile(dir, QStringLiteral("bad.json"), profileWith(R"("gamma.js")"));
    const Run r = runSimulate({QStringLiteral("--profile"), profile, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(profile.toUtf8() + ": units[0].script: gamma.js:3:"), r.err.constData());
    QVERIFY2(r.err.contains(": SyntaxError: "), r.err.constData());
    const QString missing = writeFile(dir, QStringLiteral("missing.json"), profileWith(R"("nowhere.js")"));
    const Run m = runSimulate({QStringLiteral("--profile"), missing, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")});
    QCOMPARE(m.exitCode, 2);
    QVERIFY2(m.err.contains(missing.toUtf8() + ": units[0].script: nowhere.js: no such script file"), m.err.constData());
}

// framing=delimited served by a script alone: "$01R#" answered from unit 1's holding 0.
void tst_SimulateScripts::delimitedServedByScript()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir, QStringLiteral("line.js"),
              "function onFrame(frame) {\n"
              "  var m = /^\\$(\\d\\d)R#$/.exec(frame);\n"
              "  return m ? '$' + m[1] + ' ' + unit.read('holding', 1, 2).join(' ') + ' #' : null;\n"
              "}\n");
    const QString profile = writeFile(
        dir, QStringLiteral("line.json"),
        R"({"name": "line", "units": [{"id": 1, "tables": {"holding": [{"address": 0, "values": [5, 6, 7]}]}}],
            "delimited": {"script": "line.js"}})");
    SimCli sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("--profile"), profile, QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0?framing=delimited&start=24&end=23")},
                       1, &why),
             qPrintable(why));
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), sim.port(0));
    QVERIFY(socket.waitForConnected(5000));
    socket.write("$01R#");
    QByteArray answer;
    QElapsedTimer clock;
    clock.start();
    while (!answer.endsWith('#') && clock.elapsed() < 5000) {
        if (socket.waitForReadyRead(500))
            answer += socket.readAll();
    }
    QCOMPARE(answer, QByteArray("$01 6 7 #"));
    QCOMPARE(sim.stop(), 0);
    QVERIFY2(sim.output().contains("$01R# -> $01 6 7 #"), sim.output().constData());
}

// A script's top-level log() runs while the profile loads, before the endpoints listen: its line
// comes after the "simulating" header and the "listening" lines, not above them.
void tst_SimulateScripts::topLevelLogAfterHeader()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeFile(dir, QStringLiteral("early.js"), "log('calibration table loaded');\nfunction onRequest(r) {}\n");
    const QString profile = writeFile(dir, QStringLiteral("early.json"), profileWith(R"("early.js")"));
    SimCli sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("--profile"), profile, QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0")}, 1,
                       &why),
             qPrintable(why));
    QCOMPARE(sim.stop(), 0);
    const QByteArray out = sim.output();
    const qsizetype header = out.indexOf("simulating scripted");
    const qsizetype listening = out.indexOf("listening ");
    const qsizetype logged = out.indexOf("log: calibration table loaded");
    QVERIFY2(header >= 0 && listening > header && logged > listening, out.constData());
    QCOMPARE(out.count("calibration table loaded"), 1);
}

QTEST_GUILESS_MAIN(tst_SimulateScripts)
#include "tst_simulate_scripts.moc"
