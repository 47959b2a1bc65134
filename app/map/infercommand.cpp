#include "map/infercommand.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "map/inferreport.h"
#include "common/interruptwatcher.h"
#include "common/outputpath.h"
#include "common/printoptions.h"
#include "common/progressline.h"
#include "common/recordoptions.h"
#include "scan/scanoptions.h"
#include "common/targetoptions.h"

#include "discovery/mapscanner.h"
#include "inference/blockinferrer.h"
#include "inference/blocksampler.h"
#include "inference/inferencedraft.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

bool parseBlock(const QString &text, BlockRequest *block, QTextStream &err)
{
    const QStringList parts = text.split(QLatin1Char(':'));
    if (parts.size() != 3) {
        err << "mbscope infer: --block '" << text << "': expected FC:ADDRESS:COUNT (e.g. 4:0:80, 3:0x9C40:70)\n";
        return false;
    }
    const IntegerResult fc = parseInteger(QStringLiteral("--block function"), parts.at(0), 1, 4, QStringLiteral("a read function"));
    const IntegerResult address = parseInteger(QStringLiteral("--block address"), parts.at(1), 0, 65535);
    const IntegerResult count = parseInteger(QStringLiteral("--block count"), parts.at(2), 1, 2000);
    for (const IntegerResult *r : {&fc, &address, &count}) {
        if (!r->ok) {
            err << "mbscope infer: --block '" << text << "': " << r->error << '\n';
            return false;
        }
    }
    if (address.value + count.value > 65536) {
        err << "mbscope infer: --block '" << text << "': addresses " << address.value << '-' << address.value + count.value - 1
            << " run past 65535\n";
        return false;
    }
    *block = BlockRequest{quint8(fc.value), quint16(address.value), int(count.value)};
    return true;
}

} // namespace

int runInfer(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Proposes what a device's registers mean, from their values alone. Reads blocks of registers many times (reads "
        "only: 01-04) and, for each group of registers, proposes a type (u16, i16, u32, i32, u64, f32, f64, ASCII "
        "string, bit field) and word/byte order (ABCD, CDAB, BADC, DCBA), a scale (a power of ten, or a SunSpec-style "
        "scale-factor register), a unit where the values suggest one, and a kind (constant, counter, measurement, "
        "status bits), each with a confidence and its evidence in words. The blocks are those a map scan of the unit "
        "finds (as mbscope scan --map does), or those given with --block. --out writes the guesses as a device "
        "profile draft that mbscope simulate --profile FILE serves, each entry's description marked as a guess.\n"
        "Examples (with mbscope simulate --profile conformance --listen tcp://127.0.0.1:5020 running):\n"
        "  mbscope infer tcp://127.0.0.1:5020 --block 4:0:40 --samples 20 --interval 200ms\n"
        "  mbscope infer tcp://127.0.0.1:5020 --duration 5s --out draft.json\n"
        "Exit status: 0 something was sampled, 1 nothing could be read, 2 usage or link error."));
    parser.addHelpOption();
    const TargetOptions targetOptions;
    targetOptions.addTo(parser);
    const QCommandLineOption unitOpt(QStringLiteral("unit"), QStringLiteral("The unit id (default 1)."), QStringLiteral("N"));
    const QCommandLineOption blockOpt(QStringLiteral("block"),
                                      QStringLiteral("A block to sample: read function (1-4), first address, count, e.g. "
                                                     "4:0:80 (repeatable). Without it a map scan finds the blocks."),
                                      QStringLiteral("FC:ADDRESS:COUNT"));
    const QCommandLineOption addressesOpt(QStringLiteral("addresses"),
                                          QStringLiteral("Without --block: the addresses the map scan searches (default 0-999)."),
                                          QStringLiteral("FIRST-LAST"));
    const QCommandLineOption tablesOpt(QStringLiteral("tables"),
                                       QStringLiteral("Without --block: the read functions of the tables mapped (default 1,2,3,4)."),
                                       QStringLiteral("LIST"));
    const QCommandLineOption samplesOpt(QStringLiteral("samples"), QStringLiteral("How many times each block is read (default 30)."),
                                        QStringLiteral("N"));
    const QCommandLineOption durationOpt(QStringLiteral("duration"),
                                         QStringLiteral("Sample for this long instead (samples = duration / interval)."),
                                         QStringLiteral("TIME"));
    const QCommandLineOption intervalOpt(QStringLiteral("interval"),
                                         QStringLiteral("From one round of reads to the next (default 1s)."), QStringLiteral("TIME"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print the guesses as JSON."));
    const QCommandLineOption outOpt(QStringLiteral("out"),
                                    QStringLiteral("Write the guesses as a device profile draft (docs/profiles.md) to FILE."),
                                    QStringLiteral("FILE"));
    parser.addOptions({unitOpt, blockOpt, addressesOpt, tablesOpt, samplesOpt, durationOpt, intervalOpt, jsonOpt, outOpt});
    const RecordOptions recordOptions; // --record, and --force (for --out too)
    recordOptions.addTo(parser);
    const PrintOptions printOptions(false);
    printOptions.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope infer: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "infer");
        return ExitOk;
    }
    TargetSettings target;
    if (!targetOptions.read(parser, QStringLiteral("infer"), target, err,
                            QStringLiteral("blocks are given with --block FC:ADDRESS:COUNT")))
        return ExitUsage;
    const ScanOptionReader read{parser, err, QStringLiteral("infer")};
    qint64 unit = 1;
    qint64 samples = 30;
    qint64 intervalMs = 1000;
    qint64 durationMs = 0;
    QList<qint64> tables{1, 2, 3, 4};
    MapScanSettings scan;
    if (!read.integer(unitOpt, 0, 255, &unit) || !read.integer(samplesOpt, 2, 100000, &samples)
        || !read.durationMs(intervalOpt, 1, 3600000, &intervalMs) || !read.durationMs(durationOpt, 1, 7LL * 24 * 3600 * 1000, &durationMs)
        || !read.integers(tablesOpt, 1, 4, &tables) || !read.range(addressesOpt, 0, 65535, &scan.firstAddress, &scan.lastAddress))
        return ExitUsage;
    if (parser.isSet(samplesOpt) && parser.isSet(durationOpt)) {
        err << "mbscope infer: --samples and --duration both say how long to sample: give one\n";
        return ExitUsage;
    }
    if (parser.isSet(durationOpt)) {
        samples = durationMs / intervalMs;
        if (samples < 2) {
            err << "mbscope infer: --duration " << parser.value(durationOpt) << " holds fewer than two --interval "
                << intervalMs << " ms: nothing could be seen to move\n";
            return ExitUsage;
        }
    }
    QList<BlockRequest> blocks;
    for (const QString &text : parser.values(blockOpt)) {
        BlockRequest b;
        if (!parseBlock(text, &b, err))
            return ExitUsage;
        blocks.append(b);
    }
    if (!blocks.isEmpty() && (parser.isSet(addressesOpt) || parser.isSet(tablesOpt))) {
        err << "mbscope infer: --" << (parser.isSet(addressesOpt) ? "addresses" : "tables")
            << " says where a map scan searches, and --block gives the blocks: give one\n";
        return ExitUsage;
    }
    const QString outPath = parser.value(outOpt);
    if (!outPath.isEmpty()) {
        const QString problem = OutputPath::problem(QStringLiteral("--out"), outPath, QStringLiteral("--out FILE"), parser.isSet(QStringLiteral("force")));
        if (!problem.isEmpty()) {
            err << "mbscope infer: " << problem << '\n';
            return ExitUsage;
        }
    }

    RecordSettings record;
    if (!recordOptions.read(parser, QStringLiteral("infer"), record, err, !outPath.isEmpty()))
        return ExitUsage;
    PrintSettings print;
    if (!printOptions.read(parser, QStringLiteral("infer"), parser.isSet(QStringLiteral("force")), print, err))
        return ExitUsage;
    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("infer"), arguments);
    metadata.target = target.url.toString();
    if (!openRecording(recording, record, metadata, QStringLiteral("infer"), err))
        return ExitUsage;
    FrameLog frames;
    if (!openFrameLog(frames, print, QStringLiteral("infer"), err))
        return ExitUsage;

    InterruptWatcher interrupts;
    ProgressLine line;
    frames.setProgressLine(&line);
    int maxQuantity = 125;
    if (blocks.isEmpty()) {
        scan.url = target.url;
        scan.unit = quint8(unit);
        scan.functions.clear();
        for (const qint64 t : std::as_const(tables))
            scan.functions.append(quint8(t));
        scan.optionalFunctions = false;
        scan.timeoutMs = target.timeoutMs;
        if (const QString problem = scan.problem(); !problem.isEmpty()) {
            err << "mbscope infer: " << problem << '\n';
            return ExitUsage;
        }
        MapScanner scanner;
        if (recording.isOpen())
            scanner.channel()->setTrafficLog(recording.log());
        QObject::connect(scanner.channel(), &ProbeChannel::framesLogged, &frames, &FrameLog::addFrames);
        QObject::connect(&interrupts, &InterruptWatcher::interrupted, &scanner, &MapScanner::stop);
        line.show(QStringLiteral("mapping unit %1 (addresses %2-%3)").arg(unit).arg(scan.firstAddress).arg(scan.lastAddress));
        const std::optional<RegisterMap> map = scanner.run(scan);
        line.clear();
        if (recording.isOpen())
            scanner.channel()->setTrafficLog(nullptr); // its last frames, before the sampler's

        if (!map)
            return ExitUsage;
        if (interrupts.isInterrupted()) {
            // Ctrl-C in the map scan ends the run: there is nothing sampled to infer from.
            finishRecording(recording, err);
            err << "mbscope infer: stopped (Ctrl-C) during the map scan of unit " << unit << ": nothing sampled, nothing inferred\n";
            return ExitFailure;
        }
        SampleSettings found;
        found.takeBlocks(*map);
        maxQuantity = found.maxQuantity;
        blocks = found.blocks;
        if (blocks.isEmpty()) {
            finishRecording(recording, err);
            if (scanner.end() == JobEnd::LinkError) {
                err << "mbscope infer: the link failed: "
                    << (scanner.linkProblem().isEmpty() ? target.url.toString() + QStringLiteral(" cannot be reached")
                                                        : scanner.linkProblem())
                    << '\n';
                return ExitLinkError;
            }
            err << "mbscope infer: the map scan of unit " << unit << " found no addresses in " << scan.firstAddress << '-'
                << scan.lastAddress << ": give blocks with --block FC:ADDRESS:COUNT\n";
            return ExitFailure;
        }
        err << "mbscope infer: the map scan found " << blocks.size() << " block" << (blocks.size() == 1 ? "" : "s") << '\n';
    }

    SampleSettings settings;
    settings.url = target.url;
    settings.unit = quint8(unit);
    settings.blocks = blocks;
    settings.samples = int(samples);
    settings.intervalMs = int(intervalMs);
    settings.timeoutMs = target.timeoutMs;
    settings.maxQuantity = maxQuantity;
    BlockSampler sampler;
    if (recording.isOpen())
        sampler.channel()->setTrafficLog(recording.log());
    QObject::connect(sampler.channel(), &ProbeChannel::framesLogged, &frames, &FrameLog::addFrames);
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &sampler, &BlockSampler::stop);
    QObject::connect(&sampler, &BlockSampler::roundDone, &sampler, [&](int done, int total) {
        line.show(QStringLiteral("sample %1 of %2  (Ctrl-C stops and infers from what was read)").arg(done).arg(total));
    });
    const QList<BlockSamples> sampled = sampler.run(settings);
    line.clear();
    if (interrupts.isInterrupted()) {
        int most = 0;
        for (const BlockSamples &b : sampled)
            most = std::max(most, int(b.samples.size()));
        err << "mbscope infer: stopped (Ctrl-C) after " << most << " of " << settings.samples << " samples: inferring from "
            << (most == 1 ? "that one" : "those") << '\n';
    }
    if (recording.isOpen())
        sampler.channel()->setTrafficLog(nullptr);
    finishRecording(recording, err);
    frames.close();

    QList<InferredBlock> inferred;
    QList<ValueGuess> all;
    int readable = 0;
    const QList<QList<ValueGuess>> guesses = BlockInferrer::inferUnit(sampled);
    for (qsizetype i = 0; i < sampled.size(); ++i) {
        readable += sampled.at(i).samples.isEmpty() ? 0 : 1;
        all += guesses.at(i);
        inferred.append(InferredBlock{sampled.at(i), guesses.at(i)});
    }
    if (readable == 0) {
        err << "mbscope infer: " << (sampler.linkFailed() ? "the link failed" : "nothing could be read")
            << (sampler.problem().isEmpty() ? QString() : QStringLiteral(": ") + sampler.problem()) << '\n';
        return sampler.linkFailed() ? ExitLinkError : ExitFailure;
    }
    if (!outPath.isEmpty()) {
        const QByteArray bytes = InferenceDraft::toJson(all, quint8(unit), QFileInfo(outPath).completeBaseName(),
                                                        target.url.toString(), int(intervalMs));
        QFile file(outPath);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size()) {
            err << "mbscope infer: cannot write the profile draft to " << outPath << ": " << file.errorString() << '\n';
            return ExitUsage;
        }
        err << "mbscope infer: profile draft written to " << outPath << '\n';
    }
    if (parser.isSet(jsonOpt))
        out << QJsonDocument(InferReport::json(target.url.toString(), quint8(unit), int(intervalMs), inferred)).toJson(QJsonDocument::Indented);
    else
        out << InferReport::text(target.url.toString(), quint8(unit), int(intervalMs), inferred);
    out.flush();
    return ExitOk;
}

} // namespace mbscope::app
