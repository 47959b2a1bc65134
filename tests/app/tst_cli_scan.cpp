// mbscope scan as users run it (issue 18): the unit scan against the simulator behind a gateway
// (units that answer, give 0A, answer with another id, stay silent, send a wrong CRC, refuse the
// function, and ids nobody has: 0B), against a test peer that echoes every request, against a
// pymodbus server with several units; Ctrl-C and --max-time end a scan with what it found; the
// register map of the `conformance` simulator saved as a profile draft, served again by
// `mbscope simulate --profile FILE`, maps to the same blocks with the same values.

#include "clitest.h"

#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QSocketNotifier>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtTest/QTest>

#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

using namespace mbscope::testcli;
using mbscope::testpeers::PeerProcess;

namespace {

// Six units behind one rtu-tcp endpoint, each made to do one thing by a fault rule
// (docs/profiles.md, Fault injection); ids 7 and up have no unit: the endpoint answers 0B.
const char kGatewayProfile[] = R"({
  "name": "scan-gateway",
  "units": [
    {"id": 1, "tables": {"holding": [{"address": 0, "count": 10, "values": [11, 12]}]}},
    {"id": 2, "tables": {"holding": [{"address": 0, "count": 10}]}},
    {"id": 3, "tables": {"holding": [{"address": 0, "count": 10}]}},
    {"id": 4, "tables": {"holding": [{"address": 0, "count": 10}]}},
    {"id": 5, "tables": {"holding": [{"address": 0, "count": 10}]}},
    {"id": 6, "functions": ["0x04"], "tables": {"input": [{"address": 0, "count": 10}]}}
  ],
  "faults": {"rules": [
    {"kind": "exception", "units": [2], "code": "0x0A"},
    {"kind": "wrongUnit", "units": [3], "delta": 4},
    {"kind": "drop", "units": [4]},
    {"kind": "wrongChecksum", "units": [5]}
  ]}
})";

QMap<int, QJsonObject> unitsByID(const QJsonObject &scan)
{
    QMap<int, QJsonObject> out;
    for (const QJsonValue &v : scan.value(QStringLiteral("units")).toArray())
        out.insert(v.toObject().value(QStringLiteral("unit")).toInt(), v.toObject());
    return out;
}

// The blocks of a --map --json result: "function first-last" -> values.
QMap<QString, QJsonArray> blocksOf(const QJsonObject &map)
{
    QMap<QString, QJsonArray> out;
    for (const QJsonValue &t : map.value(QStringLiteral("tables")).toArray()) {
        const int function = t.toObject().value(QStringLiteral("function")).toInt();
        for (const QJsonValue &b : t.toObject().value(QStringLiteral("blocks")).toArray()) {
            const QJsonObject o = b.toObject();
            out.insert(QStringLiteral("%1 %2-%3").arg(function).arg(o.value(QStringLiteral("first")).toInt()).arg(o.value(QStringLiteral("last")).toInt()),
                       o.value(QStringLiteral("values")).toArray());
        }
    }
    return out;
}

// mbscope run with standard error on a pseudo terminal, as a shell gives it, so that the progress
// line is drawn (ProgressLine draws only on a terminal); what the terminal received in *terminal.
CliResult runOnTerminal(const QStringList &arguments, QByteArray *terminal, int timeoutMs = 120000)
{
    CliResult result;
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
        result.err = "no pseudo terminal";
        return result;
    }
    struct winsize size = {};
    size.ws_col = 200; // the line is cut to the terminal's width
    size.ws_row = 24;
    ::ioctl(master, TIOCSWINSZ, &size);
    const int slave = ::open(::ptsname(master), O_RDWR | O_NOCTTY);
    ::fcntl(master, F_SETFL, O_NONBLOCK);
    const auto drain = [master, terminal] {
        char buffer[4096];
        ssize_t n = 0;
        while ((n = ::read(master, buffer, sizeof buffer)) > 0)
            terminal->append(buffer, n);
    };
    QSocketNotifier notifier(master, QSocketNotifier::Read);
    QObject::connect(&notifier, &QSocketNotifier::activated, drain);
    QProcess p;
    p.setChildProcessModifier([slave] { ::dup2(slave, STDERR_FILENO); });
    QEventLoop loop;
    QObject::connect(&p, &QProcess::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    p.start(mbscopePath(), arguments);
    if (p.waitForStarted(30000)) {
        p.closeWriteChannel();
        loop.exec();
    }
    result.finished = p.state() == QProcess::NotRunning && p.exitStatus() == QProcess::NormalExit;
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished(5000);
    }
    result.exitCode = result.finished ? p.exitCode() : -1;
    result.out = p.readAllStandardOutput();
    ::close(slave);
    drain();
    ::close(master);
    result.err = *terminal;
    return result;
}

// The progress lines a terminal was shown: "<what> done/total  ...  about X left  (Ctrl-C stops)",
// each drawn over the last (carriage return, erase to the end of the line).
struct ProgressShown {
    int done = 0;
    int total = 0;
    QString detail; // between the counts and the times
    QString left;
};

QList<ProgressShown> progressShown(const QByteArray &terminal, const QString &what)
{
    const QRegularExpression line(QStringLiteral("^%1 (\\d+)/(\\d+)  (?:(.*)  )?[^ ]+ m?s, about (.+) left  \\(Ctrl-C stops\\)$").arg(what));
    QList<ProgressShown> out;
    for (const QByteArray &drawn : terminal.split('\r')) {
        const QString text = QString::fromUtf8(drawn).remove(QStringLiteral("\x1b[K")).trimmed();
        const QRegularExpressionMatch m = line.match(text);
        if (m.hasMatch())
            out.append({m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3), m.captured(4)});
    }
    return out;
}

} // namespace

class TestCliScan : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void unitsBehindAGateway();
    void tableGroupsRunsAndJsonHasEveryId();
    void echoIsNamed_data();
    void echoIsNamed();
    void pymodbusSeveralUnits();
    void watchesWritten();
    void ctrlCStopsWithWhatWasFound();
    void maxTimeBoundsTheScan();
    void badInput_data();
    void badInput();
    void mapDraftServedAgainAnswersTheSame();
    void mapDraftRecordsTheLargestRead();
    void lineSettingsFound();
    void timingLimitsFound();
    void timingTellsDropOldestFromRefuse();
    void timingLimitsMergedIntoProfile();
    void timingFindsAHangUp();
    void timingProgressOnATerminal();
    void timingBoundedAndStopped();
    void allIdsSaysWhatItAsked();
    void mapOfAnAbsentUnit();
    void unitsIntoAProfile_data();
    void unitsIntoAProfile();
    void noRoomForARequestEnds();

private:
    QTemporaryDir m_dir;
    Background m_gateway;
};

void TestCliScan::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QFile profile(m_dir.filePath(QStringLiteral("gateway.json")));
    QVERIFY(profile.open(QIODevice::WriteOnly));
    profile.write(kGatewayProfile);
    profile.close();
    QString error;
    QVERIFY2(m_gateway.start({QStringLiteral("simulate"), QStringLiteral("--profile"), profile.fileName(), QStringLiteral("--listen"),
                              QStringLiteral("rtu-tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                             &error),
             qPrintable(error));
}

void TestCliScan::unitsBehindAGateway()
{
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--units"),
                                    QStringLiteral("1-9"), QStringLiteral("--timeout"), QStringLiteral("300ms"), QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QJsonObject scan = r.json();
    QCOMPARE(scan.value(QStringLiteral("asked")).toInt(), 9);
    QCOMPARE(scan.value(QStringLiteral("found")).toInt(), 2); // 1 answers, 6 refuses 03 with 01
    QCOMPARE(scan.value(QStringLiteral("end")).toString(), QStringLiteral("completed"));
    const QMap<int, QJsonObject> units = unitsByID(scan);
    const auto result = [&](int unit) { return units.value(unit).value(QStringLiteral("result")).toString(); };
    QCOMPARE(result(1), QStringLiteral("answers"));
    QCOMPARE(units.value(1).value(QStringLiteral("response")).toString().left(11), QStringLiteral("01 03 02 00"));
    QCOMPARE(result(2), QStringLiteral("gateway_path_unavailable"));
    QCOMPARE(units.value(2).value(QStringLiteral("exception_code")).toInt(), 0x0A);
    QCOMPARE(result(3), QStringLiteral("wrong_unit"));
    QCOMPARE(units.value(3).value(QStringLiteral("answered_unit")).toInt(), 7);
    QCOMPARE(result(4), QStringLiteral("silent"));
    QCOMPARE(result(5), QStringLiteral("garbage"));
    QVERIFY2(units.value(5).value(QStringLiteral("problem")).toString().contains(QStringLiteral("CRC")), r.out.constData());
    QCOMPARE(result(6), QStringLiteral("exception"));
    QCOMPARE(units.value(6).value(QStringLiteral("exception_code")).toInt(), 0x01);
    for (int unit = 7; unit <= 9; ++unit) {
        QCOMPARE(result(unit), QStringLiteral("gateway_target_failed"));
        QCOMPARE(units.value(unit).value(QStringLiteral("exception_code")).toInt(), 0x0B);
    }
}

void TestCliScan::tableGroupsRunsAndJsonHasEveryId()
{
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--units"),
                                    QStringLiteral("1-20"), QStringLiteral("--gap"), QStringLiteral("0")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QString text = r.outText();
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("\\n1 +answers"))), r.out.constData());
    QVERIFY2(text.contains(QRegularExpression(QStringLiteral("\\n7-20 +gateway_target_failed +- +\\(14 ids\\) exception 0B"))), r.out.constData());
    QVERIFY2(text.contains(QStringLiteral("20 of 20 ids asked")), r.out.constData());
    QVERIFY2(text.contains(QStringLiteral("found 2 device(s); completed")), r.out.constData());
    const CliResult all = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--units"),
                                      QStringLiteral("7-9"), QStringLiteral("--all")});
    QVERIFY2(all.outText().contains(QRegularExpression(QStringLiteral("\\n8 +gateway_target_failed"))), all.out.constData());
    QCOMPARE(all.exitCode, 1); // nothing found
}

void TestCliScan::echoIsNamed_data()
{
    QTest::addColumn<QString>("mode");
    QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp");
    QTest::newRow("tcp") << QStringLiteral("tcp");
}

void TestCliScan::echoIsNamed()
{
    QFETCH(QString, mode);
    QString why;
    if (!mbscope::testpeers::pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    PeerProcess peer;
    QVERIFY2(peer.start(mbscope::testpeers::systemPython(),
                        {mbscope::testpeers::peersDir() + QStringLiteral("/fault_server.py"), mode, QStringLiteral("--fault"), QStringLiteral("echo")}),
             qPrintable(peer.error()));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), QStringLiteral("%1://%2").arg(mode, peer.where()),
                                    QStringLiteral("--units"), QStringLiteral("1-3"), QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 1, r.describe()); // an echo is nobody
    const QMap<int, QJsonObject> units = unitsByID(r.json());
    for (int unit = 1; unit <= 3; ++unit) {
        QCOMPARE(units.value(unit).value(QStringLiteral("result")).toString(), QStringLiteral("echo"));
        QCOMPARE(units.value(unit).value(QStringLiteral("response")), units.value(unit).value(QStringLiteral("request")));
    }
}

void TestCliScan::pymodbusSeveralUnits()
{
    QString why;
    if (!mbscope::testpeers::pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    PeerProcess peer;
    QVERIFY2(peer.start(mbscope::testpeers::systemPython(), {mbscope::testpeers::peersDir() + QStringLiteral("/pymodbus_server.py"),
                                                             QStringLiteral("tcp"), QStringLiteral("--unit"), QStringLiteral("3,7,12")}),
             qPrintable(peer.error()));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), QStringLiteral("tcp://") + peer.where(),
                                    QStringLiteral("--units"), QStringLiteral("1-15"), QStringLiteral("--timeout"), QStringLiteral("150ms"),
                                    QStringLiteral("--gap"), QStringLiteral("0"), QStringLiteral("--function"), QStringLiteral("4"),
                                    QStringLiteral("--address"), QStringLiteral("10"), QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QMap<int, QJsonObject> units = unitsByID(r.json());
    QCOMPARE(units.size(), 15);
    for (int unit = 1; unit <= 15; ++unit) {
        const bool present = unit == 3 || unit == 7 || unit == 12;
        QCOMPARE(units.value(unit).value(QStringLiteral("result")).toString(),
                 present ? QStringLiteral("answers") : QStringLiteral("silent"));
    }
    // 04 at 10: input register 40000 + 2 x 10 (peer_datamap.h) = 0x9C54
    QVERIFY(units.value(7).value(QStringLiteral("response")).toString().endsWith(QStringLiteral("04 02 9C 54")));
}

void TestCliScan::watchesWritten()
{
    const QString path = m_dir.filePath(QStringLiteral("watches.json"));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--units"),
                                    QStringLiteral("1-2"), QStringLiteral("--address"), QStringLiteral("0"), QStringLiteral("--quantity"),
                                    QStringLiteral("2"), QStringLiteral("--watches"), path});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonArray watches = QJsonDocument::fromJson(file.readAll()).array();
    QCOMPARE(watches.size(), 1); // unit 2 answers 0A: no watch
    const QJsonObject w = watches.first().toObject();
    QCOMPARE(w.value(QStringLiteral("unit")).toInt(), 1);
    QCOMPARE(w.value(QStringLiteral("function")).toInt(), 3);
    QCOMPARE(w.value(QStringLiteral("quantity")).toInt(), 2);
    QCOMPARE(w.value(QStringLiteral("target")).toString(), m_gateway.url());
}

void TestCliScan::ctrlCStopsWithWhatWasFound()
{
    QProcess scan;
    // Ids 4-247: unit 4 is dropped, then 0B answers come fast; the timeout keeps 4 slow, the gap the rest.
    scan.start(mbscopePath(), {QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--gap"),
                               QStringLiteral("100ms"), QStringLiteral("--json")});
    QVERIFY(scan.waitForStarted());
    QTest::qWait(1500);
    ::kill(pid_t(scan.processId()), SIGINT);
    QVERIFY(scan.waitForFinished(10000));
    const QJsonObject o = QJsonDocument::fromJson(scan.readAllStandardOutput()).object();
    QCOMPARE(o.value(QStringLiteral("end")).toString(), QStringLiteral("stopped"));
    const int asked = o.value(QStringLiteral("asked")).toInt();
    QVERIFY2(asked >= 1 && asked < 247, qPrintable(QString::number(asked)));
    QCOMPARE(o.value(QStringLiteral("units")).toArray().size(), asked);
    QCOMPARE(o.value(QStringLiteral("found")).toInt(), 2);
}

void TestCliScan::maxTimeBoundsTheScan()
{
    QString why;
    if (!mbscope::testpeers::pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    PeerProcess peer; // unit 1 only: the others are silent
    QVERIFY2(peer.start(mbscope::testpeers::systemPython(), {mbscope::testpeers::peersDir() + QStringLiteral("/pymodbus_server.py"), QStringLiteral("tcp")}),
             qPrintable(peer.error()));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), QStringLiteral("tcp://") + peer.where(),
                                    QStringLiteral("--timeout"), QStringLiteral("100ms"), QStringLiteral("--max-time"), QStringLiteral("700ms"),
                                    QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("end")).toString(), QStringLiteral("time_limit"));
    QVERIFY(o.value(QStringLiteral("asked")).toInt() < 247);
    QVERIFY(o.value(QStringLiteral("asked")).toInt() >= 1);
}

void TestCliScan::badInput_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("no target") << QStringList{} << QStringLiteral("no --target given");
    QTest::newRow("unit 0 on rtu") << QStringList{QStringLiteral("--units"), QStringLiteral("0-5")}
                                   << QStringLiteral("unit 0 is the broadcast address on rtu framing: nobody answers it (its "
                                                     "unit ids are 1-247: start at 1)");
    QTest::newRow("all ids on rtu") << QStringList{QStringLiteral("--all-ids")}
                                    << QStringLiteral("--all-ids asks 0-255, which only an MBAP target (tcp://, tls://, udp://) "
                                                      "has; on rtu framing the unit ids are 1-247 (0 is the broadcast, which no "
                                                      "unit answers; 248-255 are reserved): leave --all-ids out to ask 1-247");
    QTest::newRow("reserved ids on rtu") << QStringList{QStringLiteral("--units"), QStringLiteral("240-250")}
                                         << QStringLiteral("unit ids 248-255 are reserved on rtu framing (Serial Line V1.02, 2.2; "
                                                           "its unit ids are 1-247): end at 247");
    QTest::newRow("ids reversed") << QStringList{QStringLiteral("--units"), QStringLiteral("9-2")}
                                  << QStringLiteral("--units '9-2': the first is above the last");
    QTest::newRow("id 300") << QStringList{QStringLiteral("--units"), QStringLiteral("1-300")}
                            << QStringLiteral("--units 300 is out of range: expected 0 to 255");
    QTest::newRow("a write") << QStringList{QStringLiteral("--function"), QStringLiteral("6")}
                             << QStringLiteral("--function 6 is out of range: expected 1 to 4");
    QTest::newRow("map option alone") << QStringList{QStringLiteral("--step"), QStringLiteral("8")}
                                      << QStringLiteral("--step belongs to --map UNIT");
    QTest::newRow("units profile missing") << QStringList{QStringLiteral("--profile-out"), QStringLiteral("x.json")}
                                           << QStringLiteral("--profile-out x.json: cannot be read (No such file or directory): the "
                                                             "units found are merged into an existing profile");
    {
        // An empty object was merged into and written without a name, which simulate then refused.
        QFile empty(m_dir.filePath(QStringLiteral("empty-profile.json")));
        QVERIFY(empty.open(QIODevice::WriteOnly) && empty.write("{}") == 2);
    }
    QTest::newRow("units profile not a profile")
        << QStringList{QStringLiteral("--profile-out"), m_dir.filePath(QStringLiteral("empty-profile.json"))}
        << QStringLiteral("empty-profile.json: not a profile the simulator loads, so nothing is merged into it:\n")
               + m_dir.filePath(QStringLiteral("empty-profile.json")) + QStringLiteral(": 'name' is missing");
    QTest::newRow("timing profile not a profile")
        << QStringList{QStringLiteral("--timing"), QStringLiteral("1"), QStringLiteral("--profile-out"),
                       m_dir.filePath(QStringLiteral("empty-profile.json"))}
        << QStringLiteral("'units' is missing");
    QTest::newRow("timing profile missing")
        << QStringList{QStringLiteral("--timing"), QStringLiteral("1"), QStringLiteral("--profile-out"), QStringLiteral("no-such-profile.json")}
        << QStringLiteral("--profile-out no-such-profile.json: cannot be read (No such file or directory): with --timing the limits are "
                          "merged into an existing profile");
    QTest::newRow("bad gap") << QStringList{QStringLiteral("--gap"), QStringLiteral("fast")} << QStringLiteral("--gap: ");
}

void TestCliScan::badInput()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QStringList args{QStringLiteral("scan")};
    if (!arguments.isEmpty() || QTest::currentDataTag() != QLatin1String("no target"))
        args << QStringLiteral("--target") << m_gateway.url();
    const CliResult r = runMbscope(args + arguments);
    QVERIFY2(r.finished && r.exitCode == 2, r.describe());
    QVERIFY2(r.errText().contains(message), r.describe());
    QVERIFY(r.out.isEmpty());
}

void TestCliScan::mapDraftServedAgainAnswersTheSame()
{
    Background original;
    QString error;
    QVERIFY2(original.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                             QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                            &error),
             qPrintable(error));
    const QString draft = m_dir.filePath(QStringLiteral("conformance-draft.json"));
    const QStringList mapArgs{QStringLiteral("--map"), QStringLiteral("1"), QStringLiteral("--addresses"), QStringLiteral("0-599"), QStringLiteral("--json")};
    const CliResult scanned = runMbscope(QStringList{QStringLiteral("scan"), QStringLiteral("--target"), original.url()} + mapArgs
                                         + QStringList{QStringLiteral("--profile-out"), draft});
    QVERIFY2(scanned.finished && scanned.exitCode == 0, scanned.describe());
    const QJsonObject first = scanned.json();
    const QMap<QString, QJsonArray> blocks = blocksOf(first);
    // conformance (docs/profiles.md): tables 0-99, typed holding registers from 200, a read-only block 300-309, live inputs 500-501
    QCOMPARE(blocks.keys(), (QStringList{QStringLiteral("1 0-99"), QStringLiteral("2 0-99"), QStringLiteral("3 0-99"), QStringLiteral("3 200-217"),
                                         QStringLiteral("3 300-309"), QStringLiteral("4 0-99"), QStringLiteral("4 500-501")}));
    QCOMPARE(blocks.value(QStringLiteral("3 0-99")).at(5).toInt(), 1000 + 3 * 5);
    for (const QJsonValue &t : first.value(QStringLiteral("tables")).toArray()) {
        const int function = t.toObject().value(QStringLiteral("function")).toInt();
        QCOMPARE(t.toObject().value(QStringLiteral("max_quantity")).toInt(), function <= 2 ? 2000 : 125);
        QVERIFY2(t.toObject().value(QStringLiteral("requests")).toInt() < 700, "fewer requests than addresses searched");
    }
    bool answers2B = false;
    for (const QJsonValue &f : first.value(QStringLiteral("functions")).toArray()) {
        const QJsonObject o = f.toObject();
        if (o.value(QStringLiteral("function")).toInt() == 0x2B)
            answers2B = o.value(QStringLiteral("answer")).toString() == QLatin1String("answers");
        QVERIFY(o.value(QStringLiteral("function")).toInt() != 0x15 || o.value(QStringLiteral("answer")).toString() == QLatin1String("not_probed"));
    }
    QVERIFY(answers2B);
    QCOMPARE(first.value(QStringLiteral("exception_status")).toInt(), 0x6D);
    // Issue 28, "whether a read spanning a gap fails": measured (02 between blocks) and stored.
    for (const QJsonValue &t : first.value(QStringLiteral("tables")).toArray())
        QCOMPARE(t.toObject().value(QStringLiteral("gap_reads_refused")).toBool(), t.toObject().value(QStringLiteral("function")).toInt() >= 3);
    {
        QFile saved(draft);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        const QJsonObject unit = QJsonDocument::fromJson(saved.readAll()).object().value(QStringLiteral("units")).toArray().at(0).toObject();
        QCOMPARE(unit.value(QStringLiteral("gapReads")).toString(), QStringLiteral("exception"));
    }

    Background clone;
    QVERIFY2(clone.start({QStringLiteral("simulate"), QStringLiteral("--profile"), draft, QStringLiteral("--listen"),
                          QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                         &error),
             qPrintable(error));
    const CliResult again = runMbscope(QStringList{QStringLiteral("scan"), QStringLiteral("--target"), clone.url()} + mapArgs);
    QVERIFY2(again.finished && again.exitCode == 0, again.describe());
    const QMap<QString, QJsonArray> cloned = blocksOf(again.json());
    QCOMPARE(cloned.keys(), blocks.keys());
    for (auto it = blocks.cbegin(); it != blocks.cend(); ++it) {
        if (it.key() == QLatin1String("4 500-501"))
            continue; // live in the original (seconds, a sine): the draft keeps the values read
        QCOMPARE(cloned.value(it.key()), it.value());
    }
    QCOMPARE(again.json().value(QStringLiteral("exception_status")).toInt(), 0x6D);
}

// A device that takes 16 registers a read at most: the map scan finds it, the draft records it
// as the profile's limits (before, the draft dropped it and a clone took 125), the clone served
// from the draft refuses 17 as the device does, and export-map's blocks honour it.
void TestCliScan::mapDraftRecordsTheLargestRead()
{
    QFile profile(m_dir.filePath(QStringLiteral("narrow.json")));
    QVERIFY(profile.open(QIODevice::WriteOnly));
    profile.write(R"({"name": "narrow", "limits": {"maxQuantity": {"0x03": 16}},
                      "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 40}]}}]})");
    profile.close();
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), profile.fileName(), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const QString draft = m_dir.filePath(QStringLiteral("narrow-draft.json"));
    const CliResult scanned = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--map"),
                                          QStringLiteral("1"), QStringLiteral("--addresses"), QStringLiteral("0-99"), QStringLiteral("--tables"),
                                          QStringLiteral("3"), QStringLiteral("--profile-out"), draft});
    QVERIFY2(scanned.finished && scanned.exitCode == 0, scanned.describe());
    QFile file(draft);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject written = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(written.value(QStringLiteral("limits")).toObject().value(QStringLiteral("maxQuantity")).toObject().value(QStringLiteral("0x03")).toInt(), 16);

    Background clone;
    QVERIFY2(clone.start({QStringLiteral("simulate"), QStringLiteral("--profile"), draft, QStringLiteral("--listen"),
                          QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                         &error),
             qPrintable(error));
    const CliResult refused = runMbscope({QStringLiteral("read"), QStringLiteral("--target"), clone.url(), QStringLiteral("--address"),
                                          QStringLiteral("0"), QStringLiteral("--quantity"), QStringLiteral("17")});
    QVERIFY2(refused.finished && (refused.out + refused.err).toLower().contains("illegal data value"), refused.describe());
    // export-map reads the 40 registers in blocks of 16 at most.
    const CliResult exported = runMbscope({QStringLiteral("export-map"), draft, QStringLiteral("--to"), QStringLiteral("csv"),
                                           QStringLiteral("--verify"), clone.url()});
    QVERIFY2(exported.finished && exported.exitCode == 0, exported.describe());
    QVERIFY2(exported.err.contains("verified: 40 values"), exported.describe());
}

void TestCliScan::lineSettingsFound()
{
    // The simulator at 19200 8E1 behind tests/peers/line_harness.py, which relays only when the
    // client's pty is set to the device's baud rate and stop bits (a pty carries no parity bit).
    QString why;
    if (!mbscope::testpeers::pymodbusAvailable(&why))
        QSKIP(qPrintable(why));
    PeerProcess line;
    QVERIFY2(line.start(mbscope::testpeers::systemPython(), {mbscope::testpeers::peersDir() + QStringLiteral("/line_harness.py"),
                                                             QStringLiteral("--baud"), QStringLiteral("19200"), QStringLiteral("--stop"), QStringLiteral("1")}),
             qPrintable(line.error()));
    const QString client = line.where().section(QLatin1Char(' '), 0, 0).section(QLatin1Char('='), 1);
    const QString device = line.where().section(QLatin1Char(' '), 1, 1).section(QLatin1Char('='), 1);
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("arduino-rs485"), QStringLiteral("--listen"),
                        QStringLiteral("rtu://%1?baud=19200&parity=E&stop=1").arg(device), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), QStringLiteral("rtu://") + client, QStringLiteral("--line"),
                                    QStringLiteral("--bauds"), QStringLiteral("9600,19200,38400"), QStringLiteral("--units"), QStringLiteral("1"),
                                    QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("tried")).toArray().size(), 3 * 3 * 2);
    const QJsonArray working = o.value(QStringLiteral("working")).toArray();
    QStringList settings;
    for (const QJsonValue &w : working)
        settings.append(w.toObject().value(QStringLiteral("setting")).toString());
    QCOMPARE(settings, (QStringList{QStringLiteral("19200 8E1"), QStringLiteral("19200 8N1"), QStringLiteral("19200 8O1")}));
    QByteArray terminal;
    const CliResult text = runOnTerminal({QStringLiteral("scan"), QStringLiteral("--target"), QStringLiteral("rtu://") + client, QStringLiteral("--line"),
                                          QStringLiteral("--bauds"), QStringLiteral("9600,19200"), QStringLiteral("--parities"), QStringLiteral("E"),
                                          QStringLiteral("--stop-bits"), QStringLiteral("2,1"), QStringLiteral("--first")},
                                         &terminal);
    QVERIFY2(text.finished && text.exitCode == 0, text.describe());
    QVERIFY2(text.outText().contains(QStringLiteral("answered: 19200 8E1 (unit 1)\n")), text.out.constData());
    QVERIFY2(text.outText().contains(QStringLiteral("\n9600 8E2        1          silent")), text.out.constData());
    QVERIFY2(text.outText().contains(QStringLiteral("4 trials")), text.out.constData());
    // On the terminal, the trials of the plan (4 settings with unit 1, then 2-247 on each in case
    // nothing answered): all of it done once 19200 8E1 answered (--first), nothing left.
    const QList<ProgressShown> shown = progressShown(terminal, QStringLiteral("trials"));
    QVERIFY2(shown.size() >= 4, terminal.constData());
    QCOMPARE(shown.first().done, 0);
    QVERIFY2(shown.first().left != QLatin1String("0 ms"), terminal.constData());
    int done = 0;
    for (const ProgressShown &p : shown) {
        QCOMPARE(p.total, 4 * 247);
        QVERIFY2(p.done >= done, terminal.constData());
        done = p.done;
    }
    QVERIFY2(terminal.contains("9600 8E2 unit 1 silent"), terminal.constData());
    QCOMPARE(shown.last().done, 4 * 247);
    QCOMPARE(shown.last().left, QStringLiteral("0 ms"));
}

void TestCliScan::timingLimitsFound()
{
    // The simulator's device limits (docs/profiles.md, Device limits): 50 ms between requests
    // (busy, 06, when sooner), two clients, 16 registers a read, 500 ms of warm-up per connection.
    QFile profile(m_dir.filePath(QStringLiteral("slow.json")));
    QVERIFY(profile.open(QIODevice::WriteOnly));
    profile.write(R"({"name": "slow", "limits": {"minGapMs": 50, "tooSoon": "busy", "maxClients": 2,
                      "maxQuantity": {"0x03": 16}, "warmUpMs": 500},
                      "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 100}]}}]})");
    profile.close();
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), profile.fileName(), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--timing"), QStringLiteral("1"),
                                    QStringLiteral("--clients"), QStringLiteral("4"), QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("warmup_failures")).toInt(), 1);
    QVERIFY2(o.value(QStringLiteral("first_answer_ms")).toDouble() >= 500, r.out.constData());
    QCOMPARE(o.value(QStringLiteral("shortest_clean_gap_ms")).toInt(), 50);
    QCOMPARE(o.value(QStringLiteral("largest_quantity")).toInt(), 16);
    QCOMPARE(o.value(QStringLiteral("clients_served")).toInt(), 2);
    QCOMPARE(o.value(QStringLiteral("clients_tried")).toInt(), 3);
    QVERIFY(o.value(QStringLiteral("pipeline_ok")).toInt() < o.value(QStringLiteral("pipeline_sent")).toInt());
    QCOMPARE(o.value(QStringLiteral("recommended")).toObject().value(QStringLiteral("gap_ms")).toInt(), 100);
    QCOMPARE(o.value(QStringLiteral("recommended")).toObject().value(QStringLiteral("telegraf_pause_between_requests")).toString(),
             QStringLiteral("100ms"));
}

// The timing scan's --profile-out merges what it measured into an existing profile's limits (before,
// it wrote them nowhere): the gap, the warm-up, the clients and the largest read of the simulator's
// device; the profile's other limits are kept, and the simulator serves the result.
void TestCliScan::timingLimitsMergedIntoProfile()
{
    QFile device(m_dir.filePath(QStringLiteral("limited.json")));
    QVERIFY(device.open(QIODevice::WriteOnly));
    device.write(R"({"name": "limited", "limits": {"minGapMs": 50, "maxClients": 2, "extraClients": "dropOldest",
                      "maxQuantity": {"0x03": 16}, "warmUpMs": 300},
                      "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 100}]}}]})");
    device.close();
    const QString target = m_dir.filePath(QStringLiteral("limited-draft.json"));
    QFile draft(target);
    QVERIFY(draft.open(QIODevice::WriteOnly));
    draft.write(R"({"name": "limited-draft", "limits": {"maxQuantity": {"0x04": 8}},
                    "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 100}]}}]})");
    draft.close();
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), device.fileName(), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--timing"), QStringLiteral("1"),
                                    QStringLiteral("--clients"), QStringLiteral("4"), QStringLiteral("--profile-out"), target});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    QVERIFY2(r.errText().contains(QStringLiteral("mbscope scan: limits measured: extraClients dropOldest, maxClients 2, maxQuantity 0x03 16, "
                                                 "minGapMs 50, warmUpMs ")),
             r.describe());
    QVERIFY2(r.errText().contains(QStringLiteral("mbscope scan: profile limits written to ") + target), r.describe());
    QVERIFY(draft.open(QIODevice::ReadOnly));
    const QJsonObject written = QJsonDocument::fromJson(draft.readAll()).object();
    draft.close();
    QCOMPARE(written.value(QStringLiteral("name")).toString(), QStringLiteral("limited-draft"));
    const QJsonObject limits = written.value(QStringLiteral("limits")).toObject();
    QCOMPARE(limits.value(QStringLiteral("minGapMs")).toInt(), 50);
    // The device counts its 300 ms from when its event loop took the connection in and read the
    // request, which on a busy machine can be milliseconds after the client saw it open and wrote
    // it (292 ms was recorded once under two parallel tests): a tenth of slack, the margin
    // DeviceLimits::clientWarmUp adds when the profile is used.
    QVERIFY2(limits.value(QStringLiteral("warmUpMs")).toDouble() >= 270, qPrintable(QJsonDocument(limits).toJson()));
    QCOMPARE(limits.value(QStringLiteral("maxClients")).toInt(), 2);
    QCOMPARE(limits.value(QStringLiteral("extraClients")).toString(), QStringLiteral("dropOldest"));
    const QJsonObject quantities = limits.value(QStringLiteral("maxQuantity")).toObject();
    QCOMPARE(quantities.value(QStringLiteral("0x03")).toInt(), 16);
    QCOMPARE(quantities.value(QStringLiteral("0x04")).toInt(), 8); // kept
    QCOMPARE(written.value(QStringLiteral("units")).toArray().size(), 1);

    // The written profile is one the simulator serves.
    Background clone;
    QVERIFY2(clone.start({QStringLiteral("simulate"), QStringLiteral("--profile"), target, QStringLiteral("--listen"),
                          QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                         &error),
             qPrintable(error));

    // Measured against a device without those limits, the ones it shows it lacks go (0 ms clean,
    // the first request answered, 125 registers read); the clients, all served, prove no more than
    // two and stay, as does the other function's maxQuantity (before, a profile kept limits its
    // device had been measured not to have).
    QFile plainFile(m_dir.filePath(QStringLiteral("plain.json")));
    QVERIFY(plainFile.open(QIODevice::WriteOnly));
    plainFile.write(R"({"name": "plain", "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 200}]}}]})");
    plainFile.close();
    Background plain;
    QVERIFY2(plain.start({QStringLiteral("simulate"), QStringLiteral("--profile"), plainFile.fileName(), QStringLiteral("--listen"),
                          QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                         &error),
             qPrintable(error));
    const CliResult again = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), plain.url(), QStringLiteral("--timing"),
                                        QStringLiteral("1"), QStringLiteral("--clients"), QStringLiteral("2"), QStringLiteral("--profile-out"),
                                        target});
    QVERIFY2(again.finished && again.exitCode == 0, again.describe());
    QVERIFY2(again.errText().contains(QStringLiteral("mbscope scan: limits measured: no limit seen: closesAfterAnswer, maxQuantity 0x03, minGapMs, "
                                                     "warmUpMs\n")),
             again.describe());
    QVERIFY(draft.open(QIODevice::ReadOnly));
    const QJsonObject after = QJsonDocument::fromJson(draft.readAll()).object().value(QStringLiteral("limits")).toObject();
    draft.close();
    QCOMPARE(QStringList(after.keys()), (QStringList{QStringLiteral("extraClients"), QStringLiteral("maxClients"), QStringLiteral("maxQuantity")}));
    QCOMPARE(after.value(QStringLiteral("maxQuantity")).toObject(), (QJsonObject{{QStringLiteral("0x04"), 8}}));
}

// A device that hangs up after each answer (limits.closesAfterAnswer): the timing scan says so,
// records it, and does not take the clients it could not keep for a client limit (before, the
// second client's recheck found the first reconnected and reported maxClients 1 dropOldest).
void TestCliScan::timingFindsAHangUp()
{
    const QString device = m_dir.filePath(QStringLiteral("hangs-up.json"));
    QVERIFY(writeFile(device, R"({"name": "hangs-up", "limits": {"closesAfterAnswer": true},
                                  "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 100}]}}]})"));
    const QString target = m_dir.filePath(QStringLiteral("hangs-up-draft.json"));
    QVERIFY(writeFile(target, R"({"name": "hangs-up-draft", "limits": {"maxQuantity": {"3": 16}},
                                  "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 100}]}}]})"));
    QFile draft(target);
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), device, QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--timing"), QStringLiteral("1"),
                                    QStringLiteral("--clients"), QStringLiteral("3"), QStringLiteral("--json"), QStringLiteral("--profile-out"), target});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("closes_after_answer")), QJsonValue(true));
    QCOMPARE(o.value(QStringLiteral("clients_tried")).toInt(), 0);
    QCOMPARE(o.value(QStringLiteral("pipeline_sent")).toInt(), 0);
    // Never tried is null, not 0 (a new user's try read "clients_served": 0 as none served).
    QVERIFY(o.value(QStringLiteral("clients_served")).isNull());
    QVERIFY(o.value(QStringLiteral("pipeline_ok")).isNull());
    QVERIFY2(r.errText().contains(QStringLiteral("mbscope scan: limits measured: closesAfterAnswer")), r.describe());
    QVERIFY(draft.open(QIODevice::ReadOnly));
    const QJsonObject limits = QJsonDocument::fromJson(draft.readAll()).object().value(QStringLiteral("limits")).toObject();
    draft.close();
    QCOMPARE(limits.value(QStringLiteral("closesAfterAnswer")), QJsonValue(true));
    QVERIFY2(!limits.contains(QStringLiteral("maxClients")), qPrintable(QJsonDocument(limits).toJson()));
    // Its map is 100 registers: 101 from address 0 gets 02, which says where the map ends, not how
    // much a read may ask (before, maxQuantity 0x03 100 was written). The draft's 16 is disproved
    // by the 100 answered and removed (it was kept, unsaid).
    QCOMPARE(o.value(QStringLiteral("largest_quantity")).toInt(), 100);
    QCOMPARE(o.value(QStringLiteral("largest_ends_map")), QJsonValue(true));
    QVERIFY2(!limits.contains(QStringLiteral("maxQuantity")), qPrintable(QJsonDocument(limits).toJson()));
    QVERIFY2(r.errText().contains(QStringLiteral("; maxQuantity 0x03 16 removed (100 were answered at once)\n")), r.describe());
}

// Two clients at most, the third refused or served by knocking the first off: the timing scan
// tells the two apart (before, a dropOldest device showed every client tried as served).
void TestCliScan::timingTellsDropOldestFromRefuse()
{
    for (const char *extra : {"refuse", "dropOldest"}) {
        QFile profile(m_dir.filePath(QStringLiteral("clients-%1.json").arg(QLatin1String(extra))));
        QVERIFY(profile.open(QIODevice::WriteOnly));
        profile.write(QByteArray(R"({"name": "clients", "limits": {"maxClients": 2, "extraClients": ")") + extra
                      + R"("}, "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 100}]}}]})");
        profile.close();
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), profile.fileName(), QStringLiteral("--listen"),
                            QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                           &error),
                 qPrintable(error));
        const QStringList args{QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--timing"),
                               QStringLiteral("1"), QStringLiteral("--clients"), QStringLiteral("5")};
        const CliResult r = runMbscope(args + QStringList{QStringLiteral("--json")});
        QVERIFY2(r.finished && r.exitCode == 0, r.describe());
        const QJsonObject o = r.json();
        QCOMPARE(o.value(QStringLiteral("clients_served")).toInt(), 2);
        QCOMPARE(o.value(QStringLiteral("clients_tried")).toInt(), 3);
        const bool drops = QByteArray(extra) == "dropOldest";
        QCOMPARE(o.value(QStringLiteral("clients_extra")).toString(), drops ? QStringLiteral("drop_oldest") : QStringLiteral("refuse"));
        QCOMPARE(o.value(QStringLiteral("closes_after_answer")), QJsonValue(false));
        const CliResult text = runMbscope(args);
        QVERIFY2(text.finished && text.exitCode == 0, text.describe());
        QVERIFY2(text.outText().contains(drops ? QStringLiteral("TCP clients served at once      2 (client 3 was served by closing "
                                                                "client 1: the device knocks its oldest client off, as "
                                                                "extraClients dropOldest)\n")
                                               : QStringLiteral("TCP clients served at once      2 (client 3 was not served)\n")),
                 text.out.constData());
        QVERIFY2(text.outText().contains(QStringLiteral("connection after each answer    kept open\n")), text.out.constData());
    }
}

// On a terminal the timing scan draws steps done of its plan, what it measures and the time left
// (before, only the name of the part it measured): here over rtu-tcp (no pipelining), 2 clients.
void TestCliScan::timingProgressOnATerminal()
{
    QByteArray terminal;
    const CliResult r = runOnTerminal({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--timing"),
                                       QStringLiteral("1"), QStringLiteral("--clients"), QStringLiteral("2"), QStringLiteral("--timeout"),
                                       QStringLiteral("300ms")},
                                      &terminal);
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    QVERIFY2(r.outText().contains(QStringLiteral("shortest gap without errors     0 ms")), r.out.constData());
    const QList<ProgressShown> shown = progressShown(terminal, QStringLiteral("steps"));
    // The first answer, 9 gaps x 20 requests, the largest read of 03 (125, then at most 7 more
    // by bisection), 2 clients.
    const int total = 1 + 9 * 20 + 8 + 2;
    QVERIFY2(shown.size() > 20, terminal.constData());
    QCOMPARE(shown.first().done, 0);
    QCOMPARE(shown.first().detail, QStringLiteral("first answer after connecting"));
    QVERIFY2(shown.first().left != QLatin1String("0 ms"), terminal.constData());
    int done = 0;
    QSet<QString> details;
    for (const ProgressShown &p : shown) {
        QCOMPARE(p.total, total);
        QVERIFY2(p.done >= done, terminal.constData());
        done = p.done;
        details.insert(p.detail);
    }
    for (const char *part : {"gap 200 ms", "gap 0 ms", "largest read", "clients at once"})
        QVERIFY2(details.contains(QLatin1String(part)), terminal.constData());
    QCOMPARE(shown.last().done, total);
    QCOMPARE(shown.last().left, QStringLiteral("0 ms"));
    // The line is erased before the report: the terminal ends clean.
    QVERIFY(terminal.endsWith("\r\x1b[K"));
}

// --max-time bounds the timing scan (before, it was not applied: only Ctrl-C ended one early), and
// Ctrl-C stops it with what was measured.
void TestCliScan::timingBoundedAndStopped()
{
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--timing"),
                                    QStringLiteral("1"), QStringLiteral("--timeout"), QStringLiteral("200ms"), QStringLiteral("--max-time"),
                                    QStringLiteral("1s"), QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("end")).toString(), QStringLiteral("time_limit"));
    QCOMPARE(o.value(QStringLiteral("stopped")).toBool(), false);
    QVERIFY2(o.value(QStringLiteral("first_answer_ms")).toDouble() >= 0, r.out.constData());
    QVERIFY2(o.value(QStringLiteral("gaps")).toArray().size() <= 1, r.out.constData()); // 200 ms, begun
    QCOMPARE(o.value(QStringLiteral("clients_tried")).toInt(), 0);
    const CliResult text = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--timing"),
                                       QStringLiteral("1"), QStringLiteral("--timeout"), QStringLiteral("200ms"), QStringLiteral("--max-time"),
                                       QStringLiteral("1s")});
    QVERIFY2(text.outText().contains(QStringLiteral("time limit (--max-time 1.0 s) reached: later measurements were not made")),
             text.out.constData());

    QProcess scan;
    scan.start(mbscopePath(), {QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--timing"), QStringLiteral("1"),
                               QStringLiteral("--json")});
    QVERIFY(scan.waitForStarted());
    QTest::qWait(1500); // in the 200 ms gaps (4 s of them)
    ::kill(pid_t(scan.processId()), SIGINT);
    QVERIFY(scan.waitForFinished(10000));
    const QJsonObject stopped = QJsonDocument::fromJson(scan.readAllStandardOutput()).object();
    QCOMPARE(stopped.value(QStringLiteral("end")).toString(), QStringLiteral("stopped"));
    QCOMPARE(stopped.value(QStringLiteral("stopped")).toBool(), true);
    QVERIFY(stopped.value(QStringLiteral("first_answer_ms")).toDouble() >= 0);
    QCOMPARE(stopped.value(QStringLiteral("clients_tried")).toInt(), 0);
}


// Issue 26 item 12: scan --all-ids asked 0-255 and said so as if all were unit addresses: the
// report says 247 of them are (1-247) and 9 are not (0, 248-255), which only an MBAP server or
// gateway may answer; --json lists those.
void TestCliScan::allIdsSaysWhatItAsked()
{
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const QStringList scan{QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--all-ids"), QStringLiteral("--timeout"),
                           QStringLiteral("20ms"), QStringLiteral("--gap"), QStringLiteral("0")};
    const CliResult text = runMbscope(scan);
    QVERIFY2(text.finished, text.describe());
    QVERIFY2(text.outText().contains(QStringLiteral("  units 0-255: 247 unit addresses (1-247) and 9 ids outside them (0, 248-255: ")),
             text.out.constData());
    QVERIFY2(text.outText().contains(QStringLiteral("256 of 256 ids asked")), text.out.constData());
    // The simulator (units 1 and 2) answers 0 and 255 for itself: two devices, not four.
    QVERIFY2(text.outText().contains(QStringLiteral("\nfound 2 device(s) at unit addresses 1-247; ids 0, 255 answered too, outside them ")),
             text.out.constData());
    const CliResult json = runMbscope(scan + QStringList{QStringLiteral("--json")});
    QVERIFY2(json.finished, json.describe());
    QCOMPARE(json.json().value(QStringLiteral("asked")).toInt(), 256);
    QCOMPARE(json.json().value(QStringLiteral("found")).toInt(), 2);
    QCOMPARE(json.json().value(QStringLiteral("answered_outside_unit_addresses")).toArray(), QJsonArray({0, 255}));
    QCOMPARE(json.json().value(QStringLiteral("outside_unit_addresses")).toArray(),
             QJsonArray({QStringLiteral("0"), QStringLiteral("248-255")}));
    // The default range is the unit addresses alone.
    const CliResult some = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--units"), QStringLiteral("1-3"),
                                       QStringLiteral("--timeout"), QStringLiteral("20ms"), QStringLiteral("--json")});
    QCOMPARE(some.json().value(QStringLiteral("outside_unit_addresses")).toArray().size(), 0);
    // Only the server answering for itself is no device found: exit status 1 (it was 0).
    const CliResult server = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--units"),
                                         QStringLiteral("250-255"), QStringLiteral("--timeout"), QStringLiteral("20ms")});
    QVERIFY2(server.finished && server.exitCode == 1, server.describe());
    QVERIFY2(server.outText().contains(QStringLiteral("found 0 device(s) at unit addresses 1-247; id 255 answered too")), server.describe());
}

// A map scan of a unit a gateway has nothing behind (exception 0B to every read) is no map: it
// said "largest quantity 125", listed every optional function as supported and wrote a draft.
void TestCliScan::mapOfAnAbsentUnit()
{
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const QString draft = m_dir.filePath(QStringLiteral("absent-unit.json"));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--map"), QStringLiteral("7"),
                                    QStringLiteral("--addresses"), QStringLiteral("0-20"), QStringLiteral("--tables"), QStringLiteral("3"),
                                    QStringLiteral("--profile-out"), draft, QStringLiteral("--json")});
    QVERIFY2(r.finished && r.exitCode == 1, r.describe());
    QVERIFY2(r.errText().contains(QStringLiteral("mbscope scan: unit 7 is not there: a gateway answered every read with exception 0B\n"
                                                 "mbscope scan: no address answered: no profile draft written\n")),
             r.describe());
    QVERIFY(!QFile::exists(draft));
    const QJsonObject table = r.json().value(QStringLiteral("tables")).toArray().at(0).toObject();
    QCOMPARE(table.value(QStringLiteral("gateway_exception")).toInt(), 0x0B);
    QCOMPARE(table.value(QStringLiteral("supported")).toBool(), false);
    QCOMPARE(table.value(QStringLiteral("max_quantity")).toInt(), 0);
    for (const QJsonValue &f : r.json().value(QStringLiteral("functions")).toArray())
        QVERIFY2(f.toObject().value(QStringLiteral("answer")).toString() == QLatin1String("not_probed"), r.out.constData());
}

void TestCliScan::unitsIntoAProfile_data()
{
    // issue 28: "which unit ids it answers", measured and stored in the profile.
    QTest::addColumn<QString>("device");   // the simulated device's profile, minus its name
    QTest::addColumn<QString>("asked");    // the ids scanned
    QTest::addColumn<QList<int>>("units");  // in the draft after the scan
    QTest::addColumn<QString>("unknownUnit"); // empty: not written
    QTest::newRow("others silent")
        << QStringLiteral(R"("unknownUnit": "silent", "units": [{"id": 2, "tables": {"holding": [{"address": 0, "count": 4}]}},
                             {"id": 5, "tables": {"holding": [{"address": 0, "count": 4}]}}])")
        << QStringLiteral("1-6") << QList<int>{1, 2, 5} << QStringLiteral("silent");
    QTest::newRow("others get 0B")
        << QStringLiteral(R"("unknownUnit": "exception", "units": [{"id": 4, "tables": {"holding": [{"address": 0, "count": 4}]}}])")
        << QStringLiteral("1-6") << QList<int>{1, 4} << QStringLiteral("exception");
    QTest::newRow("every id answers")
        << QStringLiteral(R"("unknownUnit": "first", "units": [{"id": 3, "tables": {"holding": [{"address": 0, "count": 4}]}}])")
        << QStringLiteral("1-20") << QList<int>{1} << QStringLiteral("first");
    // Three real units answer as a device ignoring the unit id would: they are added, nothing concluded.
    QTest::newRow("three units, every id asked")
        << QStringLiteral(R"("unknownUnit": "silent", "units": [{"id": 2, "tables": {"holding": [{"address": 0, "count": 4}]}},
                             {"id": 3, "tables": {"holding": [{"address": 0, "count": 4}]}},
                             {"id": 1, "tables": {"holding": [{"address": 0, "count": 4}]}}])")
        << QStringLiteral("1-3") << QList<int>{1, 2, 3} << QString();
}

void TestCliScan::unitsIntoAProfile()
{
    QFETCH(QString, device);
    QFETCH(QString, asked);
    QFETCH(QList<int>, units);
    QFETCH(QString, unknownUnit);
    const QString devicePath = m_dir.filePath(QStringLiteral("units-device.json"));
    QVERIFY(writeFile(devicePath, QStringLiteral(R"({"name": "units-device", %1})").arg(device).toUtf8()));
    // The draft knows unit 1 already (as a map scan of it would have written it).
    const QString draft = m_dir.filePath(QStringLiteral("units-draft.json"));
    QVERIFY(writeFile(draft, R"({"name": "units-draft", "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 4}]}}]})"));
    Background sim;
    QString error;
    QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), devicePath, QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       &error),
             qPrintable(error));
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), sim.url(), QStringLiteral("--units"),
                                    asked, QStringLiteral("--timeout"), QStringLiteral("200ms"), QStringLiteral("--gap"), QStringLiteral("0"),
                                    QStringLiteral("--profile-out"), draft});
    QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    QVERIFY2(r.errText().contains(QLatin1String("mbscope scan: profile units written to ")), r.describe());
    // A device that ignores the unit id is one device in the report too (it said "found 16 device(s)").
    if (unknownUnit == QLatin1String("first"))
        QVERIFY2(r.outText().contains(QLatin1String("answered: likely one device that ignores the unit id, not ")), r.describe());
    else
        QVERIFY2(r.outText().contains(QLatin1String("\nfound ")), r.describe());
    QFile file(draft);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject profile = QJsonDocument::fromJson(file.readAll()).object();
    QList<int> ids;
    for (const QJsonValue &u : profile.value(QStringLiteral("units")).toArray())
        ids.append(u.toObject().value(QStringLiteral("id")).toInt());
    QCOMPARE(ids, units);
    QCOMPARE(profile.value(QStringLiteral("unknownUnit")).toString(), unknownUnit);
    QCOMPARE(profile.value(QStringLiteral("units")).toArray().first().toObject().value(QStringLiteral("tables")).toObject().size(), 1);
    // What it wrote loads: the simulator serves it.
    const CliResult check = runMbscope({QStringLiteral("simulate"), QStringLiteral("--profile"), draft, QStringLiteral("--listen"),
                                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--duration"), QStringLiteral("100ms"),
                                        QStringLiteral("--quiet")});
    QVERIFY2(check.finished && check.exitCode == 0, check.describe());
}

void TestCliScan::noRoomForARequestEnds()
{
    // A time limit that leaves room for no request: the scan ends at once, saying so (it hung,
    // deaf to Ctrl-C, when its end came before the command waited for it).
    const CliResult r = runMbscope({QStringLiteral("scan"), QStringLiteral("--target"), m_gateway.url(), QStringLiteral("--units"),
                                    QStringLiteral("1-3"), QStringLiteral("--max-time"), QStringLiteral("100ms"), QStringLiteral("--json")},
                                   30000);
    QVERIFY2(r.finished, r.describe());
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.json().value(QStringLiteral("asked")).toInt(), 0);
    QCOMPARE(r.json().value(QStringLiteral("end")).toString(), QStringLiteral("time_limit"));
}

QTEST_GUILESS_MAIN(TestCliScan)
#include "tst_cli_scan.moc"
