// The exports of a register map (core/mapexport): each format parsed back (JSON as it is, TOML
// and YAML through Python's tomllib and PyYAML) and its fields checked against the profile; the
// Node-RED function nodes run under node against the registers the simulator would serve; the
// verifier's verdicts.

#include "mapexport/mapexportformat.h"
#include "mapexport/mapverifier.h"
#include "profile/profileloader.h"
#include "protocol/registervalue.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtTest/QtTest>

#include <cmath>

using namespace mbscope;

namespace {

// Every type and order the exports must get right, with a value each.
const char *const kProfile = R"({"name": "test-meter", "endpoints": ["udp://127.0.0.1:5020", "tcp://127.0.0.1:5020"],
  "units": [{"id": 3, "tables": {
    "holding": [
      {"address": 0, "name": "Setpoint", "type": "i16", "scale": 0.1, "unit": "degC", "value": 21.5, "kind": "setting", "min": 5, "max": 35},
      {"address": 1, "name": "Serial number", "type": "ascii", "length": 6, "padding": "space", "value": "SN42", "kind": "constant"},
      {"address": 10, "count": 2, "kind": "reserved"}],
    "input": [
      {"address": 0, "name": "Voltage", "type": "f32-cdab", "unit": "V", "value": 230.5, "kind": "measurement"},
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
      {"address": 25, "name": "Word", "type": "hex", "value": "0xBEEF"}],
    "coils": [{"address": 0, "name": "Relay", "values": [true]}]}}]})";

DeviceProfile testProfile()
{
    const ProfileLoadResult r = ProfileLoader::parse(kProfile, QStringLiteral("test-meter.json"));
    if (!r.ok)
        qFatal("%s", qPrintable(r.errorText()));
    return r.profile;
}

MapExportInput testInput()
{
    const DeviceProfile profile = testProfile();
    MapExportInput input = MapExportInput::fromProfile(profile);
    input.endpoint = *LinkUrl::parse(u"tcp://127.0.0.1:5020").url;
    return input;
}

// "modbus[0].sensors[1].data_type" in a JSON document.
QJsonValue at(const QJsonValue &root, const QString &path)
{
    QJsonValue v = root;
    static const QRegularExpression part(QStringLiteral(R"(([^.\[\]]+)|\[(\d+)\])"));
    auto it = part.globalMatch(path);
    while (it.hasNext()) {
        const QRegularExpressionMatch m = it.next();
        if (!m.captured(1).isEmpty())
            v = v.toObject().value(m.captured(1));
        else
            v = v.toArray().at(m.captured(2).toInt());
    }
    return v;
}

QString text(const QJsonValue &v)
{
    if (v.isDouble())
        return QString::number(v.toDouble(), 'g', 15);
    if (v.isBool())
        return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (v.isUndefined())
        return QStringLiteral("(absent)");
    if (v.isNull())
        return QStringLiteral("null");
    if (v.isString())
        return v.toString();
    return QString::fromUtf8(QJsonDocument::fromVariant(v.toVariant()).toJson(QJsonDocument::Compact));
}

// TOML and YAML as JSON, through Python (python3 with tomllib, 3.11, and PyYAML).
QJsonDocument parsed(MapExportFormat format, const QString &written, QString *error)
{
    if (format == MapExportFormat::NodeRed)
        return QJsonDocument::fromJson(written.toUtf8());
    if (format == MapExportFormat::Csv) {
        // CSV as {name: {column: field}}: the writer quotes no field of this profile.
        QJsonObject rows;
        QStringList lines = written.split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
        const QStringList header = lines.takeFirst().split(QLatin1Char(','));
        rows.insert(QStringLiteral("rows"), int(lines.size()));
        for (const QString &line : lines) {
            const QStringList fields = line.split(QLatin1Char(','));
            QJsonObject row;
            for (qsizetype i = 0; i < header.size(); ++i)
                row.insert(header.at(i), fields.value(i));
            rows.insert(fields.value(5), row);
        }
        return QJsonDocument(rows);
    }
    const char *script = format == MapExportFormat::Telegraf
                             ? "import sys, json, tomllib; print(json.dumps(tomllib.loads(sys.stdin.read())))"
                             : "import sys, json, yaml; print(json.dumps(yaml.safe_load(sys.stdin.read())))";
    QProcess python;
    python.start(QStringLiteral("python3"), {QStringLiteral("-c"), QString::fromLatin1(script)});
    if (!python.waitForStarted(10000)) {
        *error = QStringLiteral("python3 does not start");
        return {};
    }
    python.write(written.toUtf8());
    python.closeWriteChannel();
    if (!python.waitForFinished(30000) || python.exitCode() != 0) {
        *error = QString::fromUtf8(python.readAllStandardError());
        return {};
    }
    return QJsonDocument::fromJson(python.readAllStandardOutput());
}

} // namespace

class TestMapExport : public QObject
{
    Q_OBJECT
private slots:
    void points()
    {
        const MapExportInput input = testInput();
        QStringList names;
        for (const MapPoint &p : input.points)
            names.append(p.name);
        // Table order (coils, discrete, input, holding), reserved entries left out, strings one value.
        QCOMPARE(names.join(QLatin1Char(' ')),
                 QStringLiteral("relay voltage energy status temperature mode total flow count big signed_big swapped pressure "
                                "word setpoint serial_number"));
        QCOMPARE(input.blocks.size(), 3);
        QCOMPARE(input.blocks.at(1).start, quint16(0));
        QCOMPARE(input.blocks.at(1).quantity, 26);
        QCOMPARE(input.blocks.at(2).quantity, 4); // holding 0-3: the string's three registers with the setpoint
    }

    void blocksHonourLimits()
    {
        DeviceProfile profile = testProfile();
        profile.limits.maxQuantity.insert(0x04, 8);
        const QList<MapPoint> points = MapPoint::fromProfile(profile);
        const QList<ExportBlock> blocks = ExportBlock::group(points, &profile.limits);
        for (const ExportBlock &b : blocks)
            QVERIFY2(b.table != SimTable::InputRegisters || b.quantity <= 8, qPrintable(QString::number(b.quantity)));
        QCOMPARE(blocks.size(), 6); // coils; input 0-6, 7-14, 15-22, 23-25; holding 0-3
    }

    void formats_data()
    {
        QTest::addColumn<int>("format");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("expected");
        auto row = [](MapExportFormat f, const char *path, const char *expected) {
            QTest::addRow("%s %s", qPrintable(MapExporter::formatName(f)), path)
                << int(f) << QString::fromLatin1(path) << QString::fromUtf8(expected);
        };
        using F = MapExportFormat;
        // CSV: one value a row
        row(F::Csv, "rows", "16");
        row(F::Csv, "voltage.function", "04");
        row(F::Csv, "voltage.type", "f32");
        row(F::Csv, "voltage.order", "CDAB");
        row(F::Csv, "voltage.unit", "V");
        row(F::Csv, "voltage.kind", "measurement");
        row(F::Csv, "energy.scale", "0.001");
        row(F::Csv, "setpoint.scale", "0.1"); // the shortest text, not 0.10000000000000001
        row(F::Csv, "setpoint.min", "5");
        row(F::Csv, "setpoint.max", "35");
        row(F::Csv, "setpoint.writable", "yes");
        row(F::Csv, "serial_number.type", "string");
        row(F::Csv, "serial_number.length", "6");
        row(F::Csv, "serial_number.padding", "space");
        row(F::Csv, "temperature.not_implemented", "0x8000");
        row(F::Csv, "mode.enum", "0=off;1=auto");
        row(F::Csv, "status.bits", "0=run;3=fault");
        row(F::Csv, "relay.function", "01");
        row(F::Csv, "total.order", "HGFEDCBA");
        // Telegraf, request style: a request per unit, table and byte order
        row(F::Telegraf, "inputs.modbus[0].controller", "tcp://127.0.0.1:5020");
        row(F::Telegraf, "inputs.modbus[0].transmission_mode", "TCP");
        row(F::Telegraf, "inputs.modbus[0].configuration_type", "request");
        row(F::Telegraf, "inputs.modbus[0].request[0].register", "coil");
        row(F::Telegraf, "inputs.modbus[0].request[0].slave_id", "3");
        row(F::Telegraf, "inputs.modbus[0].request[0].fields[0].name", "relay");
        row(F::Telegraf, "inputs.modbus[0].request[1].register", "input");
        row(F::Telegraf, "inputs.modbus[0].request[1].byte_order", "CDAB");
        row(F::Telegraf, "inputs.modbus[0].request[1].fields[0].type", "FLOAT32");
        row(F::Telegraf, "inputs.modbus[0].request[1].fields[1].name", "energy");
        row(F::Telegraf, "inputs.modbus[0].request[1].fields[1].type", "UINT32");
        row(F::Telegraf, "inputs.modbus[0].request[1].fields[1].scale", "0.001");
        row(F::Telegraf, "inputs.modbus[0].request[1].fields[1].address", "2");
        row(F::Telegraf, "inputs.modbus[0].request[1].fields[2].name", "big");
        row(F::Telegraf, "inputs.modbus[0].request[1].fields[2].type", "UINT64");
        row(F::Telegraf, "inputs.modbus[0].request[2].byte_order", "ABCD");
        row(F::Telegraf, "inputs.modbus[0].request[2].fields[1].type", "INT16");
        row(F::Telegraf, "inputs.modbus[0].request[2].fields[1].scale", "0.1");
        row(F::Telegraf, "inputs.modbus[0].request[3].byte_order", "DCBA");
        row(F::Telegraf, "inputs.modbus[0].request[3].fields[0].type", "FLOAT64");
        row(F::Telegraf, "inputs.modbus[0].request[3].fields[1].type", "INT32");
        row(F::Telegraf, "inputs.modbus[0].request[4].byte_order", "BADC");
        row(F::Telegraf, "inputs.modbus[0].request[4].fields[0].name", "flow");
        row(F::Telegraf, "inputs.modbus[0].request[4].fields[1].name", "swapped");
        row(F::Telegraf, "inputs.modbus[0].request[5].register", "holding");
        row(F::Telegraf, "inputs.modbus[0].request[5].fields[1].type", "STRING");
        row(F::Telegraf, "inputs.modbus[0].request[5].fields[1].length", "3");
        // Home Assistant
        row(F::HomeAssistant, "modbus[0].type", "tcp");
        row(F::HomeAssistant, "modbus[0].host", "127.0.0.1");
        row(F::HomeAssistant, "modbus[0].port", "5020");
        row(F::HomeAssistant, "modbus[0].sensors[0].name", "Voltage");
        row(F::HomeAssistant, "modbus[0].sensors[0].device_address", "3");
        row(F::HomeAssistant, "modbus[0].sensors[0].input_type", "input");
        row(F::HomeAssistant, "modbus[0].sensors[0].data_type", "float32");
        row(F::HomeAssistant, "modbus[0].sensors[0].swap", "word");
        row(F::HomeAssistant, "modbus[0].sensors[0].unit_of_measurement", "V");
        row(F::HomeAssistant, "modbus[0].sensors[0].state_class", "measurement");
        row(F::HomeAssistant, "modbus[0].sensors[1].data_type", "uint32");
        row(F::HomeAssistant, "modbus[0].sensors[1].scale", "0.001");
        row(F::HomeAssistant, "modbus[0].sensors[1].precision", "3");
        row(F::HomeAssistant, "modbus[0].sensors[1].state_class", "total_increasing");
        row(F::HomeAssistant, "modbus[0].sensors[3].nan_value", "32768");
        row(F::HomeAssistant, "modbus[0].sensors[3].precision", "1");
        row(F::HomeAssistant, "modbus[0].sensors[5].swap", "word_byte");
        row(F::HomeAssistant, "modbus[0].sensors[6].swap", "byte");
        row(F::HomeAssistant, "modbus[0].sensors[10].swap", "byte");
        row(F::HomeAssistant, "modbus[0].sensors[11].offset", "900");
        row(F::HomeAssistant, "modbus[0].sensors[13].input_type", "holding");
        // Home Assistant's own symbol: "degC" passed through left the sensor without its unit.
        row(F::HomeAssistant, "modbus[0].sensors[13].unit_of_measurement", "\u00B0C");
        row(F::HomeAssistant, "modbus[0].sensors[13].min_value", "5");
        row(F::HomeAssistant, "modbus[0].sensors[13].max_value", "35");
        row(F::HomeAssistant, "modbus[0].sensors[14].data_type", "string");
        row(F::HomeAssistant, "modbus[0].sensors[14].count", "3");
        row(F::HomeAssistant, "modbus[0].binary_sensors[0].input_type", "coil");
        row(F::HomeAssistant, "modbus[0].binary_sensors[0].address", "0");
        // prometheus-community modbus_exporter
        row(F::ModbusExporter, "modules[0].name", "test_meter");
        row(F::ModbusExporter, "modules[0].protocol", "tcp/ip");
        row(F::ModbusExporter, "modules[0].metrics[0].address", "100000");
        row(F::ModbusExporter, "modules[0].metrics[0].dataType", "bool");
        row(F::ModbusExporter, "modules[0].metrics[1].name", "voltage");
        row(F::ModbusExporter, "modules[0].metrics[1].address", "400000");
        row(F::ModbusExporter, "modules[0].metrics[1].dataType", "float32");
        row(F::ModbusExporter, "modules[0].metrics[1].endianness", "yolo");
        row(F::ModbusExporter, "modules[0].metrics[2].factor", "0.001");
        row(F::ModbusExporter, "modules[0].metrics[2].metricType", "gauge"); // its counter adds each reading
        row(F::ModbusExporter, "modules[0].metrics[4].name", "status_run");
        row(F::ModbusExporter, "modules[0].metrics[4].dataType", "bool");
        row(F::ModbusExporter, "modules[0].metrics[4].address", "400004");
        row(F::ModbusExporter, "modules[0].metrics[4].bitOffset", "0");
        row(F::ModbusExporter, "modules[0].metrics[5].bitOffset", "3");
        row(F::ModbusExporter, "modules[0].metrics[8].endianness", "little");
        row(F::ModbusExporter, "modules[0].metrics[9].endianness", "mixed");
        row(F::ModbusExporter, "modules[0].metrics[11].endianness", "yolo"); // u64 CDAB: 7 8 5 6 3 4 1 2
        row(F::ModbusExporter, "modules[0].metrics[13].endianness", "little"); // u16 BA
        row(F::ModbusExporter, "modules[0].metrics[16].address", "300000");
        row(F::ModbusExporter, "modules[0].metrics[17].name", "(absent)"); // the string has no metric
        // Node-RED
        row(F::NodeRed, "[0].type", "tab");
        row(F::NodeRed, "[1].type", "modbus-client");
        row(F::NodeRed, "[1].tcpHost", "127.0.0.1");
        row(F::NodeRed, "[1].tcpPort", "5020");
        row(F::NodeRed, "[1].tcpType", "DEFAULT");
        row(F::NodeRed, "[2].type", "modbus-read");
        row(F::NodeRed, "[2].dataType", "Coil");
        row(F::NodeRed, "[2].unitid", "3");
        row(F::NodeRed, "[2].server", "6d62736300000002");
        row(F::NodeRed, "[2].wires[0][0]", "6d62736300000004");
        row(F::NodeRed, "[3].type", "function");
        row(F::NodeRed, "[4].type", "debug");
        row(F::NodeRed, "[5].dataType", "InputRegister");
        row(F::NodeRed, "[5].adr", "0");
        row(F::NodeRed, "[5].quantity", "26");
        row(F::NodeRed, "[5].rate", "1000");
        row(F::NodeRed, "[5].rateUnit", "ms");
        row(F::NodeRed, "[8].dataType", "HoldingRegister");
        row(F::NodeRed, "[8].quantity", "4");
        row(F::NodeRed, "[11]", "(absent)");
    }

    void formats()
    {
        QFETCH(int, format);
        QFETCH(QString, path);
        QFETCH(QString, expected);
        const auto f = MapExportFormat(format);
        // Written and parsed once per format (Python starts in a fraction of a second, a hundred times over).
        static QMap<int, QJsonDocument> docs;
        if (!docs.contains(format)) {
            const QString written = MapExporter::write(f, testInput());
            QString error;
            const QJsonDocument d = parsed(f, written, &error);
            QVERIFY2(error.isEmpty(), qPrintable(error + QStringLiteral("\n") + written));
            docs.insert(format, d);
        }
        const QJsonDocument doc = docs.value(format);
        const QJsonValue root = doc.isArray() ? QJsonValue(doc.array()) : QJsonValue(doc.object());
        QCOMPARE(text(at(root, path)), expected);
    }

    void endpoints_data()
    {
        QTest::addColumn<int>("format");
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("expected");
        using F = MapExportFormat;
        QTest::newRow("telegraf rtu-tcp") << int(F::Telegraf) << QStringLiteral("rtu-tcp://10.0.0.5:4001")
                                          << QStringLiteral("inputs.modbus[0].transmission_mode") << QStringLiteral("RTUoverTCP");
        QTest::newRow("telegraf serial") << int(F::Telegraf) << QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=N")
                                         << QStringLiteral("inputs.modbus[0].controller") << QStringLiteral("file:///dev/ttyUSB0");
        QTest::newRow("telegraf serial parity") << int(F::Telegraf) << QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=N")
                                                << QStringLiteral("inputs.modbus[0].parity") << QStringLiteral("N");
        QTest::newRow("home assistant rtu-tcp") << int(F::HomeAssistant) << QStringLiteral("rtu-tcp://10.0.0.5:4001") << QStringLiteral("modbus[0].type")
                                                << QStringLiteral("rtuovertcp");
        QTest::newRow("home assistant serial") << int(F::HomeAssistant) << QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=N")
                                               << QStringLiteral("modbus[0].baudrate") << QStringLiteral("19200");
        QTest::newRow("node-red rtu-tcp") << int(F::NodeRed) << QStringLiteral("rtu-tcp://10.0.0.5:4001") << QStringLiteral("[1].tcpType")
                                          << QStringLiteral("TCP-RTU-BUFFERED");
        QTest::newRow("node-red serial") << int(F::NodeRed) << QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=E") << QStringLiteral("[1].serialParity")
                                         << QStringLiteral("even");
    }

    void endpoints()
    {
        QFETCH(int, format);
        QFETCH(QString, url);
        QFETCH(QString, path);
        QFETCH(QString, expected);
        MapExportInput input = testInput();
        const LinkUrl::Result parsedUrl = LinkUrl::parse(url);
        QVERIFY2(parsedUrl.url, qPrintable(parsedUrl.error));
        input.endpoint = *parsedUrl.url;
        QVERIFY(MapExporter::unsupportedEndpoint(MapExportFormat(format), input.endpoint).isEmpty());
        QString error;
        const QJsonDocument doc = parsed(MapExportFormat(format), MapExporter::write(MapExportFormat(format), input), &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const QJsonValue root = doc.isArray() ? QJsonValue(doc.array()) : QJsonValue(doc.object());
        QCOMPARE(text(at(root, path)), expected);
    }

    // The device's limits reach each tool's settings for them: the gap between requests, the
    // pause after a connection opens, the largest read (a Telegraf request per block).
    void paceHonoured_data()
    {
        QTest::addColumn<int>("format");
        QTest::addColumn<QString>("url");
        QTest::addColumn<bool>("limited");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("expected");
        using F = MapExportFormat;
        const QString tcp = QStringLiteral("tcp://127.0.0.1:5020");
        const QString serial = QStringLiteral("rtu:///dev/ttyUSB0?baud=19200&parity=N");
        auto row = [](const char *name, F f, const QString &url, bool limited, const char *path, const char *expected) {
            QTest::newRow(name) << int(f) << url << limited << QString::fromLatin1(path) << QString::fromLatin1(expected);
        };
        row("telegraf gap", F::Telegraf, tcp, true, "inputs.modbus[0].workarounds.pause_between_requests", "41ms");
        row("telegraf warm-up", F::Telegraf, tcp, true, "inputs.modbus[0].workarounds.pause_after_connect", "1500ms");
        row("telegraf none", F::Telegraf, tcp, false, "inputs.modbus[0].workarounds", "(absent)");
        // input 0-25 in reads of 8 at most: a request per block and order (unlimited, [5] is holding)
        row("telegraf largest read", F::Telegraf, tcp, true, "inputs.modbus[0].request[5].fields[0].name", "big");
        row("telegraf largest read, last", F::Telegraf, tcp, true, "inputs.modbus[0].request[7].fields[0].name", "swapped");
        row("home assistant gap", F::HomeAssistant, tcp, true, "modbus[0].message_wait_milliseconds", "41");
        row("home assistant warm-up", F::HomeAssistant, tcp, true, "modbus[0].delay", "2");
        row("home assistant none", F::HomeAssistant, tcp, false, "modbus[0].delay", "(absent)");
        row("node-red gap", F::NodeRed, tcp, true, "[1].commandDelay", "41");
        row("node-red units in turn", F::NodeRed, tcp, true, "[1].parallelUnitIdsAllowed", "false");
        row("node-red warm-up", F::NodeRed, tcp, true, "[2].delayOnStart", "true");
        row("node-red warm-up seconds", F::NodeRed, tcp, true, "[2].startDelayTime", "2");
        row("node-red serial warm-up", F::NodeRed, serial, true, "[1].serialConnectionDelay", "1500");
        row("node-red serial no delay on start", F::NodeRed, serial, true, "[2].delayOnStart", "false");
        row("node-red none", F::NodeRed, tcp, false, "[1].commandDelay", "1");
        row("node-red none, no delay", F::NodeRed, tcp, false, "[2].delayOnStart", "false");
        row("node-red largest read", F::NodeRed, tcp, true, "[5].quantity", "7");
    }

    void paceHonoured()
    {
        QFETCH(int, format);
        QFETCH(QString, url);
        QFETCH(bool, limited);
        QFETCH(QString, path);
        QFETCH(QString, expected);
        DeviceProfile profile = testProfile();
        if (limited) {
            profile.limits.minGapMs = 40.5;
            profile.limits.warmUpMs = 1500;
            profile.limits.maxQuantity.insert(0x04, 8);
        }
        MapExportInput input = MapExportInput::fromProfile(profile);
        input.endpoint = *LinkUrl::parse(url).url;
        const QString written = MapExporter::write(MapExportFormat(format), input);
        QString error;
        const QJsonDocument doc = parsed(MapExportFormat(format), written, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error + QLatin1Char('\n') + written));
        const QJsonValue root = doc.isArray() ? QJsonValue(doc.array()) : QJsonValue(doc.object());
        QVERIFY2(text(at(root, path)) == expected, qPrintable(text(at(root, path)) + QStringLiteral(" != ") + expected + QLatin1Char('\n') + written));
    }

    // modbus_exporter has no setting for the pace: the module says what the device needs.
    void paceSaidWhereNoSetting()
    {
        DeviceProfile profile = testProfile();
        profile.limits.minGapMs = 40.5;
        profile.limits.warmUpMs = 1500;
        MapExportInput input = MapExportInput::fromProfile(profile);
        input.endpoint = *LinkUrl::parse(u"tcp://127.0.0.1:5020").url;
        const QString written = MapExporter::write(MapExportFormat::ModbusExporter, input);
        QVERIFY2(written.contains(QLatin1String("# The device needs 41 ms between requests and 1500 ms after a connection opens: "
                                                "modbus_exporter has no setting for either.")),
                 qPrintable(written));
        QVERIFY(!MapExporter::write(MapExportFormat::ModbusExporter, testInput()).contains(QLatin1String("The device needs")));
    }

    void unsupportedEndpoints()
    {
        const LinkUrl serial = *LinkUrl::parse(u"rtu:///dev/ttyUSB0").url;
        QCOMPARE(MapExporter::unsupportedEndpoint(MapExportFormat::ModbusExporter, serial),
                 QStringLiteral("modbus_exporter reads Modbus/TCP only (the target is given by Prometheus as host:port): "
                                "expected a tcp:// endpoint"));
        QCOMPARE(MapExporter::unsupportedEndpoint(MapExportFormat::Telegraf, *LinkUrl::parse(u"udp://1.2.3.4:502").url),
                 QStringLiteral("telegraf takes tcp://, rtu-tcp:// or rtu:// endpoints, not udp://"));
        QVERIFY(MapExporter::unsupportedEndpoint(MapExportFormat::Csv, serial).isEmpty());
    }

    // The function nodes of the flow, run under node with the registers the simulator serves
    // (the profile's initial values), give every value as mbscope decodes it.
    void nodeRedConversion_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("expected");
        QTest::newRow("bit") << QStringLiteral("relay") << QStringLiteral("1");
        QTest::newRow("f32 CDAB") << QStringLiteral("voltage") << QStringLiteral("230.5");
        QTest::newRow("u32 CDAB scale 0.001") << QStringLiteral("energy") << QStringLiteral("1234.567");
        QTest::newRow("u16 with bits") << QStringLiteral("status") << QStringLiteral("9");
        QTest::newRow("named bits") << QStringLiteral("status_bits") << QStringLiteral(R"({"fault":true,"run":true})");
        QTest::newRow("i16 sentinel 0x8000") << QStringLiteral("temperature") << QStringLiteral("null");
        QTest::newRow("enumeration") << QStringLiteral("mode") << QStringLiteral("1");
        QTest::newRow("enumeration meaning") << QStringLiteral("mode_text") << QStringLiteral("auto");
        QTest::newRow("f64 DCBA") << QStringLiteral("total") << QStringLiteral("42.25");
        QTest::newRow("f32 BADC") << QStringLiteral("flow") << QStringLiteral("-1.5");
        QTest::newRow("i32 DCBA") << QStringLiteral("count") << QStringLiteral("-70000");
        QTest::newRow("u64 CDAB") << QStringLiteral("big") << QStringLiteral("1099511627776");
        QTest::newRow("i64 ABCD") << QStringLiteral("signed_big") << QStringLiteral("-5");
        QTest::newRow("u16 BA") << QStringLiteral("swapped") << QStringLiteral("258");
        QTest::newRow("u16 scale and offset") << QStringLiteral("pressure") << QStringLiteral("1013.25");
        QTest::newRow("hex") << QStringLiteral("word") << QStringLiteral("48879");
        QTest::newRow("i16 scale 0.1") << QStringLiteral("setpoint") << QStringLiteral("21.5");
        QTest::newRow("string space padded") << QStringLiteral("serial_number") << QStringLiteral("SN42");
    }

    void nodeRedConversion()
    {
        QFETCH(QString, name);
        QFETCH(QString, expected);
        const QString node = QStandardPaths::findExecutable(QStringLiteral("node"));
        if (node.isEmpty())
            QSKIP("node (Node.js) is not installed");
        // Every function node runs once; the rows look up their values.
        static QJsonObject values;
        static bool ran = false;
        if (!ran) {
            ran = true;
            QVERIFY(runFunctionNodes(node, &values));
        }
        const QJsonValue v = values.value(name);
        if (v.isDouble() && !expected.startsWith(QLatin1Char('{'))) {
            QVERIFY2(std::abs(v.toDouble() - expected.toDouble()) <= 1e-9 * std::max(1.0, std::abs(expected.toDouble())),
                     qPrintable(QStringLiteral("%1 is %2").arg(name, text(v))));
        } else {
            QCOMPARE(text(v), expected);
        }
    }

private:
    // Each function node of the flow under node, given the registers the simulator holds for
    // its block (the profile's initial values); the payloads' values merged into *values.
    static bool runFunctionNodes(const QString &node, QJsonObject *values)
    {
        const DeviceProfile profile = testProfile();
        const MapExportInput input = testInput();
        const QJsonArray flow = QJsonDocument::fromJson(MapExporter::write(MapExportFormat::NodeRed, input).toUtf8()).array();
        for (const QJsonValue &n : flow) {
            if (n[QStringLiteral("type")].toString() != QLatin1String("function"))
                continue;
            const int b = (n[QStringLiteral("id")].toString().right(8).toInt(nullptr, 16) - 4) / 3;
            const ExportBlock &block = input.blocks.at(b);
            QJsonArray regs;
            for (int a = block.start; a < block.start + block.quantity; ++a) {
                const TableEntry *e = profile.units.at(0).entryAt(block.table, a);
                if (!e)
                    return false;
                const quint16 word = e->initial.at(a - e->address);
                regs.append(isBitTable(block.table) ? QJsonValue(word != 0) : QJsonValue(int(word)));
            }
            const QString script = QStringLiteral("const msg = {payload: %1};\nconst result = (function (msg) {\n%2\n})(msg);\n"
                                                  "process.stdout.write(JSON.stringify(result.payload));\n")
                                       .arg(QString::fromUtf8(QJsonDocument(regs).toJson(QJsonDocument::Compact)),
                                            n[QStringLiteral("func")].toString());
            QProcess run;
            run.start(node, {QStringLiteral("-e"), script});
            if (!run.waitForFinished(30000) || run.exitCode() != 0) {
                qWarning("%s", run.readAllStandardError().constData());
                return false;
            }
            const QJsonObject payload = QJsonDocument::fromJson(run.readAllStandardOutput()).object();
            for (auto it = payload.begin(); it != payload.end(); ++it)
                values->insert(it.key(), it.value());
        }
        return true;
    }

private slots:

    void verify_data()
    {
        QTest::addColumn<QString>("point");
        QTest::addColumn<QList<quint16>>("words");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("problem");
        QTest::newRow("inside the range") << QStringLiteral("setpoint") << QList<quint16>{215} << QStringLiteral("21.5") << QStringLiteral("");
        QTest::newRow("above max") << QStringLiteral("setpoint") << QList<quint16>{400} << QStringLiteral("40") << QStringLiteral("40 is above max 35");
        QTest::newRow("below min") << QStringLiteral("setpoint") << QList<quint16>{quint16(-10)} << QStringLiteral("-1") << QStringLiteral("-1 is below min 5");
        QTest::newRow("NaN") << QStringLiteral("voltage") << QList<quint16>{0x0000, 0x7FC0} << QStringLiteral("NaN") << QStringLiteral("NaN is not finite");
        QTest::newRow("infinity") << QStringLiteral("voltage") << QList<quint16>{0x0000, 0x7F80} << QStringLiteral("Inf") << QStringLiteral("Inf is not finite");
        QTest::newRow("sentinel is not a failure") << QStringLiteral("temperature") << QList<quint16>{0x8000} << QStringLiteral("not implemented") << QStringLiteral("");
        QTest::newRow("string") << QStringLiteral("serial_number") << QList<quint16>{0x534E, 0x3432, 0x2020} << QStringLiteral("\"SN42\"") << QStringLiteral("");
    }

    void verify()
    {
        QFETCH(QString, point);
        QFETCH(QList<quint16>, words);
        QFETCH(QString, value);
        QFETCH(QString, problem);
        const MapExportInput input = testInput();
        QList<MapPoint> points;
        for (const MapPoint &p : input.points)
            if (p.name == point)
                points.append(p);
        QCOMPARE(points.size(), 1);
        const QList<ExportBlock> blocks = ExportBlock::group(points);
        const QList<MapVerdict> verdicts = MapVerifier::judge(points, blocks, {ExportBlockReading{words, {}}});
        QCOMPARE(verdicts.size(), 1);
        QCOMPARE(verdicts.at(0).value, value);
        QCOMPARE(verdicts.at(0).problem, problem);
        // A failed read fails every point of its block with what went wrong.
        const QList<MapVerdict> failed = MapVerifier::judge(points, blocks, {ExportBlockReading{{}, QStringLiteral("exception 02")}});
        QCOMPARE(failed.at(0).problem, QStringLiteral("exception 02"));
    }

    void formatNames()
    {
        for (MapExportFormat f : {MapExportFormat::NodeRed, MapExportFormat::Telegraf, MapExportFormat::HomeAssistant,
                                  MapExportFormat::ModbusExporter, MapExportFormat::Csv})
            QCOMPARE(MapExporter::formatFromName(MapExporter::formatName(f)), std::optional<MapExportFormat>(f));
        QVERIFY(!MapExporter::formatFromName(u"influx"));
    }
};

QTEST_GUILESS_MAIN(TestMapExport)
#include "tst_mapexport.moc"
