// mbscope export-map as users run it (issue 28): what the profile format says of a register map
// served by `mbscope simulate` as declared and read back with `mbscope read` (a table shared by
// two functions, zeros or exception 02 over a gap, a string of N characters, a "not implemented"
// sentinel); the export's usage errors; --verify refusing a value out of range or not finite,
// naming the entry; and Node-RED for real: the exported flow run headless by Node-RED with
// node-red-contrib-modbus (scripts/install-deps.sh --tests installs them in /opt/mbscope-nodered)
// against the simulator serving the same profile, every value of every type and word order equal
// to what `mbscope read` reads from the simulator.

#include "clitest.h"

#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtTest/QTest>

#include <cmath>
#include <csignal>

using namespace mbscope::testcli;

namespace {

// Static values of every type and word order (no generators: what Node-RED reads must equal
// what mbscope reads a moment later).
const char kProfile[] = R"({"name": "map-test",
  "units": [{"id": 3, "gapReads": "zeros", "sharedTables": {"input": "holding", "discrete": "coils"},
    "tables": {
    "holding": [
      {"address": 0, "name": "Voltage", "type": "f32-cdab", "unit": "V", "value": 230.5, "kind": "measurement", "min": 180, "max": 260},
      {"address": 2, "name": "Energy", "type": "u32-cdab", "scale": 0.001, "unit": "kWh", "value": 1234.567, "kind": "counter"},
      {"address": 4, "name": "Status", "kind": "status", "bits": {"0": "run", "3": "fault"}, "value": 9},
      {"address": 5, "name": "Temperature", "type": "i16", "scale": 0.1, "notImplemented": "0x8000", "value": "0x8000"},
      {"address": 6, "name": "Mode", "enum": {"0": "off", "1": "auto"}, "value": 1, "kind": "enumeration"},
      {"address": 7, "name": "Total", "type": "f64-dcba", "value": 42.25},
      {"address": 11, "name": "Flow", "type": "f32-badc", "value": -1.5},
      {"address": 13, "name": "Count", "type": "i32-dcba", "value": -70000},
      {"address": 15, "name": "Big", "type": "u64-cdab", "value": 1099511627776},
      {"address": 19, "name": "Signed big", "type": "i64", "value": -5},
      {"address": 23, "name": "Swapped", "type": "u16-ba", "value": 258},
      {"address": 24, "name": "Pressure", "type": "u16", "scale": 0.01, "offset": 900, "value": 1013.25},
      {"address": 25, "name": "Word", "type": "hex", "value": "0xBEEF"},
      {"address": 26, "name": "Power", "type": "i16", "scaleRegister": 27, "unit": "W", "value": 1250},
      {"address": 27, "name": "Power SF", "type": "i16", "value": 1, "kind": "constant"},
      {"address": 28, "name": "Signed", "type": "i32-badc", "value": -2},
      {"address": 30, "name": "Float big", "type": "f32", "value": 0.125},
      {"address": 32, "name": "Double cdab", "type": "f64-cdab", "value": -1e10},
      {"address": 40, "name": "Serial number", "type": "ascii", "length": 7, "padding": "space", "value": "SN-42", "kind": "constant"},
      {"address": 50, "name": "CT ratio", "kind": "setting", "min": 1, "max": 5000, "value": 100}],
    "coils": [{"address": 0, "name": "Relay", "values": [true]}, {"address": 1, "name": "Lamp", "values": [false]}]}}]})";

QString writeProfile(const QTemporaryDir &dir, const QByteArray &json = kProfile)
{
    const QString path = dir.filePath(QStringLiteral("map-test.json"));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(json) != json.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

QString nodeRedDir()
{
    const QString dir = qEnvironmentVariable("MBSCOPE_NODERED_DIR", QStringLiteral("/opt/mbscope-nodered"));
    return QFileInfo::exists(dir + QStringLiteral("/node_modules/node-red/red.js"))
                   && QFileInfo::exists(dir + QStringLiteral("/node_modules/node-red-contrib-modbus/package.json"))
               ? dir
               : QString();
}

} // namespace

class TestCliExportMap : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_profile = writeProfile(m_dir);
        QString error;
        QVERIFY2(m_sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), m_profile, QStringLiteral("--listen"),
                              QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                             &error),
                 qPrintable(error));
    }

    // What the profile declares is what a client reads.
    void servedAsDeclared_data()
    {
        QTest::addColumn<QStringList>("read");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("expected"); // read -q's values, one a line
        QTest::newRow("03 reads the f32") << QStringList{QStringLiteral("-f"), QStringLiteral("3"), QStringLiteral("-a"), QStringLiteral("0"), QStringLiteral("-n"), QStringLiteral("2"), QStringLiteral("--format"), QStringLiteral("f32-cdab")} << 0 << QStringLiteral("230.5\n");
        QTest::newRow("04 reads the same registers")
            << QStringList{QStringLiteral("-f"), QStringLiteral("4"), QStringLiteral("-a"), QStringLiteral("0"), QStringLiteral("-n"), QStringLiteral("2"), QStringLiteral("--format"), QStringLiteral("f32-cdab")} << 0 << QStringLiteral("230.5\n");
        QTest::newRow("02 reads the coils") << QStringList{QStringLiteral("-f"), QStringLiteral("2"), QStringLiteral("-a"), QStringLiteral("0"), QStringLiteral("-n"), QStringLiteral("2")} << 0 << QStringLiteral("1\n0\n");
        QTest::newRow("gap: zeros between entries") << QStringList{QStringLiteral("-f"), QStringLiteral("3"), QStringLiteral("-a"), QStringLiteral("36"), QStringLiteral("-n"), QStringLiteral("5")} << 0 << QStringLiteral("0\n0\n0\n0\n21326\n");
        QTest::newRow("gap: 02 past the last entry") << QStringList{QStringLiteral("-f"), QStringLiteral("3"), QStringLiteral("-a"), QStringLiteral("50"), QStringLiteral("-n"), QStringLiteral("2")} << 1 << QStringLiteral("");
        QTest::newRow("string of 7, space padded") << QStringList{QStringLiteral("-f"), QStringLiteral("3"), QStringLiteral("-a"), QStringLiteral("40"), QStringLiteral("-n"), QStringLiteral("4"), QStringLiteral("--format"), QStringLiteral("ascii")} << 0
                                                    << QStringLiteral("SN\n-4\n2 \n  \n");
        QTest::newRow("sentinel served raw") << QStringList{QStringLiteral("-f"), QStringLiteral("3"), QStringLiteral("-a"), QStringLiteral("5"), QStringLiteral("-n"), QStringLiteral("1"), QStringLiteral("--format"), QStringLiteral("hex")} << 0 << QStringLiteral("0x8000\n");
        QTest::newRow("scale from a register: 1250 W is raw 125")
            << QStringList{QStringLiteral("-f"), QStringLiteral("3"), QStringLiteral("-a"), QStringLiteral("26"), QStringLiteral("-n"), QStringLiteral("2")} << 0 << QStringLiteral("125\n1\n");
    }

    void servedAsDeclared()
    {
        QFETCH(QStringList, read);
        QFETCH(int, exitCode);
        QFETCH(QString, expected);
        QStringList args{QStringLiteral("read"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--unit"), QStringLiteral("3"),
                         QStringLiteral("-q")};
        for (QString &a : read) {
            if (a == QLatin1String("-f"))
                a = QStringLiteral("--function");
            else if (a == QLatin1String("-a"))
                a = QStringLiteral("--address");
            else if (a == QLatin1String("-n"))
                a = QStringLiteral("--quantity");
        }
        const CliResult r = runMbscope(args + read);
        QVERIFY2(r.finished && r.exitCode == exitCode, r.describe());
        if (exitCode == 0) {
            // -q prints "[ADDRESS]: <tab>VALUE" a line, as mbpoll does: the values alone.
            QString values = r.outText();
            values.replace(QRegularExpression(QStringLiteral("(^|\n)\\[\\d+\\]: \t")), QStringLiteral("\\1"));
            QCOMPARE(values, expected);
        } else
            QVERIFY2(r.errText().contains(QStringLiteral("exception 0x02 Illegal Data Address")), r.describe());
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no profile") << QStringList{QStringLiteral("--to"), QStringLiteral("csv")}
                                    << QStringLiteral("mbscope export-map: which profile? expected a shipped profile's name or a JSON file");
        QTest::newRow("no format") << QStringList{QStringLiteral("PROFILE")}
                                   << QStringLiteral("mbscope export-map: --to is missing: expected nodered, telegraf, homeassistant, "
                                      "modbus_exporter or csv");
        QTest::newRow("unknown format") << QStringList{QStringLiteral("PROFILE"), QStringLiteral("--to"), QStringLiteral("influx")}
                                        << QStringLiteral("mbscope export-map: --to 'influx' is not a format: expected nodered, telegraf, "
                                           "homeassistant, modbus_exporter or csv");
        QTest::newRow("unit not in the profile") << QStringList{QStringLiteral("PROFILE"), QStringLiteral("--to"), QStringLiteral("csv"), QStringLiteral("--unit"), QStringLiteral("9")}
                                                 << QStringLiteral("mbscope export-map: --unit 9: the profile has no such unit");
        QTest::newRow("serial endpoint for modbus_exporter")
            << QStringList{QStringLiteral("PROFILE"), QStringLiteral("--to"), QStringLiteral("modbus_exporter"), QStringLiteral("--endpoint"), QStringLiteral("rtu:///dev/ttyUSB0")}
            << QStringLiteral("modbus_exporter reads Modbus/TCP only");
        QTest::newRow("udp for telegraf") << QStringList{QStringLiteral("PROFILE"), QStringLiteral("--to"), QStringLiteral("telegraf"), QStringLiteral("--endpoint"), QStringLiteral("udp://127.0.0.1:502")}
                                          << QStringLiteral("telegraf takes tcp://, rtu-tcp:// or rtu:// endpoints, not udp://");
        QTest::newRow("bad interval") << QStringList{QStringLiteral("PROFILE"), QStringLiteral("--to"), QStringLiteral("csv"), QStringLiteral("--interval"), QStringLiteral("soon")} << QStringLiteral("--interval");
        QTest::newRow("profile that does not load: file, row, field")
            << QStringList{QStringLiteral("BROKEN"), QStringLiteral("--to"), QStringLiteral("csv")}
            << QStringLiteral("broken.json: units[0].tables.holding[0].bits.16: '16' is not a bit of a u16: expected 0-15");
    }

    void usageErrors()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const QString broken = m_dir.filePath(QStringLiteral("broken.json"));
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"name": "b", "units": [{"id": 1, "tables": {"holding": [{"address": 0, "bits": {"16": "x"}}]}}]})");
        f.close();
        args.replaceInStrings(QStringLiteral("PROFILE"), m_profile);
        args.replaceInStrings(QStringLiteral("BROKEN"), broken);
        const CliResult r = runMbscope(QStringList{QStringLiteral("export-map")} + args);
        QVERIFY2(r.finished && r.exitCode == 2, r.describe());
        QVERIFY2(r.errText().contains(message), r.describe());
        QVERIFY(r.out.isEmpty());
    }

    void outputFile()
    {
        const QString out = m_dir.filePath(QStringLiteral("map.csv"));
        QFile::remove(out);
        const QStringList args{QStringLiteral("export-map"), m_profile, QStringLiteral("--to"), QStringLiteral("csv"),
                               QStringLiteral("-o"), out};
        CliResult r = runMbscope(args);
        QVERIFY2(r.finished && r.exitCode == 0, r.describe());
        QCOMPARE(r.errText(), QStringLiteral("wrote 22 values in 4 blocks to %1 (csv)\n").arg(out));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll().count('\n'), 23); // the header and a row a value
        r = runMbscope(args);
        QVERIFY2(r.finished && r.exitCode == 2 && r.errText().contains(QStringLiteral("--force")), r.describe());
        r = runMbscope(args + QStringList{QStringLiteral("--force")});
        QVERIFY2(r.finished && r.exitCode == 0, r.describe());
    }

    void verify_data()
    {
        QTest::addColumn<QStringList>("write"); // a write before the export, or none
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("every value usable") << QStringList{} << 0
                                            << QStringLiteral("verified: 22 values read from %1 are finite and inside their ranges\n");
        QTest::newRow("above max") << QStringList{QStringLiteral("--address"), QStringLiteral("50"), QStringLiteral("--registers"), QStringLiteral("9000")} << 1
                                   << QStringLiteral("map-test.json: unit 3 holding 50 (CT ratio): 9000 is above max 5000\n");
        QTest::newRow("below min") << QStringList{QStringLiteral("--address"), QStringLiteral("0"), QStringLiteral("--registers"), QStringLiteral("0,0x4300"), QStringLiteral("--format"), QStringLiteral("u16")} << 1
                                   << QStringLiteral("map-test.json: unit 3 holding 0 (Voltage): 128 is below min 180\n");
        QTest::newRow("not finite") << QStringList{QStringLiteral("--address"), QStringLiteral("30"), QStringLiteral("--registers"), QStringLiteral("0x7FC0,0")} << 1
                                    << QStringLiteral("map-test.json: unit 3 holding 30 (Float big): NaN is not finite\n");
        QTest::newRow("a sentinel is accepted") << QStringList{QStringLiteral("--address"), QStringLiteral("5"), QStringLiteral("--registers"), QStringLiteral("0x8000")} << 0 << QStringLiteral("verified: ");
    }

    // --verify reads every value once through the map and refuses what is not usable, naming it;
    // nothing is written then.
    void verify()
    {
        QFETCH(QStringList, write);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        // Each row starts from the profile's values.
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), m_profile, QStringLiteral("--listen"),
                            QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                           &error),
                 qPrintable(error));
        if (!write.isEmpty()) {
            const CliResult w = runMbscope(QStringList{QStringLiteral("write"), QStringLiteral("--target"), sim.url(),
                                                       QStringLiteral("--unit"), QStringLiteral("3")}
                                           + write);
            QVERIFY2(w.finished && w.exitCode == 0, w.describe());
        }
        const QString out = m_dir.filePath(QStringLiteral("verified.yaml"));
        QFile::remove(out);
        const CliResult r = runMbscope({QStringLiteral("export-map"), m_profile, QStringLiteral("--to"), QStringLiteral("homeassistant"),
                                        QStringLiteral("--verify"), sim.url(), QStringLiteral("-o"), out});
        QVERIFY2(r.finished && r.exitCode == exitCode, r.describe());
        QVERIFY2(r.errText().contains(message.contains(QLatin1String("%1")) ? message.arg(sim.url()) : message), r.describe());
        QCOMPARE(QFile::exists(out), exitCode == 0);
        if (exitCode != 0)
            QVERIFY2(r.errText().contains(QStringLiteral("refused: 1 of 22 values read from %1 are not usable; nothing written")
                                              .arg(sim.url())),
                     r.describe());
    }

    // Issue 28, from a new user's try: --verify keeps the device's pace its profile gives (it sent
    // its reads as the connection opened and got timeouts from a device with a warm-up, and
    // exception 06 from one with a gap), and a value no read can fetch whole within the device's
    // largest quantity is refused before anything is sent (it was exported as one read the device
    // refuses).
    void verifyKeepsThePaceAndTheLargestRead()
    {
        const QString paced = m_dir.filePath(QStringLiteral("paced.json"));
        QFile file(paced);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(R"({"name": "paced", "limits": {"minGapMs": 40, "warmUpMs": 300, "maxQuantity": {"0x03": 4}},
                      "units": [{"id": 1, "tables": {"holding": [{"address": 0, "type": "u16", "name": "A", "value": 1},
                                                                 {"address": 10, "type": "u16", "name": "B", "value": 2},
                                                                 {"address": 20, "type": "u16", "name": "C", "value": 3}]}}]})");
        file.close();
        Background sim;
        QString error;
        QVERIFY2(sim.start({QStringLiteral("simulate"), QStringLiteral("--profile"), paced, QStringLiteral("--listen"),
                            QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                           &error),
                 qPrintable(error));
        const CliResult r = runMbscope({QStringLiteral("export-map"), paced, QStringLiteral("--to"), QStringLiteral("csv"),
                                        QStringLiteral("--verify"), sim.url()});
        QVERIFY2(r.finished && r.exitCode == 0, r.describe());
        QVERIFY2(r.errText().contains(QLatin1String("verified: 3 values read from ")), r.describe());

        const QString tooLarge = m_dir.filePath(QStringLiteral("too-large.json"));
        QFile large(tooLarge);
        QVERIFY(large.open(QIODevice::WriteOnly | QIODevice::Truncate));
        large.write(R"({"name": "too-large", "limits": {"maxQuantity": {"0x03": 4}},
                       "units": [{"id": 1, "tables": {"holding": [{"address": 20, "type": "ascii", "length": 10, "name": "Serial number", "value": "SN-1234567"}]}}]})");
        large.close();
        const QString out = m_dir.filePath(QStringLiteral("too-large.csv"));
        const CliResult refused = runMbscope({QStringLiteral("export-map"), tooLarge, QStringLiteral("--to"), QStringLiteral("csv"),
                                              QStringLiteral("-o"), out});
        QVERIFY2(refused.finished && refused.exitCode == 1, refused.describe());
        QVERIFY2(refused.errText().contains(QLatin1String("unit 1 holding 20 (Serial number): 5 registers in one read, more than "
                                                          "maxQuantity 4 of function 0x03\n")),
                 refused.describe());
        QVERIFY(!QFile::exists(out));
    }

    void verifyUnreachable()
    {
        const CliResult r = runMbscope({QStringLiteral("export-map"), m_profile, QStringLiteral("--to"), QStringLiteral("csv"),
                                        QStringLiteral("--verify"), QStringLiteral("tcp://127.0.0.1:%1").arg(closedPort()),
                                        QStringLiteral("--timeout"), QStringLiteral("300ms")});
        QVERIFY2(r.finished && r.exitCode == 1, r.describe());
        QVERIFY2(r.errText().contains(QStringLiteral("(Voltage): ")), r.describe());
        QVERIFY(r.out.isEmpty());
    }

    // The exported flow, run by Node-RED against the simulator, reads every value as mbscope does,
    // from a device that needs its pace kept (the profile's limits, served by the simulator): 40 ms
    // between requests (exception 06 otherwise) and 600 ms after a connection opens (requests
    // ignored before). A flow that did not keep it would read nothing: its four reads go out
    // together, and its first 300 ms after connecting.
    void nodeRedReadsWhatTheSimulatorServes()
    {
        const QString nodered = nodeRedDir();
        if (nodered.isEmpty())
            QSKIP("Node-RED is not installed in /opt/mbscope-nodered (scripts/install-deps.sh --tests installs it)");
        const QString node = QStandardPaths::findExecutable(QStringLiteral("node"));
        if (node.isEmpty())
            QSKIP("node is not installed");
        QByteArray paced(kProfile);
        paced.replace(R"({"name": "map-test",)", R"({"name": "map-test", "limits": {"minGapMs": 40, "tooSoon": "busy", "warmUpMs": 600},)");
        const QString pacedProfile = m_dir.filePath(QStringLiteral("map-test-paced.json"));
        {
            QFile f(pacedProfile);
            QVERIFY(f.open(QIODevice::WriteOnly) && f.write(paced) == paced.size());
        }
        Background device;
        QString error;
        QVERIFY2(device.start({QStringLiteral("simulate"), QStringLiteral("--profile"), pacedProfile, QStringLiteral("--listen"),
                               QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                              &error),
                 qPrintable(error));

        // The flow, its debug nodes turned into file nodes that write each message's payload.
        const QString flowPath = m_dir.filePath(QStringLiteral("flow.json"));
        QFile::remove(flowPath);
        const CliResult exported = runMbscope({QStringLiteral("export-map"), pacedProfile, QStringLiteral("--to"), QStringLiteral("nodered"),
                                               QStringLiteral("--endpoint"), device.url(), QStringLiteral("--interval"),
                                               QStringLiteral("300ms"), QStringLiteral("-o"), flowPath});
        QVERIFY2(exported.finished && exported.exitCode == 0, exported.describe());
        QFile flowFile(flowPath);
        QVERIFY(flowFile.open(QIODevice::ReadOnly));
        QJsonArray flow = QJsonDocument::fromJson(flowFile.readAll()).array();
        flowFile.close();
        const QString values = m_dir.filePath(QStringLiteral("values.jsonl"));
        QFile::remove(values);
        int reads = 0;
        for (qsizetype i = 0; i < flow.size(); ++i) {
            QJsonObject n = flow.at(i).toObject();
            if (n.value(QStringLiteral("type")).toString() == QLatin1String("modbus-read"))
                ++reads;
            if (n.value(QStringLiteral("type")).toString() != QLatin1String("debug"))
                continue;
            flow[i] = QJsonObject{{QStringLiteral("id"), n.value(QStringLiteral("id"))},
                                  {QStringLiteral("type"), QStringLiteral("file")},
                                  {QStringLiteral("z"), n.value(QStringLiteral("z"))},
                                  {QStringLiteral("filename"), values},
                                  {QStringLiteral("filenameType"), QStringLiteral("str")},
                                  {QStringLiteral("appendNewline"), true},
                                  {QStringLiteral("createDir"), false},
                                  {QStringLiteral("overwriteFile"), QStringLiteral("false")},
                                  {QStringLiteral("encoding"), QStringLiteral("none")},
                                  {QStringLiteral("wires"), QJsonArray{}}};
        }
        QCOMPARE(reads, 4); // the coils; holding 0-35, the string at 40-43, the setting at 50
        const QString userDir = m_dir.filePath(QStringLiteral("nodered"));
        QVERIFY(QDir().mkpath(userDir));
        QVERIFY(QFile::link(nodered + QStringLiteral("/node_modules"), userDir + QStringLiteral("/node_modules")));
        QFile out(userDir + QStringLiteral("/flows.json"));
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(flow).toJson());
        out.close();
        QFile settings(userDir + QStringLiteral("/settings.js"));
        QVERIFY(settings.open(QIODevice::WriteOnly));
        // Headless: no editor, no HTTP endpoints, nothing listening.
        settings.write("module.exports = { httpAdminRoot: false, httpNodeRoot: false, flowFile: 'flows.json',\n"
                       "  credentialSecret: false, logging: { console: { level: 'warn' } } };\n");
        settings.close();

        QProcess red;
        red.setProcessChannelMode(QProcess::MergedChannels);
        red.start(node, {nodered + QStringLiteral("/node_modules/node-red/red.js"), QStringLiteral("--userDir"), userDir,
                         QStringLiteral("--settings"), userDir + QStringLiteral("/settings.js")});
        QVERIFY2(red.waitForStarted(30000), qPrintable(red.errorString()));
        // Every block's payload at least once (a line each), within a minute.
        QMap<QString, QJsonValue> seen;
        QElapsedTimer waited;
        waited.start();
        while (waited.elapsed() < 60000 && red.state() == QProcess::Running) {
            red.waitForReadyRead(500);
            QFile lines(values);
            if (!lines.open(QIODevice::ReadOnly))
                continue;
            for (const QByteArray &line : lines.readAll().split('\n')) {
                const QJsonObject payload = QJsonDocument::fromJson(line).object();
                for (auto it = payload.begin(); it != payload.end(); ++it)
                    seen.insert(it.key(), it.value());
            }
            // Every block's payload: the four reads go out 40 ms apart (the device's gap), so the
            // first ones can come back well before the last.
            if (seen.contains(QStringLiteral("relay")) && seen.contains(QStringLiteral("serial_number")) && seen.contains(QStringLiteral("voltage"))
                && seen.contains(QStringLiteral("ct_ratio")))
                break;
        }
        const QByteArray log = red.readAll();
        red.terminate();
        if (!red.waitForFinished(10000))
            red.kill();
        QVERIFY2(seen.contains(QStringLiteral("relay")) && seen.contains(QStringLiteral("serial_number")),
                 qPrintable(QStringLiteral("Node-RED wrote no values within a minute:\n") + QString::fromUtf8(log)));

        // Each value as `mbscope read` reads it from the simulator (raw, then the profile's scale).
        struct Expect {
            const char *name;
            const char *format;
            int function;
            int address;
            double scale;
            double offset;
        };
        const Expect expects[] = {
            {"voltage", "f32-cdab", 3, 0, 1, 0},     {"energy", "u32-cdab", 3, 2, 0.001, 0},
            {"status", "u16", 3, 4, 1, 0},           {"mode", "u16", 3, 6, 1, 0},
            {"total", "f64-hgfedcba", 3, 7, 1, 0},       {"flow", "f32-badc", 3, 11, 1, 0},
            {"count", "i32-dcba", 3, 13, 1, 0},      {"big", "u64-ghefcdab", 3, 15, 1, 0},
            {"signed_big", "i64-abcdefgh", 3, 19, 1, 0},      {"swapped", "u16-ba", 3, 23, 1, 0},
            {"pressure", "u16", 3, 24, 0.01, 900},   {"word", "u16", 3, 25, 1, 0},
            {"power", "i16", 3, 26, 10, 0},          {"signed", "i32-badc", 3, 28, 1, 0},
            {"float_big", "f32-abcd", 3, 30, 1, 0},       {"double_cdab", "f64-ghefcdab", 3, 32, 1, 0},
            {"ct_ratio", "u16", 3, 50, 1, 0},        {"relay", "", 1, 0, 1, 0},
            {"lamp", "", 1, 1, 1, 0},
        };
        for (const Expect &e : expects) {
            const RegisterFormatProbe probe{QString::fromLatin1(e.format)};
            QStringList args{QStringLiteral("read"), QStringLiteral("--target"), m_sim.url(), QStringLiteral("--unit"),
                             QStringLiteral("3"), QStringLiteral("--function"), QString::number(e.function),
                             QStringLiteral("--address"), QString::number(e.address), QStringLiteral("--quantity"),
                             QString::number(probe.registers()), QStringLiteral("--json")};
            if (*e.format)
                args << QStringLiteral("--format") << probe.format;
            const CliResult r = runMbscope(args);
            QVERIFY2(r.finished && r.exitCode == 0, r.describe());
            const QJsonObject first = r.json().value(QStringLiteral("values")).toArray().at(0).toObject();
            const QJsonValue raw = *e.format ? first.value(probe.format) : first.value(QStringLiteral("value"));
            const double served = (raw.isString() ? raw.toString().toDouble() : raw.toDouble()) * e.scale + e.offset;
            const double read = seen.value(QString::fromLatin1(e.name)).toDouble(std::nan(""));
            QVERIFY2(std::abs(read - served) <= 1e-9 * std::max(1.0, std::abs(served)),
                     qPrintable(QStringLiteral("%1: Node-RED read %2, the simulator serves %3 (%4)")
                                    .arg(QLatin1String(e.name)).arg(read, 0, 'g', 17).arg(served, 0, 'g', 17).arg(r.outText())));
        }
        // What has no number: the sentinel, the string, the meaning and the bits.
        QCOMPARE(seen.value(QStringLiteral("temperature")), QJsonValue(QJsonValue::Null));
        QCOMPARE(seen.value(QStringLiteral("serial_number")).toString(), QStringLiteral("SN-42"));
        QCOMPARE(seen.value(QStringLiteral("mode_text")).toString(), QStringLiteral("auto"));
        QCOMPARE(seen.value(QStringLiteral("status_bits")).toObject(),
                 (QJsonObject{{QStringLiteral("run"), true}, {QStringLiteral("fault"), true}}));
    }

    void cleanupTestCase() { m_sim.stop(); }

private:
    // The registers a format takes: 1, 2 or 4.
    struct RegisterFormatProbe {
        QString format;
        [[nodiscard]] int registers() const
        {
            if (format.startsWith(QLatin1String("f64")) || format.startsWith(QLatin1String("u64"))
                || format.startsWith(QLatin1String("i64")))
                return 4;
            if (format.startsWith(QLatin1String("f32")) || format.startsWith(QLatin1String("u32"))
                || format.startsWith(QLatin1String("i32")))
                return 2;
            return 1;
        }
    };

    QTemporaryDir m_dir;
    QString m_profile;
    Background m_sim;
};

QTEST_GUILESS_MAIN(TestCliExportMap)
#include "tst_cli_exportmap.moc"
