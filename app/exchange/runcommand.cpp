#include "exchange/runcommand.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "common/interruptwatcher.h"
#include "common/outputpath.h"
#include "common/printoptions.h"
#include "common/recordoptions.h"

#include "session/capturerecovery.h"
#include "session/junitreport.h"
#include "session/planrunner.h"
#include "session/sessionreader.h"
#include "traffic/trafficrecording.h"
#include "transport/linkurl.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

QString outcomeLabel(StepResult::Outcome outcome)
{
    switch (outcome) {
    case StepResult::Outcome::Passed:
        return QStringLiteral("PASS ");
    case StepResult::Outcome::Failed:
        return QStringLiteral("FAIL ");
    case StepResult::Outcome::Error:
        return QStringLiteral("ERROR");
    case StepResult::Outcome::Skipped:
        return QStringLiteral("SKIP ");
    }
    return QString();
}

void printStep(QTextStream &out, const StepResult &s)
{
    out << outcomeLabel(s.outcome) << "  " << s.name << "  (" << s.path << ", "
        << QString::number(double(s.elapsedNs) / 1e6, 'f', 1) << " ms)\n";
    for (const QString &reason : s.reasons)
        out << "       " << reason << '\n';
    if (s.outcome != StepResult::Outcome::Passed && s.outcome != StepResult::Outcome::Skipped && !s.detail.isEmpty())
        out << "       " << s.detail << '\n';
    out.flush();
}

} // namespace

int runRun(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Runs the test plan of a session document (*.mbscope.json, see docs/session.schema.json) against a device: "
        "each step sends a request and checks the answer (exact bytes, decoded field values or ranges, an exception "
        "code, no answer), polls and checks bounds on the statistics (\"p95 < 20 ms\", \"timeouts == 0\"), waits or "
        "repeats steps. Prints each step with pass or fail and why.\n"
        "Example, in mbscope's source folder (with mbscope simulate --profile rosrao-gamma --listen "
        "rtu-tcp://127.0.0.1:4001 running):\n"
        "  mbscope run docs/examples/rosrao-gamma.mbscope.json --target rtu-tcp://127.0.0.1:4001 --junit results.xml\n"
        "Ctrl-C stops the run: the steps left are reported skipped, and the JUnit file is still written.\n"
        "--record FILE journals every frame of the run; --record-capture journals it into the file the session's "
        "capture.journal names, beside the document, so that analyze, export and replay of the session read this run.\n"
        "Exit status: 0 every step passed, 1 a step failed (or the run was interrupted), 2 usage, document or link error."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("SESSION"), QStringLiteral("The session document holding the plan."));
    const QCommandLineOption target(QStringLiteral("target"),
                                    QStringLiteral("Run against this URL instead of the session's target "
                                                   "(tcp://host:502, rtu-tcp://host:4001, rtu:///dev/ttyUSB0?baud=9600 ...)."),
                                    QStringLiteral("URL"));
    const QCommandLineOption junit(QStringLiteral("junit"), QStringLiteral("Write the results as JUnit XML to FILE (for CI)."),
                                   QStringLiteral("FILE"));
    const QCommandLineOption json(QStringLiteral("json"), QStringLiteral("Print the results as JSON instead of text."));
    const QCommandLineOption recordCapture(QStringLiteral("record-capture"),
                                           QStringLiteral("Journal the run into the session's capture (the file capture.journal "
                                                          "names, beside the document); refused when it exists, unless --force."));
    parser.addOptions({target, junit, json, recordCapture});
    const RecordOptions recordOptions;
    recordOptions.addTo(parser);
    const PrintOptions printOptions(false);
    printOptions.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope run: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "run")
                   .replace(QLatin1String("Usage: mbscope run [options]\n"), QLatin1String("Usage: mbscope run [options] SESSION\n"));
        return ExitOk;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        err << "mbscope run: " << (positional.isEmpty() ? QStringLiteral("give the session document to run")
                                                        : QStringLiteral("one session document at a time ('%1' is one too many)").arg(positional.at(1)))
            << " (see mbscope run --help)\n";
        return ExitUsage;
    }
    const QString path = positional.constFirst();
    const bool force = parser.isSet(QStringLiteral("force"));
    if (parser.isSet(junit)) {
        // Said before the first step, not after a run of minutes.
        const QString problem = OutputPath::problem(QStringLiteral("--junit"), parser.value(junit), QStringLiteral("--junit results.xml"), force);
        if (!problem.isEmpty()) {
            err << "mbscope run: " << problem << '\n';
            return ExitUsage;
        }
    }
    RecordSettings record;
    if (parser.isSet(recordCapture)) {
        if (parser.isSet(QStringLiteral("record"))) {
            err << "mbscope run: --record FILE and --record-capture exclude each other: record into a file, or into the session's capture\n";
            return ExitUsage;
        }
        record.overwrite = force;
    } else if (!recordOptions.read(parser, QStringLiteral("run"), record, err, parser.isSet(junit) || printOptions.frameLogSet(parser))) {
        return ExitUsage;
    }
    PrintSettings print;
    if (!printOptions.read(parser, QStringLiteral("run"), force, print, err))
        return ExitUsage;
    const SessionLoadResult loaded = SessionReader::load(path);
    if (!loaded.ok()) {
        err << "mbscope run: cannot open the session (" << loaded.problems.size()
            << (loaded.problems.size() == 1 ? " problem" : " problems") << "):\n"
            << loaded.errorText() << '\n';
        return ExitUsage;
    }
    const SessionDocument &document = *loaded.document;
    if (document.plan.empty()) {
        err << "mbscope run: " << path << ": the session has no test plan ('plan' is missing or empty)\n";
        return ExitUsage;
    }
    const QString url = parser.isSet(target) ? parser.value(target) : document.target.url;
    if (url.isEmpty()) {
        err << "mbscope run: no target: give --target URL or save one in the session (target.url)\n";
        return ExitUsage;
    }
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    if (!parsed.url) {
        err << "mbscope run: " << (parser.isSet(target) ? QStringLiteral("--target") : QStringLiteral("%1: target.url").arg(path))
            << ": " << parsed.error << '\n';
        return ExitUsage;
    }

    SessionDocument named = document;
    if (named.name.isEmpty())
        named.name = QFileInfo(path).completeBaseName();
    if (parser.isSet(recordCapture)) {
        record.path = CaptureRecovery::journalPath(document, path);
        if (record.path.isEmpty()) {
            err << "mbscope run: --record-capture: " << path << " names no capture: add \"capture\": {\"journal\": \""
                << QFileInfo(path).completeBaseName().section(QLatin1Char('.'), 0, 0) << ".mbscope.journal\"} to it, or give --record FILE\n";
            return ExitUsage;
        }
        if (QFileInfo::exists(record.path) && !record.overwrite) {
            err << "mbscope run: --record-capture: the session's capture " << record.path
                << " exists: a journal is never overwritten (--force replaces it, --record FILE records elsewhere)\n";
            return ExitUsage;
        }
        const QString problem = OutputPath::problem(QStringLiteral("--record-capture"), record.path, QStringLiteral("--record-capture"),
                                                    record.overwrite, QStringLiteral("a journal"));
        if (!problem.isEmpty()) {
            err << "mbscope run: " << problem << '\n';
            return ExitUsage;
        }
    }
    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("run"), arguments);
    metadata.target = parsed.url->toString();
    metadata.settings.insert(QStringLiteral("session"), QFileInfo(path).absoluteFilePath());
    metadata.settings.insert(QStringLiteral("plan"), named.name);
    for (const SessionRequest &request : document.requests) {
        const SessionRequest::Bytes wire = request.wireBytes(*parsed.url, 1);
        if (wire.ok())
            metadata.requests.append(TrafficMetadataRequest{request.name, QString(), wire.bytes});
    }
    if (document.profile.kind == SessionProfile::Kind::Reference) {
        metadata.profileName = document.profile.reference;
        metadata.profileSource = QStringLiteral("session");
    } else if (document.profile.kind == SessionProfile::Kind::Inline) {
        metadata.profileName = document.profile.profile.value(QStringLiteral("name")).toString();
        metadata.profileSource = QStringLiteral("session (inline)");
    }
    if (!openRecording(recording, record, metadata, QStringLiteral("run"), err))
        return ExitUsage;
    FrameLog frames;
    if (!openFrameLog(frames, print, QStringLiteral("run"), err))
        return ExitUsage;

    const bool asJson = parser.isSet(json);
    if (!asJson) {
        out << "plan     " << named.name << " (" << path << "), " << planStepCount(named.plan) << " steps\n"
            << "target   " << parsed.url->toString() << "\n\n";
        out.flush();
    }
    PlanRunner runner(named, *parsed.url, document.target);
    if (recording.isOpen())
        runner.setTrafficLog(recording.log());
    if (frames.isOpen())
        runner.setFramesObserver([&frames](const QList<TrafficFrame> &batch, const QString &link) { frames.addFrames(batch, link); });
    InterruptWatcher interrupt;
    QObject::connect(&interrupt, &InterruptWatcher::interrupted, &interrupt, [&runner] { runner.stop(); });
    // Steps not run are each a result (JUnit lists each as skipped); the text shows the first of
    // a run of them and how many follow, not thousands of lines for a long repeat.
    int skippedInRow = 0;
    const auto flushSkipped = [&] {
        if (skippedInRow > 0)
            out << "SKIP   ... and " << skippedInRow << " more " << (skippedInRow == 1 ? "step" : "steps") << " not run\n";
        skippedInRow = 0;
    };
    bool listingSkips = false;
    const PlanResult result = runner.run([&](const StepResult &step) {
        if (asJson)
            return;
        if (step.outcome == StepResult::Outcome::Skipped && step.reasons.value(0).startsWith(QLatin1String("not run"))) {
            if (!listingSkips) {
                listingSkips = true;
                printStep(out, step);
                skippedInRow += step.runs - 1;
            } else {
                skippedInRow += step.runs;
            }
            return;
        }
        listingSkips = false;
        flushSkipped();
        printStep(out, step);
    });
    if (!asJson)
        flushSkipped();

    if (recording.isOpen())
        runner.setTrafficLog(nullptr);
    finishRecording(recording, err);
    if (asJson) {
        out << QJsonDocument(result.toJson()).toJson(QJsonDocument::Indented);
    } else {
        out << '\n' << result.total() << " steps: " << result.count(StepResult::Outcome::Passed) << " passed, "
            << result.count(StepResult::Outcome::Failed) << " failed, " << result.count(StepResult::Outcome::Error)
            << " errors, " << result.count(StepResult::Outcome::Skipped) << " skipped in "
            << QString::number(double(result.elapsedNs) / 1e9, 'f', 3) << " s\n";
    }
    out.flush();
    if (parser.isSet(junit)) {
        QString error;
        if (!JUnitReport::write(result, parser.value(junit), &error)) {
            err << "mbscope run: --junit: " << error << '\n';
            return ExitUsage;
        }
        if (!asJson)
            out << "junit    " << parser.value(junit) << '\n';
    }
    if (result.linkFailed) {
        err << "mbscope run: " << result.linkMessage << '\n';
        return ExitLinkError;
    }
    if (result.interrupted) {
        const int left = result.count(StepResult::Outcome::Skipped);
        err << "mbscope run: interrupted: " << left << (left == 1 ? " step" : " steps") << " not run\n";
        return ExitFailure;
    }
    return result.passed() ? ExitOk : ExitFailure;
}

} // namespace mbscope::app
