#include "sim/replaycommand.h"

#include "capture/captureinput.h"
#include "common/cli.h"
#include "common/framelog.h"
#include "common/printoptions.h"
#include "time/duration.h"
#include "common/interruptwatcher.h"
#include "common/recordoptions.h"
#include "sim/replayserve.h"

#include "engine/transactionengine.h"
#include "protocol/hextext.h"
#include "replay/replayrunner.h"
#include "replay/replayscript.h"
#include "session/sessionreader.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

// "max" -> 0 (no waiting), "1", "10", "0.5" -> that factor; false when it is neither.
bool parseSpeed(const QString &text, double *speed)
{
    if (text == QLatin1String("max")) {
        *speed = 0;
        return true;
    }
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !(value > 0) || value > 1e6)
        return false;
    *speed = value;
    return true;
}

} // namespace

int runReplay(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Replays recorded Modbus traffic: a session document (its captured traffic), a traffic journal, or a pcap/pcapng "
        "capture (read as analyze reads it).\n"
        "With a target (--target, default the session's, else the one a journal recorded): re-sends the recorded requests at the recorded pacing and "
        "compares each answer with the recorded one field by field (dissector keys, as a plan's expectations name them: "
        "modbus.register_value@0x007D), an exception against a normal answer, a missing answer; then the latency "
        "recorded and now (median, p95).\n"
        "Recorded writes (functions 05, 06, 0F, 10, 15, 16, 17) and the diagnostics that change the device (08 "
        "sub-functions 01 restart, 03, 04 listen only, 0A and 14 clear counters) are not sent unless --send-writes: a real "
        "device's outputs would move. Each one skipped is listed (unit, function, address and quantity or sub-function) and "
        "counted as skipped.\n"
        "With --serve URL: a simulator on URL answers with the recorded answers, matched by unit and request PDU (the "
        "MBAP transaction id aside); a request recorded several times gets its answers in turn, cycling.\n"
        "Examples, a journal recorded first (with mbscope simulate --profile rosrao-gamma --listen tcp://127.0.0.1:5020 "
        "running):\n"
        "  mbscope poll --target tcp://127.0.0.1:5020 --address 0x79 --quantity 14 --count 5 --interval 100ms --record bench.mbscope.journal\n"
        "  mbscope replay bench.mbscope.journal --speed max --ignore modbus.register_value@0x0086\n"
        "  mbscope replay bench.mbscope.journal --serve rtu-tcp://127.0.0.1:4001 --duration 1s\n"
        "--record FILE journals what the replay sent and got (with --serve: what it served).\n"
        "Exit status: 0 every answer matched (or --serve stopped), 1 some differed, 2 usage error, unreadable source or link failure."));
    parser.addHelpOption();
    const CaptureInput input;
    input.addTo(parser);
    const QCommandLineOption targetOpt(QStringLiteral("target"),
                                       QStringLiteral("The device to replay to (default: the session's target.url)."), QStringLiteral("url"));
    const QCommandLineOption speedOpt(QStringLiteral("speed"),
                                      QStringLiteral("Pacing: 1 as recorded (default), N times faster, or max (back to back). With "
                                                     "--serve: the recorded latency divided by N, max for none."),
                                      QStringLiteral("max|N"), QStringLiteral("1"));
    const QCommandLineOption serveOpt(QStringLiteral("serve"),
                                      QStringLiteral("Be the device instead: answer with the recorded answers on this URL "
                                                     "(tcp://, rtu-tcp://, udp://, rtu://... port 0: the OS chooses)."),
                                      QStringLiteral("url"));
    const QCommandLineOption unrecordedOpt(QStringLiteral("unrecorded"),
                                           QStringLiteral("With --serve, a request or unit never recorded gets: exception (0B, "
                                                          "gateway target device failed to respond; default) or ignore (no answer)."),
                                           QStringLiteral("exception|ignore"), QStringLiteral("exception"));
    const QCommandLineOption durationOpt(QStringLiteral("duration"),
                                         QStringLiteral("With --serve, stop after this long (default: until Ctrl-C)."), QStringLiteral("duration"));
    const QCommandLineOption ignoreOpt(QStringLiteral("ignore"),
                                       QStringLiteral("A field expected to change (a counter, a clock): its differences are "
                                                      "reported as ignored, not counted. KEY@ADDRESS as the report names it "
                                                      "(modbus.register_value@0x007D or @125), KEY[N], or KEY alone for every "
                                                      "address; repeat the option or separate with commas. Added to the "
                                                      "session's capture.ignore."),
                                       QStringLiteral("field"));
    const QCommandLineOption sendWritesOpt(QStringLiteral("send-writes"),
                                           QStringLiteral("Send the recording's writes to the target as well (05, 06, 0F, 10, 15, "
                                                          "16, 17, and the 08 restarts, listen-only and counter clears): they change "
                                                          "the device. Without it they are listed as skipped, not sent."));
    const QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print the result as JSON."));
    parser.addOptions({targetOpt, speedOpt, serveOpt, unrecordedOpt, durationOpt, ignoreOpt, sendWritesOpt, jsonOpt});
    const RecordOptions recordOptions;
    recordOptions.addTo(parser);
    const PrintOptions printOptions(false);
    printOptions.addTo(parser);
    parser.addPositionalArgument(QStringLiteral("source"),
                                 QStringLiteral("A session document with a capture, a traffic journal, or a .pcap/.pcapng file."));
    if (!parser.parse(arguments)) {
        err << "mbscope replay: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "replay");
        return ExitOk;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        err << "mbscope replay: " << (positional.isEmpty() ? QStringLiteral("no source given") : QStringLiteral("one source at a time"))
            << ": mbscope replay SOURCE [--target URL | --serve URL] [options]\n";
        return ExitUsage;
    }
    CaptureOptions options;
    QString error;
    if (!input.read(parser, &options, &error)) {
        err << "mbscope replay: " << error << '\n';
        return ExitUsage;
    }
    double speed = 1.0;
    if (!parseSpeed(parser.value(speedOpt), &speed)) {
        err << "mbscope replay: --speed '" << parser.value(speedOpt) << "' is not a speed: expected max or a factor above 0 (1, 10, 0.5)\n";
        return ExitUsage;
    }
    if (parser.isSet(serveOpt) && parser.isSet(targetOpt)) {
        err << "mbscope replay: --serve and --target exclude each other: replay to a device, or be the device\n";
        return ExitUsage;
    }
    const QString unrecorded = parser.value(unrecordedOpt);
    if (unrecorded != QLatin1String("exception") && unrecorded != QLatin1String("ignore")) {
        err << "mbscope replay: --unrecorded '" << unrecorded << "': expected exception or ignore\n";
        return ExitUsage;
    }
    IgnoredFields ignore;
    for (const QString &value : parser.values(ignoreOpt)) {
        for (const QString &selector : value.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            QString problem;
            if (!ignore.add(selector, &problem)) {
                err << "mbscope replay: --ignore: " << problem << '\n';
                return ExitUsage;
            }
        }
    }
    if (parser.isSet(sendWritesOpt) && parser.isSet(serveOpt)) {
        err << "mbscope replay: --send-writes applies to a replay to a device (it sends the recording's writes there); "
               "--serve sends nothing, it answers\n";
        return ExitUsage;
    }
    if (!ignore.isEmpty() && parser.isSet(serveOpt)) {
        err << "mbscope replay: --ignore applies to a replay to a device (it says which answers' fields to leave out of the "
               "comparison); --serve compares nothing\n";
        return ExitUsage;
    }
    RecordSettings record;
    if (!recordOptions.read(parser, QStringLiteral("replay"), record, err, printOptions.frameLogSet(parser)))
        return ExitUsage;
    PrintSettings print;
    if (!printOptions.read(parser, QStringLiteral("replay"), record.overwrite, print, err))
        return ExitUsage;
    if (print.frames && parser.isSet(serveOpt)) {
        err << "mbscope replay: --print frames and --frame-log show what a replay to a device sends and gets; with --serve, "
               "--record FILE journals what is served (mbscope export reads it)\n";
        return ExitUsage;
    }
    qint64 durationMs = 0;
    if (parser.isSet(durationOpt)) {
        const DurationResult d = parseDuration(parser.value(durationOpt));
        if (!d.ok() || d.ns <= 0) {
            err << "mbscope replay: --duration: " << (d.ok() ? QStringLiteral("must be more than 0") : d.error) << '\n';
            return ExitUsage;
        }
        durationMs = std::max<qint64>(1, d.ns / 1'000'000);
    }

    const QString source = positional.constFirst();
    QString path;
    if (!CaptureInput::resolve(source, &path, &error)) {
        err << "mbscope replay: " << error << '\n';
        return ExitUsage;
    }
    // A session document (resolved to its journal) also gives the target and its timeout.
    SessionTarget sessionTarget;
    if (path != source) {
        const SessionLoadResult loaded = SessionReader::load(source);
        if (loaded.ok()) {
            sessionTarget = loaded.document->target;
            if (loaded.document->capture && !parser.isSet(serveOpt)) {
                for (const QString &selector : loaded.document->capture->ignore) {
                    QString problem;
                    (void)ignore.add(selector, &problem); // the reader checked each selector
                }
            }
        }
    }
    const ReplayScript script = ReplayScript::read(path, options);
    if (!script.report().isReadable()) {
        err << "mbscope replay: " << path << ": " << script.report().error << '\n';
        return ExitUsage;
    }
    if (!script.report().error.isEmpty())
        err << "mbscope replay: " << path << ": " << script.report().error << "; the exchanges before it are replayed\n";
    if (script.isEmpty()) {
        err << "mbscope replay: " << path << ": no recorded requests to replay"
            << (script.report().kind == ExchangeSourceReport::Kind::Capture
                    ? " (no Modbus traffic on the ports looked at: --port and --rtu-port say which carry it)"
                    : "")
            << '\n';
        return ExitUsage;
    }

    if (parser.isSet(serveOpt)) {
        ReplayServeOptions serve;
        serve.url = parser.value(serveOpt);
        serve.unrecorded = unrecorded == QLatin1String("ignore") ? ReplayResponder::Unrecorded::Ignore
                                                                 : ReplayResponder::Unrecorded::Exception0B;
        serve.speed = speed;
        serve.durationMs = durationMs;
        serve.json = parser.isSet(jsonOpt);
        serve.record = record;
        serve.arguments = arguments;
        return serveReplay(script, source, serve, out, err);
    }

    // Without --target or a session's: the target the journal recorded (trafficmetadata.h).
    TrafficMetadata recorded;
    bool hasMetadata = false;
    if (script.report().kind == ExchangeSourceReport::Kind::Journal && !script.report().journal.metadata.isEmpty()) {
        QString metadataError;
        hasMetadata = TrafficMetadata::fromJson(script.report().journal.metadata, &recorded, &metadataError);
    }
    QString url = parser.isSet(targetOpt) ? parser.value(targetOpt) : sessionTarget.url;
    const bool recordedTarget = url.isEmpty() && hasMetadata && !recorded.target.isEmpty();
    if (recordedTarget)
        url = recorded.target;
    if (url.isEmpty()) {
        QString why;
        if (path != source)
            why = QStringLiteral(" or save one in the session (target.url)");
        else if (script.report().kind == ExchangeSourceReport::Kind::Capture)
            why = QStringLiteral(" (a capture names none)");
        else if (hasMetadata && recorded.role == TrafficMetadata::Role::Server)
            why = QStringLiteral(" (the journal recorded mbscope %1 serving %2: it names no device to replay to)")
                      .arg(recorded.command, recorded.listen.join(QStringLiteral(", ")));
        else
            why = QStringLiteral(" (the journal records no target: it was written before journals carried one)");
        err << "mbscope replay: no target: give --target URL" << why << ", or --serve URL to be the device\n";
        return ExitUsage;
    }
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    if (!parsed.url) {
        err << "mbscope replay: "
            << (parser.isSet(targetOpt) ? QStringLiteral("--target")
                                        : recordedTarget ? QStringLiteral("%1: the recorded target").arg(source)
                                                         : QStringLiteral("%1: target.url").arg(source))
            << ": " << parsed.error << '\n';
        return ExitUsage;
    }
    if (parsed.url->delimited.enabled) {
        err << "mbscope replay: " << url << ": a delimited link carries no Modbus framing to replay into\n";
        return ExitUsage;
    }
    // The response timeout: --timeout when given (the same that pairs a capture), else the
    // session's, else the URL's or the engine's default.
    int timeoutMs = -1;
    const bool timeoutGiven = arguments.contains(QStringLiteral("--timeout"))
        || std::any_of(arguments.begin(), arguments.end(), [](const QString &a) { return a.startsWith(QLatin1String("--timeout=")); });
    if (timeoutGiven)
        timeoutMs = int(std::max<qint64>(1, options.timeoutNs / 1'000'000));
    else if (sessionTarget.timeoutMs > 0)
        timeoutMs = sessionTarget.timeoutMs;
    else if (recordedTarget && recorded.settings.value(QStringLiteral("timeout_ms")).toInt() > 0)
        timeoutMs = recorded.settings.value(QStringLiteral("timeout_ms")).toInt();

    const bool asJson = parser.isSet(jsonOpt);
    const bool sendWrites = parser.isSet(sendWritesOpt);
    const qsizetype writes = script.writes().size();
    if (recordedTarget && asJson)
        err << "mbscope replay: no --target: replaying to " << parsed.url->toString() << ", the target " << source << " recorded\n";
    if (!asJson) {
        out << "replaying " << script.size() << " recorded requests of " << source << " to " << parsed.url->toString()
            << (recordedTarget ? " (the target the journal recorded; --target replays elsewhere)" : "") << ", "
            << (speed > 0 ? (speed == 1.0 ? QStringLiteral("at the recorded pacing") : QStringLiteral("%1 times faster").arg(speed))
                          : QStringLiteral("back to back"))
            << '\n';
        if (writes > 0)
            out << writes << (writes == 1 ? " of them is a write: " : " of them are writes: ")
                << (sendWrites ? "sent (--send-writes)" : "not sent (--send-writes sends them)") << '\n';
        out << '\n';
        out.flush();
    }
    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("replay"), arguments);
    metadata.target = parsed.url->toString();
    metadata.settings.insert(QStringLiteral("source"), source);
    metadata.settings.insert(QStringLiteral("speed"), speed);
    if (timeoutMs > 0)
        metadata.settings.insert(QStringLiteral("timeout_ms"), timeoutMs);
    metadata.settings.insert(QStringLiteral("requests"), double(script.size()));
    metadata.settings.insert(QStringLiteral("send_writes"), sendWrites);
    if (!openRecording(recording, record, metadata, QStringLiteral("replay"), err))
        return ExitUsage;
    ReplayRunner runner(script, *parsed.url, EngineOptions{}, timeoutMs);
    runner.setSpeed(speed);
    runner.setIgnoredFields(ignore);
    runner.setSendWrites(sendWrites);
    if (recording.isOpen())
        runner.setTrafficLog(recording.log());
    FrameLog frames;
    if (!openFrameLog(frames, print, QStringLiteral("replay"), err))
        return ExitUsage;
    if (frames.isOpen())
        frames.attach(runner.engine());
    InterruptWatcher interrupt;
    QObject::connect(&interrupt, &InterruptWatcher::interrupted, &interrupt, [&runner] { runner.stop(); });
    QString linkProblem;
    const ReplayResult result = runner.run([&](const ReplayOutcome &outcome) {
        if (outcome.replayed.status == TransactionStatus::LinkError && linkProblem.isEmpty()) {
            linkProblem = outcome.replayed.problem;
            runner.stop();
        }
    });
    if (recording.isOpen())
        runner.setTrafficLog(nullptr);
    if (frames.isOpen())
        runner.engine()->deliverPending(); // the last frames reach the log
    if (asJson)
        out << QJsonDocument(result.toJson(script)).toJson(QJsonDocument::Indented);
    else
        out << result.summary(script);
    out.flush();
    finishRecording(recording, err);
    if (!linkProblem.isEmpty()) {
        err << "mbscope replay: " << linkProblem << '\n';
        return ExitLinkError;
    }
    if (result.interrupted)
        return ExitFailure;
    return result.allMatched() ? ExitOk : ExitFailure;
}

} // namespace mbscope::app
