#include "sim/simulatecommand.h"

#include "time/duration.h"

#include "common/cli.h"
#include "sim/faultswatcher.h"
#include "common/interruptwatcher.h"
#include "common/readyfile.h"
#include "common/recordoptions.h"
#include "sim/simulatesession.h"

#include "profile/profileloader.h"
#include "sim/simendpoint.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QCoreApplication>
#include <QtCore/QEventLoop>
#include <QtCore/QFileInfo>
#include <QtCore/QTextStream>
#include <QtCore/QTimer>

#include <chrono>
#include <memory>
#include <optional>

namespace mbscope::app {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;

void listProfiles(QTextStream &out)
{
    const QList<ShippedProfile> profiles = ProfileLoader::shippedProfiles();
    for (const ShippedProfile &p : profiles)
        out << p.name << "\n    " << p.description << "\n";
    if (profiles.isEmpty())
        out << "(no profiles are compiled into this executable)\n";
}

QString knownProfileNames()
{
    QStringList names;
    for (const ShippedProfile &p : ProfileLoader::shippedProfiles())
        names << p.name;
    return names.join(QStringLiteral(", "));
}

} // namespace

int runSimulate(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Serves a device profile as a Modbus server until Ctrl-C (or --duration), printing one line per request "
        "(or a summary every 10 s with --quiet) and a summary at the end.\n"
        "Profiles: a shipped one by name (see --list-profiles) or a JSON file (docs/profiles.md).\n"
        "--record FILE journals every request and answer (both directions, with the fault rules that shaped each answer) "
        "for analyze, export and replay.\n"
        "Example, the RosRao detector behind a serial device server, for ten seconds:\n"
        "  mbscope simulate --profile rosrao-gamma --listen rtu-tcp://127.0.0.1:4001 --duration 10s\n"
        "Exit status: 0 after a clean stop, 2 for unusable options (unknown profile, bad URL, port in use, bad faults file)."));
    parser.addHelpOption();
    const QCommandLineOption profileOption(QStringLiteral("profile"), QStringLiteral("Profile name or JSON file."),
                                           QStringLiteral("NAME|FILE"));
    const QCommandLineOption listenOption(QStringLiteral("listen"),
                                          QStringLiteral("Listen URL (repeatable; default: the profile's endpoints), "
                                                         "e.g. tcp://127.0.0.1:1502, rtu-tcp://127.0.0.1:0 (port 0: any free port), "
                                                         "rtu:///dev/pts/5?baud=9600&parity=N."),
                                          QStringLiteral("URL"));
    const QCommandLineOption faultsOption(QStringLiteral("faults"),
                                          QStringLiteral("Fault rules file ({\"seed\": N, \"rules\": [...]}); replaces the profile's rules, and is read again whenever it is saved while the simulator runs."),
                                          QStringLiteral("FILE"));
    // --log FILE wrote JSON lines nothing else read; --record FILE replaced it (a journal that
    // analyze, export --jsonl and replay read). Kept hidden to say so.
    QCommandLineOption logOption(QStringLiteral("log"), QStringLiteral("Replaced by --record."), QStringLiteral("FILE"));
    logOption.setFlags(QCommandLineOption::HiddenFromHelp);
    const RecordOptions recordOptions;
    const QCommandLineOption durationOption(QStringLiteral("duration"),
                                            QStringLiteral("Stop after this long (60s, 500ms, 2min, 1h; a bare number is milliseconds)."), QStringLiteral("TIME"));
    const QCommandLineOption quietOption(QStringLiteral("quiet"), QStringLiteral("A summary every 10 s instead of one line per request."));
    const QCommandLineOption seedOption(QStringLiteral("seed"),
                                        QStringLiteral("Seed of the value generators and fault rules (default: the profile's and faults file's)."),
                                        QStringLiteral("N"));
    const QCommandLineOption readyOption(QStringLiteral("ready-file"),
                                         QStringLiteral("Once every endpoint listens, write FILE (atomically) with the listening URLs, one per line "
                                                        "(the ports chosen for port 0 included); it is removed when the simulator stops, and a "
                                                        "file left by an earlier run is removed at start. Scripts wait for it: "
                                                        "until [ -e FILE ]; do sleep 0.1; done"),
                                         QStringLiteral("FILE"));
    const QCommandLineOption listOption(QStringLiteral("list-profiles"), QStringLiteral("List the shipped profiles and exit."));
    parser.addOptions({profileOption, listenOption, faultsOption, durationOption, quietOption, seedOption, readyOption, listOption, logOption});
    recordOptions.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope simulate: " << parser.errorText() << '\n';
        return kExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "simulate");
        return kExitOk;
    }
    if (parser.isSet(listOption)) {
        listProfiles(out);
        return kExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "mbscope simulate: unexpected argument '" << parser.positionalArguments().first() << "'\n";
        return kExitUsage;
    }
    if (parser.isSet(logOption)) {
        err << "mbscope simulate: --log was replaced by --record FILE: a traffic journal (analyze, export and replay read "
            << "it; mbscope export FILE --jsonl OUT writes JSON lines)\n";
        return kExitUsage;
    }
    RecordSettings record;
    if (!recordOptions.read(parser, QStringLiteral("simulate"), record, err))
        return kExitUsage;
    if (!parser.isSet(profileOption)) {
        err << "mbscope simulate: --profile NAME|FILE is required; shipped profiles: " << knownProfileNames() << '\n';
        return kExitUsage;
    }

    qint64 durationMs = 0;
    if (parser.isSet(durationOption)) {
        const DurationResult d = parseDuration(parser.value(durationOption));
        durationMs = d.ns / Duration::Millisecond;
        if (!d.ok() || durationMs <= 0) {
            err << "mbscope simulate: --duration: " << (d.ok() ? QStringLiteral("'%1' is less than 1 ms").arg(parser.value(durationOption)) : d.error)
                << '\n';
            return kExitUsage;
        }
    }
    std::optional<quint64> seed;
    if (parser.isSet(seedOption)) {
        bool ok = false;
        seed = parser.value(seedOption).toULongLong(&ok, 0);
        if (!ok) {
            err << "mbscope simulate: --seed '" << parser.value(seedOption) << "' is not a number\n";
            return kExitUsage;
        }
    }

    const QString profileName = parser.value(profileOption);
    if (!ProfileLoader::isPath(profileName)) {
        bool known = false;
        for (const ShippedProfile &p : ProfileLoader::shippedProfiles())
            known = known || p.name == profileName;
        if (!known) {
            err << "mbscope simulate: unknown profile '" << profileName << "'; shipped profiles: " << knownProfileNames()
                << " (or give a JSON file's path)\n";
            return kExitUsage;
        }
    }
    ProfileLoadResult loaded = ProfileLoader::load(profileName);
    if (!loaded.ok) {
        err << "mbscope simulate: profile '" << profileName << "':\n" << loaded.errorText() << '\n';
        return kExitUsage;
    }
    for (const ProfileProblem &warning : loaded.warnings)
        err << "mbscope simulate: warning: " << warning.toString() << '\n';
    err.flush();
    DeviceProfile profile = loaded.profile;
    std::optional<FaultRuleSet> faults;
    if (parser.isSet(faultsOption)) {
        FaultRulesLoadResult rules = ProfileLoader::loadFaults(parser.value(faultsOption));
        if (!rules.ok) {
            err << "mbscope simulate: faults file '" << parser.value(faultsOption) << "':\n" << rules.errorText() << '\n';
            return kExitUsage;
        }
        faults = rules.rules;
    }
    if (seed) {
        profile.seed = *seed;
        profile.faults.seed = *seed;
        if (faults)
            faults->seed = *seed;
    }
    const QStringList urls = parser.isSet(listenOption) ? parser.values(listenOption) : profile.endpoints;
    if (urls.isEmpty()) {
        err << "mbscope simulate: profile '" << profile.name << "' names no endpoint: give one with --listen URL\n";
        return kExitUsage;
    }

    ReadyFile ready;
    QString readyError;
    if (parser.isSet(readyOption) && !ready.prepare(parser.value(readyOption), &readyError)) {
        err << "mbscope simulate: " << readyError << '\n';
        return kExitUsage;
    }

    SimulateSession::Options options;
    options.quiet = parser.isSet(quietOption);
    SimulateSession session(out, options);
    QString error;
    if (!session.load(profile, faults, &error)) {
        err << "mbscope simulate: profile '" << profile.name << "': " << error << '\n';
        return kExitUsage;
    }
    if (!session.listen(urls, &error)) {
        err << "mbscope simulate: " << error << '\n';
        return kExitUsage;
    }
    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("simulate"), arguments);
    metadata.role = TrafficMetadata::Role::Server;
    for (SimEndpoint *endpoint : session.simulator().endpoints())
        metadata.listen.append(endpoint->name());
    metadata.profileName = profile.name;
    metadata.profileSource = profile.source;
    metadata.settings.insert(QStringLiteral("seed"), QString::number(profile.seed));
    if (parser.isSet(faultsOption))
        metadata.settings.insert(QStringLiteral("faults_file"), QFileInfo(parser.value(faultsOption)).absoluteFilePath());
    if (!openRecording(recording, record, metadata, QStringLiteral("simulate"), err))
        return kExitUsage;
    if (recording.isOpen())
        session.setTrafficLog(recording.log());

    // Ctrl-C and SIGTERM are caught before the header says the simulator listens: a stop sent
    // right after "listening" ends it cleanly, with its summary, instead of killing it.
    QEventLoop loop;
    InterruptWatcher interrupts;
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &loop, &QEventLoop::quit);
    out << "simulating " << profile.name << " (" << profile.source << ", seed " << profile.seed << ")\n";
    for (const QString &line : session.endpointDescriptions())
        out << "listening " << line << '\n';
    out.flush();

    std::unique_ptr<FaultsWatcher> faultsWatcher;
    if (parser.isSet(faultsOption))
        faultsWatcher = std::make_unique<FaultsWatcher>(parser.value(faultsOption), &session.faultInjector(), seed, out);

    if (durationMs > 0)
        QTimer::singleShot(std::chrono::milliseconds(durationMs), &loop, &QEventLoop::quit);
    session.start();
    QStringList listening;
    for (SimEndpoint *endpoint : session.simulator().endpoints())
        listening.append(endpoint->name());
    if (!ready.publish(listening, &readyError)) {
        session.stop();
        err << "mbscope simulate: " << readyError << '\n';
        return kExitUsage;
    }
    loop.exec();
    session.stop();
    session.setTrafficLog(nullptr);
    out << (interrupts.isInterrupted() ? "interrupted: " : "stopped: ") << session.summary() << Qt::endl;
    finishRecording(recording, err);
    return kExitOk;
}

} // namespace mbscope::app
