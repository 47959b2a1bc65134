#include "scan/scancommand.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "common/interruptwatcher.h"
#include "common/outputpath.h"
#include "common/progressline.h"
#include "scan/scanoptions.h"
#include "scan/scanline.h"
#include "scan/scanreport.h"
#include "scan/scantiming.h"

#include "discovery/mapscanner.h"
#include "discovery/profiledraft.h"
#include "discovery/scanwatches.h"
#include "discovery/unitscanner.h"
#include "protocol/framing.h"
#include "traffic/trafficrecording.h"
#include "transport/linkurl.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

// Options whose file must be writable before the first request: a scan may take minutes
// (OutputPath's policy: an existing file only with --force).
bool checkWritable(const QString &option, const QString &path, bool force, QTextStream &err)
{
    if (path.isEmpty())
        return true;
    const QString problem = OutputPath::problem(option, path, option + QStringLiteral(" FILE"), force);
    if (!problem.isEmpty()) {
        err << "mbscope scan: " << problem << '\n';
        return false;
    }
    return true;
}

struct Common {
    LinkUrl url;
    bool json = false;
    bool all = false;
    QString watchesPath;
    qint64 maxTimeMs = 600000;
    ScanRecord record;
};

// --profile-out FILE for the scans that merge into an existing profile (--timing's limits, the
// unit scan's units): read and checked now, so that a bad file costs no scan.
bool profileToMerge(const QString &path, const char *what, QTextStream &err)
{
    QByteArray unused;
    return path.isEmpty() || readProfileToMerge(path, what, &unused, err);
}

int runUnits(const Common &common, UnitScanSettings settings, const QString &profilePath, QTextStream &out, QTextStream &err)
{
    settings.url = common.url;
    settings.maxDurationMs = common.maxTimeMs;
    settings.keepTargetPace();
    if (const QString problem = settings.problem(); !problem.isEmpty()) {
        err << "mbscope scan: " << problem << '\n';
        return ExitUsage;
    }
    TrafficRecording recording;
    if (!openRecording(recording, common.record.settings, common.record.metadata, QStringLiteral("scan"), err))
        return ExitUsage;
    FrameLog frames;
    if (!openFrameLog(frames, common.record.print, QStringLiteral("scan"), err))
        return ExitUsage;
    UnitScanner scanner;
    if (recording.isOpen())
        scanner.channel()->setTrafficLog(recording.log());
    QObject::connect(scanner.channel(), &ProbeChannel::framesLogged, &frames, &FrameLog::addFrames);
    InterruptWatcher interrupts;
    ProgressLine line;
    frames.setProgressLine(&line);
    QEventLoop loop;
    JobEnd end = JobEnd::Completed;
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &scanner, &UnitScanner::stop);
    QObject::connect(&scanner, &UnitScanner::progressChanged, &loop, [&](const JobProgress &p) {
        line.show(ScanReport::progressText(QStringLiteral("ids"), p));
    });
    QObject::connect(&scanner, &UnitScanner::probed, &loop, [&](const UnitProbe &p) {
        if (p.isPresent() && line.isEnabled()) {
            line.clear();
            err << "unit " << p.unit << ": " << p.summary() << '\n';
            err.flush();
        }
    });
    QObject::connect(&scanner, &UnitScanner::finished, &loop, [&](JobEnd how) {
        end = how;
        loop.quit();
    });
    if (line.isEnabled())
        line.show(QStringLiteral("scanning %1 ids, at most %2  (Ctrl-C stops)")
                      .arg(settings.idCount())
                      .arg(ScanReport::durationText(qMin(settings.worstCaseMs(), settings.maxDurationMs))));
    scanner.start(settings);
    loop.exec();
    line.clear();
    scanner.channel()->setTrafficLog(nullptr); // the last frames reach the journal
    finishRecording(recording, err);

    const QList<UnitProbe> &results = scanner.results();
    const JobProgress progress = scanner.progress();
    if (end == JobEnd::LinkError && progress.found == 0 && !results.isEmpty()) {
        err << "mbscope scan: " << results.constLast().problem << '\n';
        if (!common.json)
            return ExitLinkError;
    }
    if (!common.watchesPath.isEmpty()) {
        QList<WatchDefinition> watches;
        for (const UnitProbe &p : results)
            watches += ScanWatches::fromProbe(settings, p);
        if (!writeScanFile(common.watchesPath, ScanWatches::toJson(watches), "watch definitions", err))
            return ExitUsage;
    }
    if (!profilePath.isEmpty()
        && !mergeIntoProfileFile(profilePath, [&](const QByteArray &profile, QString *said, QString *problem) {
               const QByteArray merged = ProfileDraft::mergeUnits(profile, results, said, problem);
               if (end != JobEnd::Completed) // what the others got is of the ids asked only
                   *said += QStringLiteral(" (from %1 of %2 ids: %3)")
                                .arg(results.size())
                                .arg(settings.idCount())
                                .arg(end == JobEnd::Stopped ? QStringLiteral("stopped") : QStringLiteral("cut short"));
               return merged;
           }, "profile units", err))
        return ExitUsage;
    if (common.json)
        out << QJsonDocument(ScanReport::unitsJson(settings, results, progress, end)).toJson(QJsonDocument::Indented);
    else
        out << ScanReport::unitsText(settings, results, progress, end, common.all);
    out.flush();
    if (end == JobEnd::LinkError && progress.found == 0)
        return ExitLinkError;
    // Only 0 or 255 answering (a gateway for itself) is no device found.
    return ScanReport::devicesFound(results) > 0 ? ExitOk : ExitFailure;
}

int runMap(const Common &common, MapScanSettings settings, const QString &profilePath, QTextStream &out, QTextStream &err)
{
    settings.url = common.url;
    settings.maxDurationMs = common.maxTimeMs;
    if (const QString problem = settings.problem(); !problem.isEmpty()) {
        err << "mbscope scan: " << problem << '\n';
        return ExitUsage;
    }
    TrafficRecording recording;
    if (!openRecording(recording, common.record.settings, common.record.metadata, QStringLiteral("scan"), err))
        return ExitUsage;
    FrameLog frames;
    if (!openFrameLog(frames, common.record.print, QStringLiteral("scan"), err))
        return ExitUsage;
    MapScanner scanner;
    if (recording.isOpen())
        scanner.channel()->setTrafficLog(recording.log());
    QObject::connect(scanner.channel(), &ProbeChannel::framesLogged, &frames, &FrameLog::addFrames);
    InterruptWatcher interrupts;
    ProgressLine line;
    frames.setProgressLine(&line);
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &scanner, &MapScanner::stop);
    QObject::connect(&scanner, &MapScanner::progressChanged, &scanner,
                     [&](const JobProgress &p) { line.show(ScanReport::progressText(QStringLiteral("addresses"), p)); });
    QElapsedTimer clock;
    clock.start();
    const std::optional<RegisterMap> map = scanner.run(settings);
    line.clear();
    scanner.channel()->setTrafficLog(nullptr); // the last frames reach the journal
    finishRecording(recording, err);
    const qint64 elapsedMs = clock.elapsed();
    if (!map)
        return ExitUsage;
    bool anything = false;
    for (const TableMap &t : map->tables)
        anything = anything || !t.blocks.isEmpty();
    if (scanner.end() == JobEnd::LinkError && !anything) {
        err << "mbscope scan: the link failed: "
            << (scanner.linkProblem().isEmpty() ? settings.url.toString() + QStringLiteral(" cannot be reached") : scanner.linkProblem())
            << '\n';
        return ExitLinkError;
    }
    bool gatewayOnly = !map->tables.isEmpty();
    for (const TableMap &t : map->tables)
        gatewayOnly = gatewayOnly && t.gatewayException != 0;
    if (gatewayOnly)
        err << "mbscope scan: unit " << map->unit << " is not there: a gateway answered every read with exception "
            << QString::number(map->tables.constFirst().gatewayException, 16).toUpper().rightJustified(2, QLatin1Char('0')) << '\n';
    // Nothing found is no map: no draft, no watches (a draft of an absent unit listed functions it never had).
    if (!anything && (!profilePath.isEmpty() || !common.watchesPath.isEmpty()))
        err << "mbscope scan: no address answered: no " << (profilePath.isEmpty() ? "watch definitions" : "profile draft")
            << " written\n";
    if (anything && !profilePath.isEmpty()) {
        const QString name = QFileInfo(profilePath).completeBaseName();
        if (!writeScanFile(profilePath, ProfileDraft::toJson(*map, name, settings.url.toString()), "profile draft", err))
            return ExitUsage;
    }
    if (anything && !common.watchesPath.isEmpty()
        && !writeScanFile(common.watchesPath, ScanWatches::toJson(ScanWatches::fromMap(settings.url.toString(), *map)),
                      "watch definitions", err))
        return ExitUsage;
    if (common.json)
        out << QJsonDocument(ScanReport::mapJson(*map, scanner.end(), elapsedMs)).toJson(QJsonDocument::Indented);
    else
        out << ScanReport::mapText(*map, scanner.end(), elapsedMs);
    out.flush();
    return anything ? ExitOk : ExitFailure;
}

} // namespace

int runScan(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Finds what is on a link, sending only reads. By default asks every unit id of a range the same harmless read "
        "(03 at address 0, one register) and says what each did: answers; exception (which); gateway path unavailable "
        "(0A) or gateway target failed (0B); silent; answered with another unit's id; garbage (wrong CRC, malformed); "
        "echo of the request. With --map UNIT it finds which addresses of each table the unit has (exception 02 as the "
        "signal: galloping and bisection over blocks), the largest quantity each read function takes (exception 03), "
        "and which optional functions it answers (07, 08, 0B, 0C, 11, 14, 17, 18, 2B/0E); --profile-out saves the map "
        "as a device profile draft that mbscope simulate --profile FILE serves.\n"
        "With --line (a serial port) it tries baud rates, parities and stop bits with the read until CRC-valid answers "
        "come back, and says what was tried and what worked.\n"
        "With --timing UNIT it measures the unit's timing limits and prints settings ready to use (a watch link's "
        "gapMs and timeoutMs, Telegraf's modbus input pause_between_requests and pause_after_connect); --profile-out "
        "merges what it measured (minGapMs, warmUpMs, maxClients and extraClients, maxQuantity, closesAfterAnswer) into an existing profile's limits.\n"
        "Examples (with mbscope simulate --profile conformance --listen tcp://127.0.0.1:5020 running):\n"
        "  mbscope scan --target tcp://127.0.0.1:5020 --units 1-10\n"
        "  mbscope scan --target tcp://127.0.0.1:5020 --map 1 --profile-out draft.json\n"
        "  mbscope scan --target tcp://127.0.0.1:5020 --timing 1 --profile-out draft.json\n"
        "Every scan is bounded (--max-time, --max-requests), shows its progress and the time left on a terminal, and "
        "stops on Ctrl-C with what it found so far.\n"
        "Exit status: 0 something was found, 1 nothing was, 2 usage or link error."));
    parser.addHelpOption();
    const QCommandLineOption targetOpt(QStringLiteral("target"),
                                       QStringLiteral("The link: tcp://host:502, rtu-tcp://host:4001, rtu:///dev/ttyUSB0?baud=9600..."),
                                       QStringLiteral("URL"));
    const QCommandLineOption unitsOpt(QStringLiteral("units"), QStringLiteral("Unit ids to ask (default 1-247)."),
                                      QStringLiteral("FIRST-LAST"));
    const QCommandLineOption allIdsOpt(QStringLiteral("all-ids"),
                                       QStringLiteral("Ask 0-255: the unit addresses 1-247, and 0 and 248-255, which only an MBAP server or gateway may "
                                                      "answer (tcp, tls and udp only: unit 0 is a broadcast on serial framings)."));
    const QCommandLineOption functionOpt(QStringLiteral("function"), QStringLiteral("The read asked: 1, 2, 3 (default) or 4."),
                                         QStringLiteral("FC"));
    const QCommandLineOption addressOpt(QStringLiteral("address"), QStringLiteral("Its address (default 0)."), QStringLiteral("ADDR"));
    const QCommandLineOption quantityOpt(QStringLiteral("quantity"), QStringLiteral("Its quantity (default 1)."), QStringLiteral("N"));
    const QCommandLineOption timeoutOpt(QStringLiteral("timeout"),
                                        QStringLiteral("How long each request waits (default 200ms; 500ms with --map; 1s with --timing)."),
                                        QStringLiteral("TIME"));
    const QCommandLineOption gapOpt(QStringLiteral("gap"),
                                    QStringLiteral("Quiet time between one answer (or timeout) and the next request (default 20ms; 0 with --map)."),
                                    QStringLiteral("TIME"));
    const QCommandLineOption maxTimeOpt(QStringLiteral("max-time"), QStringLiteral("Stop the scan, of any kind, after this long (default 10min): a request that would end after it is not sent."),
                                        QStringLiteral("TIME"));
    const QCommandLineOption allOpt(QStringLiteral("all"), QStringLiteral("One line per id (by default ids that found nothing are grouped in runs of the same result)."));
    const QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print the result as JSON."));
    const QCommandLineOption watchesOpt(QStringLiteral("watches"),
                                        QStringLiteral("Write what was found as watch definitions (a JSON array) to FILE."),
                                        QStringLiteral("FILE"));
    const QCommandLineOption mapOpt(QStringLiteral("map"), QStringLiteral("Map the registers of this unit."), QStringLiteral("UNIT"));
    const QCommandLineOption addressesOpt(QStringLiteral("addresses"),
                                          QStringLiteral("--map: the addresses searched in each table (default 0-999)."),
                                          QStringLiteral("FIRST-LAST"));
    const QCommandLineOption tablesOpt(QStringLiteral("tables"),
                                       QStringLiteral("--map: the read functions of the tables mapped (default 1,2,3,4)."),
                                       QStringLiteral("LIST"));
    const QCommandLineOption noOptionalOpt(QStringLiteral("no-optional"), QStringLiteral("--map: do not ask the optional functions."));
    const QCommandLineOption profileOutOpt(QStringLiteral("profile-out"),
                                           QStringLiteral("--map: save the map as a device profile draft (docs/profiles.md). --timing: merge "
                                                          "the limits measured into this existing profile's \"limits\". A "
                                                          "unit scan: add the units that answered to this existing "
                                                          "profile, and its \"unknownUnit\" from what the others got."),
                                           QStringLiteral("FILE"));
    const QCommandLineOption stepOpt(QStringLiteral("step"),
                                     QStringLiteral("--map: between blocks ask one address in N (default 1: every address; "
                                                    "16 finds every block of 16 or more in a sixteenth of the requests)."),
                                     QStringLiteral("N"));
    const QCommandLineOption maxRequestsOpt(QStringLiteral("max-requests"),
                                            QStringLiteral("--map: stop after this many requests (default 20000)."), QStringLiteral("N"));
    const QCommandLineOption lineOpt(QStringLiteral("line"),
                                     QStringLiteral("Find a serial port's line settings: try baud rates, parities and stop bits "
                                                    "with the read until CRC-valid answers come back."));
    const QCommandLineOption baudsOpt(QStringLiteral("bauds"),
                                      QStringLiteral("--line: baud rates to try (default 9600,19200,38400,57600,115200,4800,2400,1200)."),
                                      QStringLiteral("LIST"));
    const QCommandLineOption paritiesOpt(QStringLiteral("parities"), QStringLiteral("--line: parities to try (default E,N,O)."),
                                         QStringLiteral("LIST"));
    const QCommandLineOption stopBitsOpt(QStringLiteral("stop-bits"), QStringLiteral("--line: stop bits to try (default 1,2)."),
                                         QStringLiteral("LIST"));
    const QCommandLineOption firstOpt(QStringLiteral("first"), QStringLiteral("--line: stop at the first setting that answers."));
    const QCommandLineOption timingOpt(QStringLiteral("timing"),
                                       QStringLiteral("Measure this unit's timing limits: first answer after connecting, shortest "
                                                      "gap, largest read, pipelining, TCP clients at once; prints settings."),
                                       QStringLiteral("UNIT"));
    const QCommandLineOption clientsOpt(QStringLiteral("clients"), QStringLiteral("--timing: most TCP clients tried (default 16)."),
                                        QStringLiteral("N"));
    const RecordOptions recordOptions;
    recordOptions.addTo(parser);
    const PrintOptions printOptions(false);
    printOptions.addTo(parser);
    parser.addOptions({lineOpt, baudsOpt, paritiesOpt, stopBitsOpt, firstOpt, timingOpt, clientsOpt});
    parser.addOptions({targetOpt, unitsOpt, allIdsOpt, functionOpt, addressOpt, quantityOpt, timeoutOpt, gapOpt, maxTimeOpt,
                       allOpt, jsonOpt, watchesOpt, mapOpt, addressesOpt, tablesOpt, noOptionalOpt, profileOutOpt,
                       maxRequestsOpt, stepOpt});
    if (!parser.parse(arguments)) {
        err << "mbscope scan: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "scan");
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "mbscope scan: unexpected argument '" << parser.positionalArguments().constFirst()
            << "': the link is given with --target URL\n";
        return ExitUsage;
    }
    if (!parser.isSet(targetOpt)) {
        err << "mbscope scan: no --target given: e.g. mbscope scan --target tcp://127.0.0.1:5020\n";
        return ExitUsage;
    }
    const LinkUrl::Result parsed = LinkUrl::parse(parser.value(targetOpt));
    if (!parsed.url) {
        err << "mbscope scan: --target: " << parsed.error << '\n';
        return ExitUsage;
    }
    Common common;
    common.url = *parsed.url;
    common.json = parser.isSet(jsonOpt);
    common.all = parser.isSet(allOpt);
    common.watchesPath = parser.value(watchesOpt);
    // --force (RecordOptions') covers --record, --watches and --profile-out alike.
    if (!recordOptions.read(parser, QStringLiteral("scan"), common.record.settings, err, true))
        return ExitUsage;
    const bool force = common.record.settings.overwrite;
    if (!printOptions.read(parser, QStringLiteral("scan"), force, common.record.print, err))
        return ExitUsage;
    common.record.metadata = commandMetadata(QStringLiteral("scan"), arguments);
    common.record.metadata.target = common.url.toString();
    const ScanOptionReader read{parser, err};
    if (!read.durationMs(maxTimeOpt, 1, 24LL * 3600 * 1000, &common.maxTimeMs) || !checkWritable(QStringLiteral("--watches"), common.watchesPath, force, err))
        return ExitUsage;
    const bool map = parser.isSet(mapOpt);
    qint64 timeoutMs = map ? 500 : (common.url.responseTimeoutMs > 0 ? common.url.responseTimeoutMs : 200);
    qint64 gapMs = map ? 0 : 20;
    if (!read.durationMs(timeoutOpt, 1, 3600000, &timeoutMs) || !read.durationMs(gapOpt, 0, 3600000, &gapMs))
        return ExitUsage;

    if (parser.isSet(timingOpt)) {
        if (map || parser.isSet(lineOpt)) {
            err << "mbscope scan: --timing, --map and --line are three scans: give one\n";
            return ExitUsage;
        }
        TimingScanSettings settings;
        settings.url = common.url;
        qint64 unit = 1;
        qint64 function = 3;
        qint64 address = 0;
        qint64 clients = settings.maxClients;
        if (!read.integer(timingOpt, 0, 255, &unit) || !read.integer(functionOpt, 1, 4, &function)
            || !read.integer(addressOpt, 0, 65535, &address) || !read.integer(clientsOpt, 1, 256, &clients))
            return ExitUsage;
        settings.unit = quint8(unit);
        settings.function = quint8(function);
        settings.address = quint16(address);
        settings.maxClients = int(clients);
        settings.timeoutMs = parser.isSet(timeoutOpt) ? int(timeoutMs) : 1000;
        settings.maxDurationMs = common.maxTimeMs;
        const QString profilePath = parser.value(profileOutOpt);
        if (!profileToMerge(profilePath, "with --timing the limits are", err))
            return ExitUsage;
        return runTimingScan(settings, common.json, common.record, profilePath, out, err);
    }
    if (parser.isSet(clientsOpt)) {
        err << "mbscope scan: --clients belongs to --timing UNIT\n";
        return ExitUsage;
    }
    if (parser.isSet(lineOpt)) {
        if (map) {
            err << "mbscope scan: --line and --map are two scans: give one\n";
            return ExitUsage;
        }
        if (parser.isSet(profileOutOpt)) {
            err << "mbscope scan: --profile-out belongs to --map, --timing and the unit scan: --line finds a serial "
                << "line's settings, which a device profile does not hold\n";
            return ExitUsage;
        }
        LineScanSettings settings;
        settings.url = common.url;
        settings.maxDurationMs = common.maxTimeMs;
        settings.timeoutMs = int(timeoutMs);
        settings.stopAtFirst = parser.isSet(firstOpt);
        QList<qint64> bauds;
        QList<qint64> stops;
        qint64 function = 3;
        qint64 address = 0;
        qint64 quantity = 1;
        if (!read.integers(baudsOpt, 50, 4000000, &bauds) || !read.integers(stopBitsOpt, 1, 2, &stops)
            || !read.integer(functionOpt, 1, 4, &function) || !read.integer(addressOpt, 0, 65535, &address)
            || !read.integer(quantityOpt, 1, 125, &quantity))
            return ExitUsage;
        if (!bauds.isEmpty()) {
            settings.bauds.clear();
            for (const qint64 b : std::as_const(bauds))
                settings.bauds.append(int(b));
        }
        if (!stops.isEmpty()) {
            settings.stopBits.clear();
            for (const qint64 b : std::as_const(stops))
                settings.stopBits.append(int(b));
        }
        if (parser.isSet(paritiesOpt)) {
            settings.parities.clear();
            for (const QString &p : parser.value(paritiesOpt).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                const QString u = p.trimmed().toUpper();
                if (u != QLatin1String("N") && u != QLatin1String("E") && u != QLatin1String("O")) {
                    err << "mbscope scan: --parities '" << p << "': expected N, E or O\n";
                    return ExitUsage;
                }
                settings.parities.append(u.at(0).toLatin1());
            }
        }
        if (parser.isSet(unitsOpt)) {
            int first = 1;
            int last = 1;
            if (!read.range(unitsOpt, 1, 247, &first, &last))
                return ExitUsage;
            for (int u = first; u <= last; ++u)
                settings.units.append(quint8(u));
        }
        settings.function = quint8(function);
        settings.address = quint16(address);
        settings.quantity = quint16(quantity);
        return runLineScan(settings, common.json, common.record, out, err);
    }
    for (const QCommandLineOption *lineOnly : {&baudsOpt, &paritiesOpt, &stopBitsOpt, &firstOpt}) {
        if (parser.isSet(*lineOnly)) {
            err << "mbscope scan: --" << lineOnly->names().constFirst() << " belongs to --line\n";
            return ExitUsage;
        }
    }

    if (map) {
        MapScanSettings settings;
        qint64 unit = 1;
        qint64 maxRequests = settings.maxRequests;
        qint64 step = 1;
        QList<qint64> tables{1, 2, 3, 4};
        if (!read.integer(mapOpt, 0, 255, &unit) || !read.range(addressesOpt, 0, 65535, &settings.firstAddress, &settings.lastAddress)
            || !read.integers(tablesOpt, 1, 4, &tables) || !read.integer(maxRequestsOpt, 1, 10'000'000, &maxRequests) || !read.integer(stepOpt, 1, 2000, &step))
            return ExitUsage;
        const QString profilePath = parser.value(profileOutOpt);
        if (!checkWritable(QStringLiteral("--profile-out"), profilePath, force, err))
            return ExitUsage;
        settings.unit = quint8(unit);
        settings.functions.clear();
        for (const qint64 t : std::as_const(tables))
            settings.functions.append(quint8(t));
        settings.optionalFunctions = !parser.isSet(noOptionalOpt);
        settings.timeoutMs = int(timeoutMs);
        settings.gapMs = int(gapMs);
        settings.maxRequests = int(maxRequests);
        settings.step = int(step);
        return runMap(common, settings, profilePath, out, err);
    }

    for (const QCommandLineOption *mapOnly : {&addressesOpt, &tablesOpt, &noOptionalOpt, &maxRequestsOpt, &stepOpt}) {
        if (parser.isSet(*mapOnly)) {
            err << "mbscope scan: --" << mapOnly->names().constFirst() << " belongs to --map UNIT\n";
            return ExitUsage;
        }
    }
    const QString unitsProfile = parser.value(profileOutOpt);
    if (!profileToMerge(unitsProfile, "the units found are", err))
        return ExitUsage;
    UnitScanSettings settings;
    if (parser.isSet(allIdsOpt)) {
        if (parser.isSet(unitsOpt)) {
            err << "mbscope scan: --units and --all-ids both say which ids: give one\n";
            return ExitUsage;
        }
        if (const Framing framing = common.url.framing(); framing != Framing::Tcp && framing != Framing::Udp) {
            // Serial Line V1.02, 2.2: 0 is the broadcast address (no unit answers it), 1-247 are
            // the units' addresses, 248-255 are reserved. Only MBAP asks 0 and 255 (the server).
            err << "mbscope scan: --all-ids asks 0-255, which only an MBAP target (tcp://, tls://, udp://) has; on "
                << framingName(framing) << " framing the unit ids are 1-247 (0 is the broadcast, which no unit answers; "
                << "248-255 are reserved): leave --all-ids out to ask 1-247\n";
            return ExitUsage;
        }
        settings.firstUnit = 0;
        settings.lastUnit = 255;
    }
    qint64 function = 3;
    qint64 address = 0;
    qint64 quantity = 1;
    if (!read.range(unitsOpt, 0, 255, &settings.firstUnit, &settings.lastUnit) || !read.integer(functionOpt, 1, 4, &function)
        || !read.integer(addressOpt, 0, 65535, &address) || !read.integer(quantityOpt, 1, 2000, &quantity))
        return ExitUsage;
    settings.function = quint8(function);
    settings.address = quint16(address);
    settings.quantity = quint16(quantity);
    settings.timeoutMs = int(timeoutMs);
    settings.gapMs = int(gapMs);
    return runUnits(common, settings, unitsProfile, out, err);
}

} // namespace mbscope::app
