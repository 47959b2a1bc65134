#include "map/exportmapcommand.h"

#include "common/cli.h"
#include "exchange/deviceexchange.h"
#include "common/outputpath.h"
#include "common/requestoptions.h"
#include "common/targetoptions.h"
#include "common/transactionreport.h"

#include "mapexport/mapexportformat.h"
#include "mapexport/mapverifier.h"
#include "profile/profileloader.h"
#include "protocol/adubuilder.h"
#include "protocol/readanswer.h"
#include "time/duration.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFile>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

// One read of every block through target; bits come back as 0/1 words.
QList<ExportBlockReading> readBlocks(const TargetSettings &target, const QList<MapPoint> &points,
                                  const QList<ExportBlock> &blocks)
{
    QList<PlannedRequest> requests;
    for (const ExportBlock &b : blocks) {
        const quint8 function = points.at(b.points.constFirst()).readFunction();
        QByteArray pdu;
        pdu.append(char(function));
        pdu.append(char(b.start >> 8)).append(char(b.start & 0xFF));
        pdu.append(char(b.quantity >> 8)).append(char(b.quantity & 0xFF));
        AduOptions options;
        options.framing = target.url.framing();
        options.unitId = b.unitId;
        PlannedRequest r;
        r.item = RequestItem::forLink(AduBuilder::complete(pdu, options), target.url);
        r.item.timeoutMs = target.timeoutMs;
        r.item.retries = target.retries;
        r.functionCode = function;
        r.address = b.start;
        r.quantity = b.quantity;
        requests.append(r);
    }
    const QList<Transaction> records = exchange(target, requests);
    QList<ExportBlockReading> readings;
    for (qsizetype i = 0; i < blocks.size(); ++i) {
        ExportBlockReading reading;
        if (i >= records.size()) {
            reading.error = QStringLiteral("not read: the link failed before");
        } else if (records.at(i).status != TransactionStatus::Ok) {
            reading.error = TransactionReport::outcome(records.at(i));
        } else {
            const PlannedRequest &r = requests.at(i);
            const ReadAnswerResult answer = ReadAnswer::fromResponse(
                r.functionCode, r.address, r.quantity, AduBuilder::parse(records.at(i).response, target.url.framing()).pdu);
            if (!answer.ok)
                reading.error = answer.error;
            else if (answer.answer.isBits())
                for (bool bit : answer.answer.bits)
                    reading.words.append(bit ? 1 : 0);
            else
                reading.words = answer.answer.registers;
        }
        readings.append(reading);
    }
    return readings;
}

} // namespace

int runExportMap(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Writes a device profile's register map for the tool that will poll the device: a Node-RED flow "
        "(node-red-contrib-modbus read nodes and function nodes that convert the values), a Telegraf "
        "[[inputs.modbus]] section, Home Assistant modbus: YAML, a prometheus-community modbus_exporter module, or "
        "CSV, one value a row. Every value of every table entry is written with its type, word order, scale and "
        "unit; reserved entries are left out. The profile's limits reach the tool's settings where it has them: "
        "the largest read (maxQuantity), the pause between requests (minGapMs) and after connecting (warmUpMs).\n"
        "With --verify TARGET it first reads every value once through the map, and refuses the export when a value "
        "is not finite or outside the min and max its entry declares, naming the entry (a \"not implemented\" "
        "sentinel is allowed and said). It only reads.\n"
        "Example, a profile drafted first (with mbscope simulate --profile conformance --listen tcp://127.0.0.1:5020 "
        "running):\n"
        "  mbscope scan --target tcp://127.0.0.1:5020 --map 1 --addresses 0-99 --no-optional --profile-out bench.json\n"
        "  mbscope export-map bench.json --to telegraf -o telegraf.conf --verify tcp://127.0.0.1:5020\n"
        "Exit status: 0 written, 1 --verify refused the map (or could not read it), 2 usage error or a profile "
        "that does not load."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("profile"),
                                 QStringLiteral("The device profile: a shipped name or a JSON file."));
    const QCommandLineOption to(QStringLiteral("to"),
                                QStringLiteral("The format: nodered, telegraf, homeassistant, modbus_exporter or csv."),
                                QStringLiteral("format"));
    const QCommandLineOption output(QStringList{QStringLiteral("o"), QStringLiteral("output")},
                                    QStringLiteral("Write to this file instead of standard output."), QStringLiteral("file"));
    const QCommandLineOption endpoint(QStringLiteral("endpoint"),
                                      QStringLiteral("Where the tool will reach the device (tcp://host:port, rtu-tcp://..., "
                                                     "rtu:///dev/ttyUSB0?baud=...); default: the profile's first endpoint "
                                                     "the format takes, else tcp://127.0.0.1:502."),
                                      QStringLiteral("url"));
    const QCommandLineOption unit(QStringLiteral("unit"),
                                  QStringLiteral("Only this unit of the profile (default: every unit)."), QStringLiteral("id"));
    const QCommandLineOption interval(QStringLiteral("interval"),
                                      QStringLiteral("How often the tool polls (default 1s)."), QStringLiteral("duration"),
                                      QStringLiteral("1s"));
    const QCommandLineOption verify(QStringLiteral("verify"),
                                    QStringLiteral("Read every value once from this target first (as --target of read) and "
                                                   "refuse the export when one is not finite or out of its range."),
                                    QStringLiteral("url"));
    const QCommandLineOption timeout(QStringLiteral("timeout"),
                                     QStringLiteral("Response timeout of each --verify read, and the timeout written into "
                                                    "the export (default 1000 ms)."),
                                     QStringLiteral("duration"), QStringLiteral("1000"));
    const QCommandLineOption force = OutputPath::forceOption();
    parser.addOptions({to, output, endpoint, unit, interval, verify, timeout, force});
    if (!parser.parse(arguments)) {
        err << "mbscope export-map: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "export-map");
        return ExitOk;
    }

    auto usage = [&err](const QString &message) {
        err << "mbscope export-map: " << message << '\n';
        return int(ExitUsage);
    };
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty())
        return usage(QStringLiteral("which profile? expected a shipped profile's name or a JSON file "
                                    "(mbscope export-map bench.json --to csv)"));
    if (positional.size() > 1)
        return usage(QStringLiteral("unexpected argument '%1': one profile only").arg(positional.at(1)));
    if (!parser.isSet(to))
        return usage(QStringLiteral("--to is missing: expected %1").arg(MapExporter::formatNames()));
    const auto format = MapExporter::formatFromName(parser.value(to));
    if (!format)
        return usage(QStringLiteral("--to '%1' is not a format: expected %2").arg(parser.value(to), MapExporter::formatNames()));

    const ProfileLoadResult loaded = ProfileLoader::load(positional.constFirst());
    if (!loaded.ok) {
        err << loaded.errorText() << '\n';
        return ExitUsage;
    }
    const DeviceProfile &profile = loaded.profile;

    std::optional<quint8> unitId;
    if (parser.isSet(unit)) {
        const IntegerResult id = parseInteger(QStringLiteral("--unit"), parser.value(unit), 1, 255);
        if (!id.ok)
            return usage(id.error);
        if (!profile.unit(quint8(id.value)))
            return usage(QStringLiteral("--unit %1: the profile has no such unit").arg(id.value));
        unitId = quint8(id.value);
    }
    MapExportInput input = MapExportInput::fromProfile(profile, unitId);
    if (input.points.isEmpty())
        return usage(QStringLiteral("%1 has no table entries to export").arg(profile.source));
    if (!input.tooLarge.isEmpty()) {
        // No tool can poll such a value: the device refuses the one read it needs.
        for (const QString &line : std::as_const(input.tooLarge))
            err << "mbscope export-map: " << profile.source << ": " << line << '\n';
        err << "mbscope export-map: refused: " << input.tooLarge.size()
            << " value(s) cannot be read whole within the device's limits.maxQuantity; nothing written\n";
        return ExitFailure;
    }
    const DurationResult every = parseDuration(parser.value(interval));
    if (!every.ok() || every.ns < Duration::Millisecond)
        return usage(QStringLiteral("--interval %1").arg(every.ok() ? QStringLiteral("is under 1 ms") : every.error));
    input.intervalMs = int(std::min<qint64>(every.ns / Duration::Millisecond, 24LL * 3600 * 1000));
    const DurationResult wait = parseDuration(parser.value(timeout));
    if (!wait.ok() || wait.ns < Duration::Millisecond)
        return usage(QStringLiteral("--timeout %1").arg(wait.ok() ? QStringLiteral("is under 1 ms") : wait.error));
    input.timeoutMs = int(std::min<qint64>(wait.ns / Duration::Millisecond, 600000));
    if (parser.isSet(endpoint)) {
        const LinkUrl::Result parsed = LinkUrl::parse(parser.value(endpoint));
        if (!parsed.url)
            return usage(QStringLiteral("--endpoint %1").arg(parsed.error));
        input.endpoint = *parsed.url;
    } else {
        input.endpoint = MapExporter::defaultEndpoint(profile, *format);
    }
    if (const QString why = MapExporter::unsupportedEndpoint(*format, input.endpoint); !why.isEmpty())
        return usage(QStringLiteral("--endpoint %1: %2").arg(input.endpoint.toString(), why));


    const QString path = parser.value(output);
    if (parser.isSet(output) && path != QLatin1String("-")) {
        const QString problem = OutputPath::problem(QStringLiteral("-o"), path, QStringLiteral("-o map.conf"), parser.isSet(force));
        if (!problem.isEmpty())
            return usage(problem);
    }

    if (parser.isSet(verify)) {
        const LinkUrl::Result parsed = LinkUrl::parse(parser.value(verify));
        if (!parsed.url)
            return usage(QStringLiteral("--verify %1").arg(parsed.error));
        TargetSettings target;
        target.url = input.paced(*parsed.url); // the device's gap, warm-up and hang-up, as its profile says
        target.timeoutMs = input.timeoutMs;
        const QList<MapVerdict> verdicts = MapVerifier::judge(input.points, input.blocks,
                                                              readBlocks(target, input.points, input.blocks));
        int bad = 0;
        for (const MapVerdict &v : verdicts) {
            const MapPoint &p = input.points.at(v.point);
            if (v.ok())
                continue;
            ++bad;
            err << "mbscope export-map: " << profile.source << ": unit " << int(p.unitId) << ' ' << p.tableKey() << ' '
                << p.address << " (" << p.label << "): " << v.problem << '\n';
        }
        if (bad > 0) {
            err << "mbscope export-map: refused: " << bad << " of " << verdicts.size() << " values read from "
                << target.url.toString() << " are not usable; nothing written\n";
            return ExitFailure;
        }
        err << "verified: " << verdicts.size() << " values read from " << target.url.toString()
            << " are finite and inside their ranges\n";
    }

    const QString text = MapExporter::write(*format, input);
    if (!parser.isSet(output) || path == QLatin1String("-")) {
        out << text;
        return ExitOk;
    }
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(text.toUtf8()) < 0) {
        err << "mbscope export-map: -o: cannot write " << path << ": " << file.errorString() << '\n';
        return ExitUsage;
    }
    err << "wrote " << input.points.size() << (input.points.size() == 1 ? " value in " : " values in ") << input.blocks.size()
        << (input.blocks.size() == 1 ? " block to " : " blocks to ") << path << " ("
        << MapExporter::formatName(*format) << ")\n";
    return ExitOk;
}

} // namespace mbscope::app
