// mbscope replay as users run it: a recording made by the engine polling `mbscope simulate
// --profile rosrao-gamma` without its live gate counts (RTU over TCP) is replayed against the same simulator (every answer
// matches), against one whose profile was changed (differences by field key, exit 1), and
// served by `mbscope replay --serve` then read back with mbscope read, pymodbus and replay itself.

#include "clitest.h"

#include "exchange/requestitem.h"
#include "traffic/trafficjournal.h"
#include "traffic/trafficlog.h"
#include "engine/transactionengine.h"
#include "protocol/adubuilder.h"
#include "transport/linkurl.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QHash>
#include <QtCore/QJsonArray>
#include <QtCore/QLocale>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtTest/QTest>

#include <csignal>
#include <memory>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

QByteArray pdu(const char *hex)
{
    return QByteArray::fromHex(hex);
}

// The requests a device's journal (simulate --record) holds, by function code (RTU over TCP:
// unit, then the function code).
QHash<quint8, int> requestsReceived(const QString &journal)
{
    QHash<quint8, int> byFunction;
    (void)TrafficJournalReader::read(journal, [&](const TrafficEntry &e) {
        if (e.direction == TrafficDirection::In && e.bytes.size() >= 2)
            ++byFunction[quint8(e.bytes.at(1))];
    });
    return byFunction;
}

// Out frames (requests written) in a journal being written.
int requestsWritten(const QString &journal)
{
    int n = 0;
    (void)TrafficJournalReader::read(journal, [&](const TrafficEntry &e) { n += e.direction == TrafficDirection::Out ? 1 : 0; });
    return n;
}

} // namespace

class TestCliReplay : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void replayMatchesTheSameDevice();
    void replayAtRecordedPacing();
    void replayReportsChangedValues();
    void replayReportsLinkAndUsageErrors();
    void serveAnswersWithTheRecording();
    void serveToPymodbus();
    void recordedWritesAreNotSent();
    void recordedRestartsAreNotSent();
    void killedRecordingIsTruncated();
    void serveCountsAnswersApartFromSilences();

private:
    [[nodiscard]] bool record(const QString &target, QString *error);

    QTemporaryDir m_dir;
    Background m_sim;
    QString m_journal;
    QString m_session;
    QString m_steadyProfile; // rosrao-gamma without its live values
    int m_requests = 0;
};

// Polls the simulator with the engine, its traffic journaled: reads of the settings of units 1
// and 3 (the same request three times), a write of the value already there, a read of a
// register the device does not have (exception 02) and a unit nobody has (exception 0B).
bool TestCliReplay::record(const QString &target, QString *error)
{
    const LinkUrl::Result parsed = LinkUrl::parse(target);
    if (!parsed.url) {
        *error = parsed.error;
        return false;
    }
    const QList<QPair<quint8, QByteArray>> requests = {
        {1, pdu("0300790016")}, {3, pdu("030079000d")}, {1, pdu("0300790016")}, {1, pdu("06007d00fa")},
        {1, pdu("0302000001")}, {7, pdu("0300790001")}, {1, pdu("0300790016")},
    };
    TrafficLog log;
    if (!log.openJournal(m_journal, {}, true, error))
        return false;
    TransactionEngine engine;
    engine.setTarget(*parsed.url);
    engine.setTrafficLog(&log);
    for (const auto &[unit, request] : requests) {
        RequestItem item = RequestItem::forLink(AduBuilder::rtu(request, unit), *parsed.url);
        item.timeoutMs = 300;
        if (!engine.sendAndWait(item)) {
            *error = QStringLiteral("the engine did not finish a request");
            return false;
        }
        QThread::msleep(20); // a recorded pacing to replay
        ++m_requests;
    }
    engine.closeLink();
    engine.setTrafficLog(nullptr);
    log.closeJournal();
    QFile session(m_session);
    if (!session.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = session.errorString();
        return false;
    }
    session.write(QStringLiteral(R"({"format": "mbscope-session", "version": 1, "name": "recorded",
  "target": {"url": "%1", "timeoutMs": 300}, "capture": {"journal": "recorded.mbscope.journal"}})")
                      .arg(target)
                      .toUtf8());
    return true;
}

void TestCliReplay::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_journal = m_dir.filePath(QStringLiteral("recorded.mbscope.journal"));
    m_session = m_dir.filePath(QStringLiteral("recorded.mbscope.json"));
    QString error;
    // The detector without its live gate counts (0x0086, inside every read here): a count that
    // changes once the first 1000 ms gate ends would make the comparisons depend on how fast a
    // loaded machine runs them.
    QFile shipped(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/rosrao-gamma.json"));
    QVERIFY(shipped.open(QIODevice::ReadOnly));
    QString steady = QString::fromUtf8(shipped.readAll());
    static const QRegularExpression generator(QStringLiteral(R"(,\s*"generator": \{[^}]*\})"));
    QCOMPARE(steady.count(generator), 2);
    steady.remove(generator);
    m_steadyProfile = m_dir.filePath(QStringLiteral("steady.json"));
    QFile steadyFile(m_steadyProfile);
    QVERIFY(steadyFile.open(QIODevice::WriteOnly));
    steadyFile.write(steady.toUtf8());
    steadyFile.close();
    QVERIFY2(m_sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), m_steadyProfile, QStringLiteral("--listen"),
                          QStringLiteral("rtu-tcp://127.0.0.1:0")},
                         &error),
             qPrintable(error));
    QVERIFY2(record(m_sim.url(), &error), qPrintable(error));
}

void TestCliReplay::replayMatchesTheSameDevice()
{
    // The session's own target; the live gate counts (0x0086) are outside what was read. The
    // recorded write is not sent (recordedWritesAreNotSent): every other request is.
    const CliResult r = runMbscope({QStringLiteral("replay"), m_session, QStringLiteral("--speed"), QStringLiteral("max"), QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("replayed")).toInt(), m_requests - 1);
    QCOMPARE(o.value(QStringLiteral("matched")).toInt(), m_requests - 1);
    QCOMPARE(o.value(QStringLiteral("skipped_writes")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("differences")).toArray().size(), 0);
    const QJsonObject latency = o.value(QStringLiteral("latency_us")).toObject();
    // Every request sent answered, exceptions included (unit 7: 0B from the simulator's gateway).
    QCOMPARE(latency.value(QStringLiteral("recorded")).toObject().value(QStringLiteral("count")).toInt(), m_requests - 1);
    QCOMPARE(latency.value(QStringLiteral("replayed")).toObject().value(QStringLiteral("count")).toInt(), m_requests - 1);
}

void TestCliReplay::replayAtRecordedPacing()
{
    const CliResult r = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--target"), m_sim.url()});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    const QString text = r.outText();
    QVERIFY2(text.contains(QStringLiteral("at the recorded pacing")), r.describe().constData());
    QVERIFY2(text.contains(QStringLiteral("matched       %1").arg(m_requests - 1)), r.describe().constData());
    QVERIFY2(text.contains(QStringLiteral("latency ms    recorded median")), r.describe().constData());
    // Requests go out no earlier than their recorded offsets: at least the 20 ms gaps recorded.
    const CliResult j = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--target"), m_sim.url(), QStringLiteral("--json")});
    QVERIFY2(j.json().value(QStringLiteral("elapsed_ms")).toDouble() >= 20.0 * (m_requests - 1), j.describe().constData());
}

void TestCliReplay::replayReportsChangedValues()
{
    // The profile with one published value changed: 250 at 0x007D becomes 251.
    QFile steady(m_steadyProfile);
    QVERIFY(steady.open(QIODevice::ReadOnly));
    QByteArray profile = steady.readAll();
    QVERIFY(profile.contains("[1050, 0, 0, 0, 250,"));
    profile.replace("[1050, 0, 0, 0, 250,", "[1050, 0, 0, 0, 251,");
    const QString changed = m_dir.filePath(QStringLiteral("changed.json"));
    QFile out(changed);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(profile);
    out.close();
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), changed, QStringLiteral("--listen"), QStringLiteral("rtu-tcp://127.0.0.1:0")}, &error),
             qPrintable(error));

    // The recorded write sent as well (--send-writes): it puts 250 back, so the read after it matches.
    const CliResult r = runMbscope({QStringLiteral("replay"), m_session, QStringLiteral("--target"), sim.url(), QStringLiteral("--speed"), QStringLiteral("10"),
                                    QStringLiteral("--send-writes")});
    QVERIFY2(r.finished && r.exitCode == 1, r.describe().constData());
    const QString text = r.outText();
    // Unit 1's three reads differ (unit 3's profile kept 250), each by that one field.
    QCOMPARE(text.count(QStringLiteral("modbus.register_value@0x007D: recorded 250, now 251")), 3);
    QVERIFY2(text.contains(QStringLiteral("#1 unit 1 Read Holding Registers 03 00 79 00 16: values differ")), r.describe().constData());
    QVERIFY2(text.contains(QStringLiteral("differed      3  (values 3, outcome 0, missing answers 0)")), r.describe().constData());
    QVERIFY2(!text.contains(QStringLiteral("@0x007E")), r.describe().constData());
    // The write echoes its request, which did not change: it matches.
    QVERIFY2(!text.contains(QStringLiteral("#4 ")), r.describe().constData());

    // A field expected to change, named as the report names it: reported as ignored, not counted.
    const CliResult ignored = runMbscope({QStringLiteral("replay"), m_session, QStringLiteral("--target"), sim.url(), QStringLiteral("--speed"),
                                          QStringLiteral("max"), QStringLiteral("--ignore"), QStringLiteral("modbus.register_value@0x007D")});
    QVERIFY2(ignored.finished && ignored.exitCode == 0, ignored.describe().constData());
    QVERIFY2(ignored.outText().contains(QStringLiteral("differed      0  (values 0, outcome 0, missing answers 0)")), ignored.describe().constData());
    // (The first replay's write put 250 back in unit 1: how many answers still differ depends on
    // that state, not on --ignore; at least unit 3's does.)
    static const QRegularExpression ignoredLine(QStringLiteral(
        R"(\nignored       modbus\.register_value@0x007D: differed in [1-9][0-9]* answer\(s\), not counted; )"
        R"(first modbus\.register_value@0x007D: recorded 250, now 251 \(request #[0-9]+\)\n)"));
    QVERIFY2(ignoredLine.match(ignored.outText()).hasMatch(), ignored.describe().constData());
    // The decimal address selects the same field; JSON lists what was ignored.
    const CliResult json = runMbscope({QStringLiteral("replay"), m_session, QStringLiteral("--target"), sim.url(), QStringLiteral("--speed"),
                                       QStringLiteral("max"), QStringLiteral("--ignore"), QStringLiteral("modbus.register_value@125"), QStringLiteral("--json")});
    QVERIFY2(json.finished && json.exitCode == 0, json.describe().constData());
    const QJsonArray list = json.json().value(QStringLiteral("ignored")).toArray();
    QCOMPARE(list.size(), 1);
    QCOMPARE(list.at(0).toObject().value(QStringLiteral("field")).toString(), QStringLiteral("modbus.register_value@125"));
    QVERIFY(list.at(0).toObject().value(QStringLiteral("answers")).toInt() >= 1);
    QCOMPARE(json.json().value(QStringLiteral("values_differ")).toInt(), 0);
    // Another field ignored: the change is still a difference.
    const CliResult other = runMbscope({QStringLiteral("replay"), m_session, QStringLiteral("--target"), sim.url(), QStringLiteral("--speed"),
                                        QStringLiteral("max"), QStringLiteral("--ignore"), QStringLiteral("modbus.register_value@0x007E")});
    QVERIFY2(other.finished && other.exitCode == 1, other.describe().constData());
    QVERIFY2(other.outText().contains(QStringLiteral("ignored       modbus.register_value@0x007E: no answer differed there")), other.describe().constData());

    // The same in the session document (capture.ignore).
    QFile session(m_session);
    QVERIFY(session.open(QIODevice::ReadOnly));
    QByteArray document = session.readAll();
    session.close();
    const QString withIgnore = m_dir.filePath(QStringLiteral("ignoring.mbscope.json"));
    QFile ignoring(withIgnore);
    QVERIFY(ignoring.open(QIODevice::WriteOnly));
    ignoring.write(QByteArray(document).replace(R"("journal": "recorded.mbscope.journal")",
                                                R"("journal": "recorded.mbscope.journal", "ignore": ["modbus.register_value@0x007D"])"));
    ignoring.close();
    const CliResult fromDocument = runMbscope({QStringLiteral("replay"), withIgnore, QStringLiteral("--target"), sim.url(), QStringLiteral("--speed"), QStringLiteral("max")});
    QVERIFY2(fromDocument.finished && fromDocument.exitCode == 0, fromDocument.describe().constData());
    QVERIFY2(ignoredLine.match(fromDocument.outText()).hasMatch(), fromDocument.describe().constData());

    // Bad selectors: said where.
    const CliResult badOption = runMbscope({QStringLiteral("replay"), m_session, QStringLiteral("--target"), sim.url(), QStringLiteral("--ignore"), QStringLiteral("register@0x7D")});
    QVERIFY2(badOption.exitCode == 2 && badOption.errText().contains(QStringLiteral("--ignore: 'register@0x7D' is not a field selector")),
             badOption.describe().constData());
    QVERIFY(ignoring.open(QIODevice::WriteOnly | QIODevice::Truncate));
    ignoring.write(QByteArray(document).replace(R"("journal": "recorded.mbscope.journal")",
                                                R"("journal": "recorded.mbscope.journal", "ignore": ["modbus.register_value@70000"])"));
    ignoring.close();
    const CliResult badDocument = runMbscope({QStringLiteral("replay"), withIgnore, QStringLiteral("--target"), sim.url()});
    QVERIFY2(badDocument.exitCode == 2 && badDocument.errText().contains(QStringLiteral("capture.ignore[0]"))
                 && badDocument.errText().contains(QStringLiteral("address 70000 is beyond 65535")),
             badDocument.describe().constData());
}

void TestCliReplay::replayReportsLinkAndUsageErrors()
{
    const QString closed = QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(closedPort());
    const CliResult refused = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--target"), closed, QStringLiteral("--speed"), QStringLiteral("max")});
    QVERIFY2(refused.finished && refused.exitCode == 2, refused.describe().constData());
    QVERIFY2(refused.errText().contains(QStringLiteral("127.0.0.1")), refused.describe().constData());

    const CliResult noTarget = runMbscope({QStringLiteral("replay"), m_journal});
    QVERIFY2(noTarget.exitCode == 2 && noTarget.errText().contains(QStringLiteral("no target: give --target URL")), noTarget.describe().constData());
    const CliResult badSpeed = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--speed"), QStringLiteral("fast")});
    QVERIFY2(badSpeed.exitCode == 2 && badSpeed.errText().contains(QStringLiteral("--speed 'fast' is not a speed")), badSpeed.describe().constData());
    const CliResult missing = runMbscope({QStringLiteral("replay"), m_dir.filePath(QStringLiteral("none.pcapng"))});
    QVERIFY2(missing.exitCode == 2 && missing.errText().contains(QStringLiteral("no such file")), missing.describe().constData());
}

void TestCliReplay::serveAnswersWithTheRecording()
{
    // The RTU-over-TCP recording served over Modbus TCP: answers re-framed, matched by unit and PDU.
    Background served;
    QString error;
    QVERIFY2(served.start({QStringLiteral("replay"), m_session, QStringLiteral("--serve"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--speed"), QStringLiteral("max")},
                          &error),
             qPrintable(error));
    QVERIFY2(served.url().startsWith(QStringLiteral("tcp://127.0.0.1:")), qPrintable(served.url()));

    const CliResult read = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), served.url(), QStringLiteral("--unit"), QStringLiteral("1"),
                                       QStringLiteral("--address"), QStringLiteral("0x79"), QStringLiteral("--quantity"), QStringLiteral("22"), QStringLiteral("--json")});
    QVERIFY2(read.finished && read.exitCode == 0, read.describe().constData());
    QVERIFY2(read.outText().contains(QStringLiteral("1050")) && read.outText().contains(QStringLiteral("8000")), read.describe().constData());

    // A request never recorded: exception 0B, as the startup line says.
    const CliResult unrecorded = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), served.url(), QStringLiteral("--address"), QStringLiteral("0x80")});
    QVERIFY2(unrecorded.exitCode == 1 && unrecorded.outText().contains(QStringLiteral("0x0B")), unrecorded.describe().constData());

    // Replaying the recording against its own stand-in: every answer (and the silence) matches.
    const CliResult replay = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--target"), served.url(), QStringLiteral("--speed"), QStringLiteral("max"),
                                         QStringLiteral("--timeout"), QStringLiteral("300ms"), QStringLiteral("--json")});
    QVERIFY2(replay.finished && replay.exitCode == 0, replay.describe().constData());
    QCOMPARE(replay.json().value(QStringLiteral("matched")).toInt(), m_requests - 1); // the write is not sent

    const QString output = QString::fromUtf8(served.stop());
    QVERIFY2(output.contains(QStringLiteral("not recorded  exception 0B")), qPrintable(output));
    QVERIFY2(output.contains(QStringLiteral("1 request never recorded")), qPrintable(output));
}

void TestCliReplay::serveToPymodbus()
{
    QProcess probe;
    probe.start(QStringLiteral("/usr/bin/python3"), {QStringLiteral("-c"), QStringLiteral("import pymodbus")});
    if (!probe.waitForFinished(30000) || probe.exitCode() != 0)
        QSKIP("pymodbus is missing: apt install python3-pymodbus (scripts/install-deps.sh --tests)");
    Background served;
    QString error;
    QVERIFY2(served.start({QStringLiteral("replay"), m_journal, QStringLiteral("--serve"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--unrecorded"), QStringLiteral("ignore")},
                          &error),
             qPrintable(error));
    const quint16 port = quint16(served.url().section(QLatin1Char(':'), -1).toUInt());
    // Unit 3's settings were read once: each read gets that answer again (cycling through one).
    const QString script = QStringLiteral(
        "from pymodbus.client import ModbusTcpClient\n"
        "c = ModbusTcpClient('127.0.0.1', port=%1, timeout=1, retries=0)\n"
        "c.connect()\n"
        "for _ in range(2):\n"
        "    r = c.read_holding_registers(0x79, 13, slave=3)\n"
        "    print(' '.join(str(v) for v in r.registers))\n"
        "r = c.read_holding_registers(0x79, 12, slave=3)\n"
        "print('unrecorded', 'error' if r.isError() else 'answered')\n"
        "c.close()\n").arg(port);
    QProcess client;
    client.start(QStringLiteral("/usr/bin/python3"), {QStringLiteral("-c"), script});
    QVERIFY(client.waitForFinished(60000));
    const QString out = QString::fromUtf8(client.readAllStandardOutput());
    const QString expected = QStringLiteral("1050 0 0 0 250 1 1000 10000 4 4 80 800 8000\n");
    QVERIFY2(out.startsWith(expected + expected), qPrintable(out + QString::fromUtf8(client.readAllStandardError())));
    QVERIFY2(out.contains(QStringLiteral("unrecorded error")), qPrintable(out));
}

// Issue 26 item 1: a replay to a live device sends none of the recording's writes unless
// --send-writes; each one skipped is listed (unit, function, address, quantity) and counted.
// The device journals what reaches it (simulate --record): the write must not be there.
void TestCliReplay::recordedWritesAreNotSent()
{
    QString error;
    const QString seen = m_dir.filePath(QStringLiteral("device-without-writes.mbscope.journal"));
    Background device;
    QVERIFY2(device.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                           QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--record"), seen},
                          &error),
             qPrintable(error));
    const CliResult json = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--target"), device.url(), QStringLiteral("--speed"),
                                       QStringLiteral("max"), QStringLiteral("--json")});
    QVERIFY2(json.finished && json.exitCode == 0, json.describe().constData());
    const QJsonObject o = json.json();
    QCOMPARE(o.value(QStringLiteral("requests")).toInt(), m_requests);
    QCOMPARE(o.value(QStringLiteral("skipped_writes")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("replayed")).toInt(), m_requests - 1);
    QCOMPARE(o.value(QStringLiteral("matched")).toInt(), m_requests - 1);
    const QJsonArray skipped = o.value(QStringLiteral("skipped")).toArray();
    QCOMPARE(skipped.size(), 1);
    const QJsonObject write = skipped.at(0).toObject();
    QCOMPARE(write.value(QStringLiteral("request")).toInt(), 4);
    QCOMPARE(write.value(QStringLiteral("unit")).toInt(), 1);
    QCOMPARE(write.value(QStringLiteral("function")).toString(), QStringLiteral("0x06"));
    QCOMPARE(write.value(QStringLiteral("address")).toInt(), 0x7D);
    QCOMPARE(write.value(QStringLiteral("quantity")).toInt(), 1);

    const CliResult text = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--target"), device.url(), QStringLiteral("--speed"),
                                       QStringLiteral("max")});
    QVERIFY2(text.finished && text.exitCode == 0, text.describe().constData());
    QVERIFY2(text.outText().contains(QStringLiteral("1 of them is a write: not sent (--send-writes sends them)")), text.describe().constData());
    QVERIFY2(text.outText().contains(QStringLiteral("#4 unit 1 Write Single Register (0x06) address 0x007D quantity 1: not sent")),
             text.describe().constData());
    QVERIFY2(text.outText().contains(QStringLiteral("skipped       1 write, not sent (--send-writes sends them)")), text.describe().constData());
    (void)device.stop();
    QVERIFY2(requestsReceived(seen).value(0x03) > 0, "the device's journal holds no reads");
    QCOMPARE(requestsReceived(seen).value(0x06), 0);

    // Asked for: sent, and compared like any other request.
    const QString seenWithWrites = m_dir.filePath(QStringLiteral("device-with-writes.mbscope.journal"));
    Background asked;
    QVERIFY2(asked.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                          QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--record"), seenWithWrites},
                         &error),
             qPrintable(error));
    const CliResult sent = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--target"), asked.url(), QStringLiteral("--speed"),
                                       QStringLiteral("max"), QStringLiteral("--send-writes"), QStringLiteral("--json")});
    QVERIFY2(sent.finished && sent.exitCode == 0, sent.describe().constData());
    QCOMPARE(sent.json().value(QStringLiteral("skipped_writes")).toInt(), 0);
    QCOMPARE(sent.json().value(QStringLiteral("matched")).toInt(), m_requests);
    (void)asked.stop();
    QCOMPARE(requestsReceived(seenWithWrites).value(0x06), 1);

    // The option is documented, and means nothing to --serve.
    const CliResult help = runMbscope({QStringLiteral("replay"), QStringLiteral("--help")});
    QVERIFY2(help.outText().contains(QStringLiteral("--send-writes")), help.describe().constData());
    const CliResult serve = runMbscope({QStringLiteral("replay"), m_journal, QStringLiteral("--serve"), QStringLiteral("tcp://127.0.0.1:0"),
                                        QStringLiteral("--send-writes")});
    QVERIFY2(serve.exitCode == 2 && serve.errText().contains(QStringLiteral("--send-writes applies to a replay to a device")),
             serve.describe().constData());
}

// Issue 26 item 1, "the same rule for anything else that re-sends recorded traffic": a recorded
// Diagnostics Restart Communications Option (08/0001) restarts the device's port and Force Listen
// Only Mode (08/0004) silences it until restarted; neither is re-sent unasked (both are recorded
// from a simulator of their own, the restart taking it out of listen-only mode). Return Query Data
// (08/0000) only echoes and is replayed.
void TestCliReplay::recordedRestartsAreNotSent()
{
    const QString journal = m_dir.filePath(QStringLiteral("restarts.mbscope.journal"));
    QString error;
    Background recorded; // a device of its own: listen-only mode must not reach the other tests' simulator
    QVERIFY2(recorded.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                             QStringLiteral("rtu-tcp://127.0.0.1:0")},
                            &error),
             qPrintable(error));
    const LinkUrl::Result parsed = LinkUrl::parse(recorded.url());
    QVERIFY2(parsed.url, qPrintable(parsed.error));
    {
        TrafficLog log;
        QVERIFY2(log.openJournal(journal, {}, true, &error), qPrintable(error));
        TransactionEngine engine;
        engine.setTarget(*parsed.url);
        engine.setTrafficLog(&log);
        for (const char *request : {"080000a537", "0800040000", "0800010000", "0300790001"}) {
            RequestItem item = RequestItem::forLink(AduBuilder::rtu(pdu(request), 1), *parsed.url);
            item.timeoutMs = 300;
            QVERIFY(engine.sendAndWait(item));
        }
        engine.closeLink();
        engine.setTrafficLog(nullptr);
        log.closeJournal();
    }
    (void)recorded.stop();
    const QString seen = m_dir.filePath(QStringLiteral("device-without-restarts.mbscope.journal"));
    Background device;
    QVERIFY2(device.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                           QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--record"), seen},
                          &error),
             qPrintable(error));
    const CliResult json = runMbscope({QStringLiteral("replay"), journal, QStringLiteral("--target"), device.url(), QStringLiteral("--speed"),
                                       QStringLiteral("max"), QStringLiteral("--json")});
    QVERIFY2(json.finished && json.exitCode == 0, json.describe().constData());
    const QJsonObject o = json.json();
    QCOMPARE(o.value(QStringLiteral("skipped_writes")).toInt(), 2);
    QCOMPARE(o.value(QStringLiteral("replayed")).toInt(), 2);
    const QJsonArray skipped = o.value(QStringLiteral("skipped")).toArray();
    QCOMPARE(skipped.size(), 2);
    QCOMPARE(skipped.at(0).toObject().value(QStringLiteral("subFunction")).toString(), QStringLiteral("0x0004"));
    QCOMPARE(skipped.at(1).toObject().value(QStringLiteral("subFunction")).toString(), QStringLiteral("0x0001"));
    const CliResult text = runMbscope({QStringLiteral("replay"), journal, QStringLiteral("--target"), device.url(), QStringLiteral("--speed"),
                                       QStringLiteral("max")});
    QVERIFY2(text.outText().contains(QStringLiteral("#3 unit 1 Diagnostics (0x08) sub-function 0x0001 Restart Communications Option: not sent")),
             text.describe().constData());
    (void)device.stop();
    QCOMPARE(requestsReceived(seen).value(0x08), 2); // Return Query Data, once per replay
}

// Issue 26 item 7: a poll recording killed with SIGKILL while a request is in flight (the
// device drops that one request). The journal holds whole batches and no end record: analyze
// says it is truncated and where; the request cut by the end is unanswered at the end of the
// recording, not a timeout; replay compares the completed exchanges only.
void TestCliReplay::killedRecordingIsTruncated()
{
    const QString faults = m_dir.filePath(QStringLiteral("drop-0x80.json"));
    QFile file(faults);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"seed": 1, "rules": [{"name": "never", "kind": "drop", "start": 128, "probability": 1.0}]})");
    file.close();
    Background device;
    QString error;
    QVERIFY2(device.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                           QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults, QStringLiteral("--quiet")},
                          &error),
             qPrintable(error));
    const QString journal = m_dir.filePath(QStringLiteral("killed.mbscope.journal"));
    // Each cycle: the settings read three times, then 0x0080, which the device never answers.
    QProcess poll;
    poll.start(mbscopePath(), {QStringLiteral("poll"), QStringLiteral("--target"), device.url(), QStringLiteral("--complete"),
                               QStringLiteral("--hex"), QStringLiteral("0300790016"), QStringLiteral("--hex"), QStringLiteral("0300790016"),
                               QStringLiteral("--hex"), QStringLiteral("0300790016"), QStringLiteral("--hex"), QStringLiteral("0300800001"),
                               QStringLiteral("--timeout"), QStringLiteral("60s"), QStringLiteral("--interval"), QStringLiteral("0"),
                               QStringLiteral("--record"), journal});
    QVERIFY(poll.waitForStarted(30000));
    // Until the request in flight is on disk (its batch written by the journal's timer).
    QElapsedTimer waited;
    waited.start();
    while (requestsWritten(journal) < 4 && waited.elapsed() < 60000 && poll.state() == QProcess::Running)
        QThread::msleep(20);
    QVERIFY2(poll.state() == QProcess::Running, poll.readAllStandardError().constData());
    QCOMPARE(requestsWritten(journal), 4);
    ::kill(pid_t(poll.processId()), SIGKILL);
    QVERIFY(poll.waitForFinished(10000));
    QCOMPARE(poll.exitStatus(), QProcess::CrashExit);

    const CliResult a = runMbscope({QStringLiteral("analyze"), journal, QStringLiteral("--json")});
    QVERIFY2(a.finished && a.exitCode == 1, a.describe().constData()); // a damaged source
    const QJsonObject o = a.json();
    const QJsonObject source = o.value(QStringLiteral("source")).toObject();
    QVERIFY2(!source.value(QStringLiteral("complete")).toBool(), a.describe().constData());
    const QString size = QLocale(QLocale::English).toString(QFileInfo(journal).size());
    QVERIFY2(source.value(QStringLiteral("error")).toString().contains(
                 QStringLiteral("truncated: its writer never closed it (killed, crashed or still writing), it stops after the last "
                                "complete batch, at byte %1").arg(size)),
             a.describe().constData());
    QCOMPARE(source.value(QStringLiteral("unanswered_at_end")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("count")).toInt(), 3);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 3);
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), 0);
    const CliResult text = runMbscope({QStringLiteral("analyze"), journal});
    QVERIFY2(text.outText().contains(QStringLiteral("\ntruncated     recovered ")), text.describe().constData());
    QVERIFY2(text.outText().contains(QStringLiteral("\nunanswered    1 request(s) at the end of the recording")), text.describe().constData());
    QVERIFY2(!text.outText().contains(QStringLiteral("ends cleanly")), text.describe().constData());

    // Replayed to a device that answers 0x0080: only the three completed exchanges are compared.
    // (The live gate count at 0x0086 grows with the simulator's age: expected to change.)
    const CliResult r = runMbscope({QStringLiteral("replay"), journal, QStringLiteral("--target"), m_sim.url(), QStringLiteral("--speed"),
                                    QStringLiteral("max"), QStringLiteral("--ignore"), QStringLiteral("modbus.register_value@0x0086"),
                                    QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe().constData());
    QCOMPARE(r.json().value(QStringLiteral("requests")).toInt(), 3);
    QCOMPARE(r.json().value(QStringLiteral("matched")).toInt(), 3);
    QVERIFY2(r.errText().contains(QStringLiteral("truncated: its writer never closed it")), r.describe().constData());
}

// Issue 26 item 12: replay --serve said "serving 2 recorded answers" of a recording holding one
// answer and one silence (a request recorded without an answer): one too many. Answers and
// silences are counted apart, as they are served.
void TestCliReplay::serveCountsAnswersApartFromSilences()
{
    const QString faults = m_dir.filePath(QStringLiteral("drop-0x80-again.json"));
    QFile file(faults);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"seed": 1, "rules": [{"name": "never", "kind": "drop", "start": 128, "probability": 1.0}]})");
    file.close();
    Background device;
    QString error;
    QVERIFY2(device.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("rosrao-gamma"), QStringLiteral("--listen"),
                           QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--faults"), faults, QStringLiteral("--quiet")},
                          &error),
             qPrintable(error));
    const QString journal = m_dir.filePath(QStringLiteral("answer-and-silence.mbscope.journal"));
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), device.url(), QStringLiteral("--complete"),
                                       QStringLiteral("--hex"), QStringLiteral("0300790001"), QStringLiteral("--hex"), QStringLiteral("0300800001"),
                                       QStringLiteral("--timeout"), QStringLiteral("200ms"), QStringLiteral("--count"), QStringLiteral("1"),
                                       QStringLiteral("--record"), journal, QStringLiteral("--json")});
    QVERIFY2(poll.finished, poll.describe().constData());
    QCOMPARE(poll.json().value(QStringLiteral("ok")).toInt(), 1);
    QCOMPARE(poll.json().value(QStringLiteral("timeouts")).toInt(), 1);

    Background served;
    QVERIFY2(served.start({QStringLiteral("replay"), journal, QStringLiteral("--serve"), QStringLiteral("rtu-tcp://127.0.0.1:0"),
                           QStringLiteral("--speed"), QStringLiteral("max")},
                          &error),
             qPrintable(error));
    const CliResult answered = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), served.url(), QStringLiteral("--address"),
                                           QStringLiteral("0x79")});
    QVERIFY2(answered.finished && answered.exitCode == 0, answered.describe().constData());
    const CliResult silent = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), served.url(), QStringLiteral("--address"),
                                         QStringLiteral("0x80"), QStringLiteral("--timeout"), QStringLiteral("200ms")});
    QVERIFY2(silent.finished && silent.exitCode != 0, silent.describe().constData());
    const QString output = QString::fromUtf8(served.stop());
    QVERIFY2(output.startsWith(QStringLiteral("serving 1 recorded answer and 1 recorded silence of %1 (2 distinct requests, units 1)\n").arg(journal)),
             qPrintable(output));
    QVERIFY2(output.contains(QStringLiteral(": 1 recorded answer served, 1 recorded silence kept, 0 requests never recorded\n")), qPrintable(output));
}

QTEST_GUILESS_MAIN(TestCliReplay)
#include "tst_cli_replay.moc"
