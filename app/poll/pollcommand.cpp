#include "poll/pollcommand.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "poll/polloptions.h"
#include "poll/pollresults.h"
#include "poll/pollrunner.h"
#include "poll/polltranscript.h"
#include "common/recordoptions.h"

#include "protocol/broadcastrule.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

// Poll and sweep differ in one option and in what they print; the rest is shared.
int runPollOrSweep(const QStringList &arguments, bool sweep)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const char *name = sweep ? "sweep" : "poll";
    QCommandLineParser parser;
    parser.setApplicationDescription(
        sweep ? QStringLiteral(
                    "Runs the same poll at each interval in turn and prints a table of interval against error rate and "
                    "latency (min, mean, p50, p99, max), e.g. to find how fast a noisy RS485 bus can be polled.\n"
                    "Example (with mbscope simulate --profile rosrao-gamma --listen rtu-tcp://127.0.0.1:4001 running; on a "
                    "bus: --target \"rtu:///dev/ttyUSB0?baud=9600\" and --count 300):\n"
                    "  mbscope sweep --target rtu-tcp://127.0.0.1:4001 --function 3 --address 0x79 --quantity 10 "
                    "--intervals 20,50,100 --count 20\n"
                    "A live progress line is shown on a terminal; Ctrl-C stops and prints the intervals run so far.\n"
                    "Exit status: 0 every transaction ok, 1 some failed, 2 usage or link error.")
              : QStringLiteral(
                    "Sends the requests in cycles at an interval, for a count of cycles or a duration, and prints the "
                    "statistics: counts by outcome, latency min, mean, median, p90, p95, p99, max and standard "
                    "deviation.\n"
                    "Examples (with mbscope simulate --profile rosrao-gamma --listen tcp://127.0.0.1:5020 running):\n"
                    "  mbscope poll --target tcp://127.0.0.1:5020 --function 3 --address 0x79 --quantity 10 "
                    "--interval 100ms --count 20\n"
                    "  mbscope poll --target tcp://127.0.0.1:5020 --hex \"00 01 00 00 00 06 01 03 00 79 00 0A\" "
                    "--interval 0 --duration 2s --pipeline 8 --histogram latency.png\n"
                    "A live progress line is shown on a terminal; Ctrl-C stops the poll and still prints the statistics.\n"
                    "Exit status: 0 every transaction ok, 1 some failed, 2 usage or link error."));
    parser.addHelpOption();
    const PollOptions options(sweep);
    options.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope " << name << ": " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), name);
        return ExitOk;
    }
    PollConfig config;
    if (!options.read(parser, config, err))
        return ExitUsage;

    PollTranscript transcript(config.plan, config.target.url.framing(), out);
    transcript.setPrintValues(config.printValues);
    if (!config.csvPath.isEmpty()) {
        QString error;
        if (!transcript.openCsv(config.csvPath, &error)) {
            err << "mbscope " << name << ": --csv: " << error << '\n';
            return ExitUsage;
        }
    }
    FrameLog frames;
    if (!openFrameLog(frames, config.print, QString::fromLatin1(name), err))
        return ExitUsage;
    TrafficRecording recording;
    TrafficMetadata metadata = clientMetadata(QString::fromLatin1(name), arguments, config.target, config.plan);
    metadata.settings.insert(QStringLiteral("pipeline"), config.engine.pipelineDepth);
    if (sweep) {
        QJsonArray intervals;
        for (qint64 ns : config.settings.intervalsNs)
            intervals.append(double(ns) / 1e6);
        metadata.settings.insert(QStringLiteral("intervals_ms"), intervals);
    } else {
        metadata.settings.insert(QStringLiteral("interval_ms"), double(config.settings.poll.intervalNs) / 1e6);
    }
    if (config.settings.poll.count > 0)
        metadata.settings.insert(QStringLiteral("count"), double(config.settings.poll.count));
    if (config.settings.poll.durationNs > 0)
        metadata.settings.insert(QStringLiteral("duration_ms"), double(config.settings.poll.durationNs) / 1e6);
    if (!openRecording(recording, config.record, metadata, QString::fromLatin1(name), err))
        return ExitUsage;

    // A read sent to unit 0 on a serial framing goes out as typed, but nobody can answer it.
    bool unanswerable = false;
    for (const PlannedRequest &r : config.plan.requests) {
        const QString why = config.target.url.delimited.enabled
                                ? QString()
                                : BroadcastRule::broadcastReadProblem(r.item.bytes, config.target.url.framing());
        if (why.isEmpty())
            continue;
        unanswerable = true;
        err << "mbscope " << name << ": " << r.item.name << ": the read cannot be answered: " << why << '\n';
    }

    PollRunner runner(config.target, config.engine);
    if (recording.isOpen())
        runner.setTrafficLog(recording.log());
    if (transcript.isActive())
        runner.setTranscript(&transcript);
    if (frames.isOpen())
        runner.setFrameLog(&frames);
    const PollOutcome outcome = runner.run(config.settings, sweep);
    transcript.close();
    finishRecording(recording, err);
    const PollResults results(config, outcome);
    if (outcome.linkFailed) {
        err << "mbscope " << name << ": " << outcome.linkMessage << '\n';
        return results.exitStatus();
    }
    if (config.json)
        out << QJsonDocument(sweep ? results.sweepJson() : results.pollJson()).toJson(QJsonDocument::Indented);
    else
        out << (sweep ? results.sweepText() : results.pollText());
    out.flush();
    if (!config.histogramPath.isEmpty()) {
        QString error;
        if (!results.writeHistogram(&error)) {
            err << "mbscope " << name << ": --histogram: " << error << '\n';
            return ExitUsage;
        }
        if (!config.json)
            out << "plot          " << config.histogramPath << '\n';
    }
    return qMax(results.exitStatus(), unanswerable ? int(ExitFailure) : int(ExitOk));
}

int runPoll(const QStringList &arguments)
{
    return runPollOrSweep(arguments, false);
}

} // namespace mbscope::app
