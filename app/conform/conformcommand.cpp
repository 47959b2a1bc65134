#include "conform/conformcommand.h"

#include "common/cli.h"
#include "common/framelog.h"
#include "common/interruptwatcher.h"
#include "common/outputpath.h"
#include "common/printoptions.h"
#include "common/recordoptions.h"
#include "common/targetoptions.h"

#include "conformance/conformancehtml.h"
#include "conformance/conformancerunner.h"
#include "profile/profileloader.h"
#include "session/junitreport.h"
#include "traffic/trafficrecording.h"

#ifdef MBSCOPE_HAVE_UI
#include "conformance/conformancepdf.h"
#endif

#include <QtCore/QCommandLineParser>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

bool readRanges(const QCommandLineParser &parser, const QCommandLineOption &option, QList<TableRange> *out, QTextStream &err)
{
    for (const QString &value : parser.values(option)) {
        for (const QString &item : value.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            QString error;
            const std::optional<TableRange> range = TableRange::parse(item.trimmed(), &error);
            if (!range) {
                err << "mbscope conform: --" << option.names().constFirst() << ' ' << error << '\n';
                return false;
            }
            out->append(*range);
        }
    }
    return true;
}

void listChecks(QTextStream &out)
{
    for (const ConformanceCheck &c : ConformanceRunner::battery())
        out << c.id.leftJustified(32) << ' ' << QString::fromLatin1(checkLevelName(c.level)).leftJustified(13) << ' ' << c.title
            << "  [" << c.clause << "]\n";
}

} // namespace

int runConform(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Runs a conformance battery against a Modbus slave and prints its scorecard: every check names the clause it "
        "tests (MODBUS Application Protocol V1.1b3, Serial Line V1.02, Messaging on TCP/IP Implementation Guide V1.0b) "
        "and is judged from the raw bytes of the answer; a failure says what was sent, what came back and what the "
        "clause requires. Checks: exception codes 01, 02 and 03 (quantity 0, above the maximum, a block past the "
        "address space or the map), quantity limits, byte counts, bit order, the MBAP header, protocol ids, unit 0xFF, "
        "pipelined requests, broadcasts, reserved unit ids, wrong checksums, a request cut short, one answer per "
        "request, the connection kept, reconnects, a second client and up to 8 more connections at once, on an RTU serial "
        "port the line timing (t3.5 before the answer, no silence over t1.5 inside it; not judged when the link's times "
        "cannot show it), 08/0000 echo, device identification, response times; with --writable, 05, 06, 0F, 10, 16 and "
        "17 too. --html writes the scorecard as one self-contained page, --pdf the same report as a PDF; Tools > "
        "Conformance in the window runs the "
        "same battery.\n"
        "Safe by default: it only reads. A check that writes runs only on the addresses --writable names, and puts back "
        "the value it found. Checks of what the device does not support (exception 01 to the survey's read, or not in "
        "the --profile's functions) are skipped with the reason.\n"
        "Example (with mbscope simulate --profile conformance --listen tcp://127.0.0.1:5020 running):\n"
        "  mbscope conform --target tcp://127.0.0.1:5020 --profile conformance --junit conform.xml\n"
        "Exit status: 0 every mandatory check passed, 1 a mandatory check failed, or the run was cut short (the device "
        "lost mid-run, or Ctrl-C), 2 usage error, or the "
        "target refused or answered nothing at all."));
    parser.addHelpOption();
    const TargetOptions targetOptions(false);
    targetOptions.addTo(parser);
    const QCommandLineOption unit(QStringLiteral("unit"), QStringLiteral("The unit id under test, 1-247 (default 1)."),
                                  QStringLiteral("id"), QStringLiteral("1"));
    const QCommandLineOption profile(QStringLiteral("profile"),
                                     QStringLiteral("A device profile (shipped name or JSON file) that declares what the device "
                                                    "promises: its functions, and its tables, which give readable and missing addresses."),
                                     QStringLiteral("name|file"));
    const QCommandLineOption readable(QStringLiteral("readable"),
                                      QStringLiteral("An address the device has, per table (default: the profile's, else 0): "
                                                     "holding:121, coils:0 (repeatable, or comma-separated)."),
                                      QStringLiteral("table:address"));
    const QCommandLineOption missing(QStringLiteral("missing"),
                                     QStringLiteral("An address the device does not have, per table (default: the profile's first "
                                                    "gap, else 65535): holding:100 (repeatable)."),
                                     QStringLiteral("table:address"));
    const QCommandLineOption writable(QStringLiteral("writable"),
                                      QStringLiteral("Addresses the checks may write (each value found is put back): holding:10-13, "
                                                     "coils:0-7 (repeatable). Without it nothing is written."),
                                      QStringLiteral("table:first[-last]"));
    const QCommandLineOption only(QStringLiteral("only"),
                                  QStringLiteral("Run only the checks whose id starts with one of these (read.03,mbap)."),
                                  QStringLiteral("prefixes"));
    const QCommandLineOption samples(QStringLiteral("samples"),
                                     QStringLiteral("Reads timed by timing.response, 1-10000 (default 20)."), QStringLiteral("n"),
                                     QStringLiteral("20"));
    const QCommandLineOption json(QStringLiteral("json"), QStringLiteral("Print the scorecard as JSON instead of text."));
    const QCommandLineOption junit(QStringLiteral("junit"),
                                   QStringLiteral("Write the scorecard as JUnit XML to FILE, one test case per check (for CI)."),
                                   QStringLiteral("file"));
    const QCommandLineOption html(QStringLiteral("html"),
                                  QStringLiteral("Write the scorecard as one self-contained HTML page to FILE: the verdict first, "
                                                 "then every check with its clause, verdict, request and answer (prints well)."),
                                  QStringLiteral("file"));
    const QCommandLineOption pdf(QStringLiteral("pdf"),
                                 QStringLiteral("Write the scorecard as a PDF to FILE (A4): the --html report, laid out for print."),
                                 QStringLiteral("file"));
    const QCommandLineOption list(QStringLiteral("list"), QStringLiteral("List the checks (id, level, title, clause) and exit."));
    parser.addOptions({unit, profile, readable, missing, writable, only, samples, json, junit, html, pdf, list});
    const RecordOptions recordOptions;
    recordOptions.addTo(parser);
    const PrintOptions printOptions(false);
    printOptions.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope conform: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "conform");
        return ExitOk;
    }
    if (parser.isSet(list)) {
        listChecks(out);
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "mbscope conform: unexpected argument '" << parser.positionalArguments().constFirst()
            << "': the device is given with --target URL (see mbscope conform --help)\n";
        return ExitUsage;
    }
    TargetSettings target;
    if (!targetOptions.read(parser, QStringLiteral("conform"), target, err))
        return ExitUsage;
    ConformanceSettings settings;
    settings.url = target.url;
    settings.timeoutMs = target.timeoutMs;
    const IntegerResult unitId = parseInteger(QStringLiteral("--unit"), parser.value(unit), 1, 247, QStringLiteral("a slave's unit id"));
    if (!unitId.ok) {
        err << "mbscope conform: " << unitId.error << '\n';
        return ExitUsage;
    }
    settings.unit = quint8(unitId.value);
    const IntegerResult sampleCount = parseInteger(QStringLiteral("--samples"), parser.value(samples), 1, 10000);
    if (!sampleCount.ok) {
        err << "mbscope conform: " << sampleCount.error << '\n';
        return ExitUsage;
    }
    settings.timingSamples = int(sampleCount.value);
    QList<TableRange> readables;
    QList<TableRange> missings;
    if (!readRanges(parser, readable, &readables, err) || !readRanges(parser, missing, &missings, err)
        || !readRanges(parser, writable, &settings.writable, err))
        return ExitUsage;
    for (const TableRange &r : readables)
        settings.readable[int(r.table)] = r.first;
    for (const TableRange &r : missings)
        settings.missing[int(r.table)] = r.first;
    for (const QString &prefix : parser.value(only).split(QLatin1Char(','), Qt::SkipEmptyParts))
        settings.only.append(prefix.trimmed());
    if (parser.isSet(only)) {
        bool any = false;
        for (const ConformanceCheck &c : ConformanceRunner::battery())
            any = any || settings.selected(c.id);
        if (!any) {
            err << "mbscope conform: --only " << parser.value(only) << " selects no check (mbscope conform --list lists them)\n";
            return ExitUsage;
        }
    }
    if (parser.isSet(profile)) {
        const ProfileLoadResult loaded = ProfileLoader::load(parser.value(profile));
        if (!loaded.ok) {
            err << "mbscope conform: --profile " << parser.value(profile) << ":\n" << loaded.errorText() << '\n';
            return ExitUsage;
        }
        QString error;
        if (!settings.applyProfile(loaded.profile, &error)) {
            err << "mbscope conform: --profile: " << error << " (give --unit)\n";
            return ExitUsage;
        }
    }
    const bool force = parser.isSet(QStringLiteral("force"));
#ifndef MBSCOPE_HAVE_UI
    if (parser.isSet(pdf)) {
        err << "mbscope conform: --pdf: this mbscope was built without the GUI (MBSCOPE_BUILD_UI=OFF), so it writes no PDF; --html "
               "writes the same report\n";
        return ExitUsage;
    }
#endif
    for (const auto &[option, example] :
         {std::pair{&junit, "--junit conform.xml"}, std::pair{&html, "--html conform.html"}, std::pair{&pdf, "--pdf conform.pdf"}}) {
        if (!parser.isSet(*option))
            continue;
        const QString name = QStringLiteral("--") + option->names().constFirst();
        const QString problem = OutputPath::problem(name, parser.value(*option), QLatin1String(example), force);
        if (!problem.isEmpty()) {
            err << "mbscope conform: " << problem << '\n';
            return ExitUsage;
        }
    }
    RecordSettings record;
    if (!recordOptions.read(parser, QStringLiteral("conform"), record, err, parser.isSet(junit) || parser.isSet(html) || parser.isSet(pdf)))
        return ExitUsage;
    PrintSettings print;
    if (!printOptions.read(parser, QStringLiteral("conform"), force, print, err))
        return ExitUsage;
    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("conform"), arguments);
    metadata.target = settings.url.toString();
    if (!openRecording(recording, record, metadata, QStringLiteral("conform"), err))
        return ExitUsage;

    const bool asJson = parser.isSet(json);
    ConformanceRunner runner(settings);
    if (recording.isOpen())
        runner.setTrafficLog(recording.log());
    FrameLog frames;
    if (!openFrameLog(frames, print, QStringLiteral("conform"), err))
        return ExitUsage;
    if (frames.isOpen())
        runner.setFramesLogged([&frames](const QList<TrafficFrame> &batch, const QString &link) { frames.addFrames(batch, link); });
    InterruptWatcher interrupt;
    QObject::connect(&interrupt, &InterruptWatcher::interrupted, &interrupt, [&runner] { runner.stop(); });
    if (!asJson) {
        QStringList writes;
        for (const TableRange &r : settings.writable)
            writes.append(r.toString());
        out << "conform  " << settings.url.toString() << ", unit " << int(settings.unit) << " ("
            << (writes.isEmpty() ? QStringLiteral("reads only") : QString(QStringLiteral("writes allowed on ") + writes.join(QLatin1String(", "))))
            << ")\n";
        out.flush();
    }
    const ConformanceResult result = runner.run();
    finishRecording(recording, err);
    frames.close();
    if (result.linkFailed) {
        err << "mbscope conform: " << result.linkMessage << '\n';
        if (!asJson)
            return ExitLinkError;
    }
    if (asJson)
        out << QJsonDocument(result.toJson()).toJson(QJsonDocument::Indented);
    else if (!result.linkFailed)
        out << result.toText();
    out.flush();
    if (parser.isSet(junit) && !result.linkFailed) {
        QString error;
        if (!JUnitReport::write(result.toJUnit(), parser.value(junit), &error)) {
            err << "mbscope conform: --junit: " << error << '\n';
            return ExitUsage;
        }
        if (!asJson)
            out << "junit      " << parser.value(junit) << '\n';
    }
    if (parser.isSet(html) && !result.linkFailed) {
        QString error;
        if (!ConformanceHtml::write(result, parser.value(html), &error)) {
            err << "mbscope conform: --html: " << error << '\n';
            return ExitUsage;
        }
        if (!asJson)
            out << "html       " << parser.value(html) << '\n';
    }
#ifdef MBSCOPE_HAVE_UI
    if (parser.isSet(pdf) && !result.linkFailed) {
        QString error;
        if (!ConformancePdf::write(result, parser.value(pdf), &error)) {
            err << "mbscope conform: --pdf: " << error << '\n';
            return ExitUsage;
        }
        if (!asJson)
            out << "pdf        " << parser.value(pdf) << '\n';
    }
#endif
    if (result.linkFailed)
        return ExitLinkError;
    return result.passed() ? ExitOk : ExitFailure;
}

} // namespace mbscope::app
