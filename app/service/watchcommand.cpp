#include "service/watchcommand.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "common/interruptwatcher.h"
#include "common/printoptions.h"
#include "common/recordoptions.h"
#include "service/watchreport.h"
#include "service/watchservice.h"

#include "fleet/watchrunner.h"
#include "session/sessionreader.h"
#include "time/duration.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QDir>
#include <QtCore/QEventLoop>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>
#include <QtCore/QTimer>

#include <memory>
#include <optional>

namespace mbscope::app {

namespace {

// Every option of `mbscope watch`, read in one place (the metrics and MQTT options join them here).
struct WatchOptions {
    QString session;
    std::optional<QString> csvDirectory; // --csv DIR
    std::optional<WatchLogSettings::Mode> csvMode;
    qint64 durationNs = 0;
    quint64 count = 0;                   // polls of every watch
    bool json = false;
    bool quiet = false;
    WatchService::Options service; // --metrics, --mqtt..., --log-level
    RecordSettings record;         // --record, --force
    PrintSettings print;           // --print frames, --frame-log FILE
};

// Parses the command line into options; false when the command should end now with *status
// (help printed, or a usage error said on err).
bool parseWatchOptions(const QStringList &arguments, WatchOptions *options, int *status, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Runs the watches of a session document headless: each watch (a block of a device: target, unit, function, "
        "address, quantity, interval; docs/guide/watching.md) is polled at its own interval, the watches of one link "
        "taking turns with the link's gap between requests, every link on its own engine so that a dead device stalls "
        "no other link. A link that fails is opened again after a backoff (doubling from reconnectMinMs to "
        "reconnectMaxMs), counted. One line per poll with the values named, scaled and with their units; rule events "
        "as they fire and clear; errors and link changes on standard error; the counters of every watch at the end.\n"
        "Example, in mbscope's source folder (with mbscope simulate --profile m221-plc --listen tcp://127.0.0.1:5020 "
        "running):\n"
        "  mbscope watch docs/examples/plc-watches.mbscope.json --csv logs --duration 3s\n"
        "Ctrl-C or SIGTERM stops cleanly: the CSV files are flushed and the counters printed.\n"
        "Exit status: 0 every poll answered, 1 some polls failed (or CSV rows were lost), 2 usage error or a session "
        "that cannot be read, 3 every poll answered but the --mqtt broker was never reached (nothing published)."));
    parser.addHelpOption();
    const QCommandLineOption csvOpt(QStringLiteral("csv"),
                                    QStringLiteral("Log values to CSV files in DIR, one per watch (replaces the session's "
                                                   "watchLog directory; rolling as the session says)."),
                                    QStringLiteral("DIR"));
    const QCommandLineOption csvModeOpt(QStringLiteral("csv-mode"),
                                        QStringLiteral("poll: a row per poll (default); change: a row when a value changes."),
                                        QStringLiteral("MODE"));
    const QCommandLineOption durationOpt(QStringLiteral("duration"),
                                         QStringLiteral("Stop after this long (60s, 500ms, 2min, 1h; a bare number is milliseconds)."),
                                         QStringLiteral("TIME"));
    const QCommandLineOption countOpt(QStringLiteral("count"), QStringLiteral("Stop once every watch has polled N times."),
                                      QStringLiteral("N"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("JSON lines on standard output: {\"type\": \"sample\" | \"rule\" | \"link\" | "
                                                    "\"summary\", ...}."));
    const QCommandLineOption quietOpt(QStringLiteral("quiet"), QStringLiteral("No line per poll: rule events, errors and the counters."));
    parser.addOptions({csvOpt, csvModeOpt, durationOpt, countOpt, jsonOpt, quietOpt});
    const RecordOptions recordOptions;
    recordOptions.addTo(parser);
    const PrintOptions printOptions(false);
    printOptions.addTo(parser);
    WatchService::addOptions(parser);
    parser.addPositionalArgument(QStringLiteral("session"), QStringLiteral("A session document with watches (*.mbscope.json)."));
    *status = ExitUsage;
    if (!parser.parse(arguments)) {
        err << "mbscope watch: " << parser.errorText() << '\n';
        return false;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "watch");
        *status = ExitOk;
        return false;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        err << "mbscope watch: " << (positional.isEmpty() ? "no session given" : "one session at a time")
            << ": mbscope watch SESSION.mbscope.json [options]\n";
        return false;
    }
    options->session = positional.constFirst();
    if (parser.isSet(csvOpt)) {
        options->csvDirectory = parser.value(csvOpt);
        if (options->csvDirectory->trimmed().isEmpty()) {
            err << "mbscope watch: --csv: give a directory\n";
            return false;
        }
    }
    if (parser.isSet(csvModeOpt)) {
        const QString mode = parser.value(csvModeOpt);
        if (mode == QLatin1String("poll"))
            options->csvMode = WatchLogSettings::Mode::EveryPoll;
        else if (mode == QLatin1String("change"))
            options->csvMode = WatchLogSettings::Mode::OnChange;
        else {
            err << "mbscope watch: --csv-mode '" << mode << "': expected poll or change\n";
            return false;
        }
    }
    if (parser.isSet(durationOpt)) {
        const DurationResult d = parseDuration(parser.value(durationOpt));
        if (!d.ok() || d.ns <= 0) {
            err << "mbscope watch: --duration: " << (d.ok() ? QStringLiteral("'%1' is not above zero").arg(parser.value(durationOpt)) : d.error)
                << '\n';
            return false;
        }
        options->durationNs = d.ns;
    }
    if (parser.isSet(countOpt)) {
        bool ok = false;
        options->count = parser.value(countOpt).toULongLong(&ok);
        if (!ok || options->count == 0) {
            err << "mbscope watch: --count '" << parser.value(countOpt) << "' is not a whole number above zero\n";
            return false;
        }
    }
    if (!recordOptions.read(parser, QStringLiteral("watch"), options->record, err, printOptions.frameLogSet(parser)))
        return false;
    if (!printOptions.read(parser, QStringLiteral("watch"), options->record.overwrite, options->print, err))
        return false;
    options->json = parser.isSet(jsonOpt);
    options->quiet = parser.isSet(quietOpt);
    QString error;
    const std::optional<WatchService::Options> service = WatchService::readOptions(parser, options->session, &error);
    if (!service) {
        err << "mbscope watch: " << error << '\n';
        return false;
    }
    options->service = *service;
    return true;
}

void printJson(QTextStream &out, const QJsonObject &o)
{
    out << QJsonDocument(o).toJson(QJsonDocument::Compact) << '\n';
    out.flush();
}

} // namespace

int runWatch(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    WatchOptions options;
    int status = ExitOk;
    if (!parseWatchOptions(arguments, &options, &status, out, err))
        return status;

    const SessionLoadResult loaded = SessionReader::load(options.session);
    if (!loaded.ok()) {
        err << "mbscope watch: the session cannot be used:\n" << loaded.errorText() << '\n';
        return ExitUsage;
    }
    SessionWatches watches = loaded.document->watches;
    int enabled = 0;
    for (const WatchDefinition &w : watches.watches)
        enabled += w.enabled ? 1 : 0;
    if (enabled == 0) {
        err << "mbscope watch: " << options.session
            << (watches.isEmpty() ? ": the session has no watches: add a \"watches\" section (docs/guide/watching.md)\n"
                                  : ": every watch of the session is disabled (\"enabled\": false)\n");
        return ExitUsage;
    }

    // CSV: --csv DIR (relative to the working directory), else the session's watchLog (relative
    // to the document). The runner's log thread writes the files (values and rule events); they
    // open anew, for the new set of watches, when SIGHUP reloads the session. The folder is made
    // here first, so that one that cannot be made is said before anything runs.
    const auto csvSettings = [&](const SessionWatches &w, QString *error) -> std::optional<WatchLogSettings> {
        if (!options.csvDirectory && !(w.log && w.log->enabled))
            return std::nullopt;
        WatchLogSettings log = w.log.value_or(WatchLogSettings{});
        log.enabled = true;
        log.directory = options.csvDirectory ? QDir(*options.csvDirectory).absolutePath()
                                             : QDir(QFileInfo(options.session).absolutePath()).absoluteFilePath(log.directory);
        if (options.csvMode)
            log.mode = *options.csvMode;
        if (!QDir().mkpath(log.directory)) {
            *error = QStringLiteral("%1: the log directory cannot be made").arg(log.directory);
            return std::nullopt;
        }
        return log;
    };
    std::optional<WatchLogSettings> csv;
    {
        QString error;
        csv = csvSettings(watches, &error);
        if (!error.isEmpty()) {
            err << "mbscope watch: CSV: " << error << '\n';
            return ExitUsage;
        }
    }

    // --record: declared before the runner, so that the journal outlives its engines.
    TrafficRecording recording;
    WatchRunner runner(watches);
    WatchService service(runner, options.service);
    {
        QString error;
        if (!service.start(&error)) {
            err << "mbscope watch: " << error << '\n';
            return ExitUsage;
        }
    }
    // --record: one journal for every link, each link's engine on a link id of its own (the log
    // shared between their threads).
    {
        TrafficMetadata metadata = commandMetadata(QStringLiteral("watch"), arguments);
        QStringList targets;
        for (const WatchDefinition &w : std::as_const(watches.watches)) {
            if (w.enabled && !targets.contains(w.target))
                targets.append(w.target);
        }
        if (targets.size() == 1)
            metadata.target = targets.constFirst();
        metadata.settings.insert(QStringLiteral("targets"), QJsonArray::fromStringList(targets));
        metadata.settings.insert(QStringLiteral("watches"), enabled);
        if (!openRecording(recording, options.record, metadata, QStringLiteral("watch"), err))
            return ExitUsage;
        recording.log()->setShared(true);
    }
    if (recording.isOpen())
        runner.setTrafficLog(recording.log());
    FrameLog frames;
    if (!openFrameLog(frames, options.print, QStringLiteral("watch"), err))
        return ExitUsage;
    frames.setNamesLinks(true); // the watches' links take turns
    runner.setFramesPublished(frames.isOpen());
    QObject::connect(&runner, &WatchRunner::framesLogged, &frames, &FrameLog::addFrames);
    service.setWatches(watches);
    runner.setLog(csv);
    QEventLoop loop;
    InterruptWatcher interrupts;
    bool stopping = false;
    bool failed = false;
    bool csvFailed = false;
    const auto stop = [&] {
        if (stopping)
            return;
        stopping = true;
        runner.stop();
    };
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &loop, stop);
    QObject::connect(&runner, &WatchRunner::stopped, &loop, &QEventLoop::quit);
    QObject::connect(&runner, &WatchRunner::sampled, &loop, [&](const QList<WatchSample> &samples, const QList<WatchCounters> &) {
        for (const WatchSample &s : samples) {
            if (options.count > 0 && s.poll > options.count)
                continue;
            if (!s.isOk())
                failed = true;
            if (options.json)
                printJson(out, WatchReport::sampleJson(s));
            else if (!s.isOk()) {
                if (!s.linkError)
                    service.log().warning(WatchReport::errorLine(s));
            } else if (!options.quiet)
                out << WatchReport::sampleLine(s) << '\n';
        }
        out.flush();
        err.flush();
        if (options.count > 0) {
            bool done = true;
            for (int i = 0; i < watches.watches.size(); ++i) {
                if (watches.watches.at(i).enabled && runner.counters(i).polls < options.count)
                    done = false;
            }
            if (done)
                stop();
        }
    });
    // The CSV log's troubles, said as they happen; the rows lost, when its files close.
    QStringList csvFiles;
    QObject::connect(&runner, &WatchRunner::logFailed, &loop, [&](const QString &message) {
        csvFailed = true;
        service.log().error(QStringLiteral("CSV: %1 (polling goes on; the rows lost are counted)").arg(message));
    });
    // A disk slower than the polls: said when rows start to be dropped and when it caught up.
    QObject::connect(&runner, &WatchRunner::logDropping, &loop, [&](const QString &message) {
        service.log().warning(QStringLiteral("CSV: %1").arg(message));
    });
    QObject::connect(&runner, &WatchRunner::logCaughtUp, &loop, [&](quint64, const QString &message) {
        service.log().notice(QStringLiteral("CSV: %1").arg(message));
    });
    QObject::connect(&runner, &WatchRunner::logClosed, &loop, [&](const QString &, const QStringList &files, quint64 lost, quint64 dropped) {
        csvFiles += files;
        if (lost > 0) {
            csvFailed = true;
            QString text = QStringLiteral("CSV: %1 %2 could not be written").arg(lost).arg(lost == 1 ? QStringLiteral("row") : QStringLiteral("rows"));
            if (dropped > 0)
                text += QStringLiteral(" (%1 dropped while the log fell behind the polls)").arg(dropped);
            service.log().error(text);
        }
    });
    QObject::connect(&runner, &WatchRunner::ruleChanged, &loop, [&](const WatchRuleEvent &e) {
        if (options.json)
            printJson(out, WatchReport::ruleJson(e));
        else
            out << WatchReport::ruleLine(e) << '\n';
        out.flush();
    });
    // A link that fails is said by the service's log (WatchService): once when it goes down, with
    // the reason, once when it is back; the polls it costs are not said again one by one.
    QObject::connect(&runner, &WatchRunner::linkStateChanged, &loop, [&](const WatchLinkState &s) {
        if (options.json)
            printJson(out, WatchReport::linkJson(s));
    });
    // SIGHUP: the session read again; the runner restarts with the new watches (counters anew),
    // and so do the metrics and the CSV files. A session that no longer reads changes nothing.
    interrupts.watchHangup();
    QObject::connect(&interrupts, &InterruptWatcher::hangup, &loop, [&] {
        if (stopping)
            return;
        const SessionLoadResult again = SessionReader::load(options.session);
        if (!again.ok()) {
            service.log().error(QStringLiteral("SIGHUP: %1 does not read, the running watches stay:\n%2").arg(options.session, again.errorText()));
            return;
        }
        int on = 0;
        for (const WatchDefinition &w : again.document->watches.watches)
            on += w.enabled ? 1 : 0;
        if (on == 0) {
            service.log().error(QStringLiteral("SIGHUP: %1 has no enabled watches, the running watches stay").arg(options.session));
            return;
        }
        watches = again.document->watches;
        runner.setWatches(watches);
        service.setWatches(watches);
        QString error;
        csv = csvSettings(watches, &error);
        if (!error.isEmpty())
            service.log().error(QStringLiteral("SIGHUP: CSV: %1 (logging stops; polling goes on)").arg(error));
        runner.setLog(csv);
        service.log().notice(QStringLiteral("SIGHUP: %1 read again, %2 %3").arg(options.session).arg(on).arg(on == 1 ? QStringLiteral("watch") : QStringLiteral("watches")));
    });
    QTimer durationTimer;
    durationTimer.setSingleShot(true);
    durationTimer.setTimerType(Qt::PreciseTimer);
    if (options.durationNs > 0) {
        QObject::connect(&durationTimer, &QTimer::timeout, &loop, stop);
        durationTimer.start(std::chrono::milliseconds(qMax<qint64>(1, options.durationNs / 1'000'000)));
    }
    if (!options.json && !options.quiet)
        err << "mbscope watch: " << enabled << (enabled == 1 ? " watch" : " watches") << " from " << options.session
            << "; Ctrl-C stops\n";
    err.flush();
    runner.start();
    loop.exec();

    service.stop();
    runner.setTrafficLog(nullptr); // every link closed: the journal is complete
    finishRecording(recording, err);
    const QString unpublished = service.mqttNeverReached();
    if (!unpublished.isEmpty())
        service.log().error(unpublished);
    if (options.json) {
        QJsonArray counters;
        for (const WatchCounters &c : runner.allCounters())
            counters.append(WatchReport::countersJson(c));
        QJsonObject summary;
        summary.insert(QLatin1String("type"), QStringLiteral("summary"));
        summary.insert(QLatin1String("watches"), counters);
        if (!csvFiles.isEmpty())
            summary.insert(QLatin1String("csv_files"), QJsonArray::fromStringList(csvFiles));
        printJson(out, summary);
    } else {
        for (const WatchCounters &c : runner.allCounters()) {
            if (watches.watches.at(c.watch).enabled)
                out << WatchReport::countersLine(c) << '\n';
        }
        if (!csvFiles.isEmpty())
            out << "CSV: " << csvFiles.join(QLatin1String(", ")) << '\n';
    }
    out.flush();
    if (failed || csvFailed)
        return ExitFailure;
    return unpublished.isEmpty() ? ExitOk : ExitNotPublished;
}

} // namespace mbscope::app
