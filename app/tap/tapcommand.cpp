#include "tap/tapcommand.h"

#include "common/cli.h"
#include "sim/faultswatcher.h"
#include "common/interruptwatcher.h"
#include "common/listenaddress.h"
#include "service/metricsendpoint.h"
#include "common/readyfile.h"
#include "common/recordoptions.h"
#include "sim/simulatesession.h"

#include "profile/profileloader.h"
#include "sim/simendpoint.h"
#include "tap/tapforwarder.h"
#include "tap/tapmetrics.h"
#include "time/duration.h"
#include "traffic/trafficrecording.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QEventLoop>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonArray>
#include <QtCore/QTextStream>
#include <QtCore/QTimer>

#include <chrono>
#include <memory>
#include <optional>

namespace mbscope::app {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;

// --timeout, --duration: a duration of at least 1 ms.
bool readMs(const QCommandLineParser &parser, const QCommandLineOption &option, qint64 *ms, QTextStream &err)
{
    if (!parser.isSet(option))
        return true;
    const QString text = parser.value(option);
    const DurationResult d = parseDuration(text);
    *ms = d.ns / Duration::Millisecond;
    if (!d.ok() || *ms <= 0) {
        err << "mbscope tap: --" << option.names().constFirst() << ": "
            << (d.ok() ? QStringLiteral("'%1' is less than 1 ms").arg(text) : d.error) << '\n';
        return false;
    }
    return true;
}

bool readCount(const QCommandLineParser &parser, const QCommandLineOption &option, int low, int high, int *value,
               QTextStream &err)
{
    if (!parser.isSet(option))
        return true;
    bool ok = false;
    const int n = parser.value(option).toInt(&ok);
    if (!ok || n < low || n > high) {
        err << "mbscope tap: --" << option.names().constFirst() << " '" << parser.value(option) << "': expected a number from "
            << low << " to " << high << '\n';
        return false;
    }
    *value = n;
    return true;
}

// "1 request", "2 requests": a count with its noun in the right number.
QString counted(quint64 n, const char *one, const char *many)
{
    return QStringLiteral("%1 %2").arg(n).arg(QLatin1String(n == 1 ? one : many));
}

QString countsLine(const TapCounters &c)
{
    QString line = QStringLiteral("tap: %1, %2 forwarded: %3 answered, %4 from devices, %5 without answer, "
                                  "%6, %7 damaged; %8, %9 without route, %10 refused")
                       .arg(counted(c.requests, "request", "requests"))
                       .arg(c.forwarded)
                       .arg(c.answered)
                       .arg(counted(c.exceptions, "exception", "exceptions"))
                       .arg(c.noAnswer)
                       .arg(counted(c.linkErrors, "link error", "link errors"))
                       .arg(c.damaged)
                       .arg(counted(c.broadcasts, "broadcast", "broadcasts"))
                       .arg(c.noRoute)
                       .arg(counted(c.refusedWrites, "write", "writes"));
    if (c.resent > 0)
        line += QStringLiteral("; %1 sent again after a link closed under them").arg(counted(c.resent, "read", "reads"));
    if (c.deviceLatencyCount > 0)
        line += QStringLiteral("; devices answered in %1 on average")
                    .arg(formatDuration(qint64(c.deviceLatencyNsSum / c.deviceLatencyCount)));
    return line;
}

} // namespace

int runTap(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The inline tap: masters (a SCADA, a PLC, mbpoll...) connect to the --listen URLs as if to the device; each request goes "
        "on to the device its unit's route names, over any link (a Modbus/TCP to RTU gateway, a proxy in front of a TCP device, "
        "a man in the middle between two serial ports), and its answer back to the master that asked, function code and data "
        "unchanged. One line per request (or a summary every 10 s with --quiet) and a summary at the end.\n"
        "--record FILE journals both legs: master to tap (the listening URL's link) and tap to device (the target's link), each "
        "with its own times, so analyze shows the device's own response time beside what the master saw.\n"
        "Example (with mbscope simulate --profile rosrao-gamma --listen rtu-tcp://127.0.0.1:4001 running; point a master "
        "at tcp://127.0.0.1:5020 within two seconds):\n"
        "  mbscope tap --listen tcp://127.0.0.1:5020 --target rtu-tcp://127.0.0.1:4001 --duration 2s\n"
        "Exit status: 0 after a clean stop (Ctrl-C or --duration), 2 for unusable options."));
    parser.addHelpOption();
    const QCommandLineOption listenOption(QStringLiteral("listen"),
                                          QStringLiteral("Where masters connect (repeatable): tcp://, rtu-tcp://, ascii-tcp://, udp://, rtu-udp://, "
                                                         "tls://, or a serial port rtu:///dev/ttyUSB0?baud=19200&parity=N (port 0: any free port)."),
                                          QStringLiteral("URL"));
    const QCommandLineOption targetOption(QStringLiteral("target"),
                                          QStringLiteral("The device every unit goes to (the route 0-255=URL), over any link mbscope has; its URL may "
                                                         "give timeout= and retries= as a route's does."),
                                          QStringLiteral("URL"));
    const QCommandLineOption routeOption(QStringLiteral("route"),
                                         QStringLiteral("Units to a device (repeatable; the first route that serves a unit takes it): "
                                                        "UNITS[:DEVICE_UNIT]=URL, e.g. 1-10=rtu:///dev/ttyUSB0 or 1:17=tcp://10.0.0.5:502 "
                                                        "(the master's unit 1 is the device's unit 17). A route's URL may give timeout= and retries= "
                                                        "(this route's response timeout and further attempts of a read)."),
                                         QStringLiteral("ROUTE"));
    const QCommandLineOption timeoutOption(QStringLiteral("timeout"),
                                           QStringLiteral("Response timeout of a forwarded request (default 1s), unless its route's URL gives timeout=."),
                                           QStringLiteral("TIME"));
    const QCommandLineOption retriesOption(QStringLiteral("retries"),
                                           QStringLiteral("Further attempts of a read after a timeout or a damaged answer (default 0), unless its route's "
                                                          "URL gives retries=; a write is sent once, as its master sent it."), QStringLiteral("N"));
    const QCommandLineOption noAnswerOption(QStringLiteral("no-answer"),
                                            QStringLiteral("What a master gets when its device does not answer (exception 0B) or no route serves "
                                                           "its unit (exception 0A): auto (exceptions to Modbus/TCP and UDP masters, silence to "
                                                           "serial ones; the default), exception, or silence."),
                                            QStringLiteral("auto|exception|silence"));
    const QCommandLineOption readOnlyOption(QStringLiteral("read-only"),
                                            QStringLiteral("Forward no write (05, 06, 0F, 10, 15, 16, 17) and no Diagnostics sub-function that "
                                                           "changes a device (08/01, 03, 04, 0A, 14): refused and counted."));
    const QCommandLineOption refuseOption(QStringLiteral("refuse"),
                                          QStringLiteral("How --read-only refuses: exception (01 illegal function; the default) or silence."),
                                          QStringLiteral("exception|silence"));
    const QCommandLineOption pipelineOption(QStringLiteral("pipeline"),
                                            QStringLiteral("Requests in flight at once on a Modbus/TCP, TLS or UDP target (default 1; serial "
                                                           "framings carry one at a time)."),
                                            QStringLiteral("N"));
    const QCommandLineOption faultsOption(QStringLiteral("faults"),
                                          QStringLiteral("Fault rules applied to the devices' answers on their way back (the simulator's rules, "
                                                         "docs/profiles.md \"Faults\"); read again whenever the file is saved."),
                                          QStringLiteral("FILE"));
    const QCommandLineOption seedOption(QStringLiteral("seed"), QStringLiteral("Seed of the fault rules' random draws."), QStringLiteral("N"));
    const QCommandLineOption durationOption(QStringLiteral("duration"),
                                            QStringLiteral("Stop after this long (60s, 500ms, 2min; a bare number is milliseconds)."),
                                            QStringLiteral("TIME"));
    const QCommandLineOption quietOption(QStringLiteral("quiet"), QStringLiteral("A summary every 10 s instead of one line per request."));
    const QCommandLineOption readyOption(QStringLiteral("ready-file"),
                                         QStringLiteral("Once every URL listens, write FILE with the listening URLs, one per line (the ports "
                                                        "chosen for port 0 included); removed when the tap stops."),
                                         QStringLiteral("FILE"));
    const QCommandLineOption metricsOption(QStringLiteral("metrics"),
                                           QStringLiteral("Serve Prometheus metrics at http://HOST:PORT/metrics (requests by outcome, requests "
                                                          "waiting, each leg's latency); a port alone listens on the loopback interface, port 0 "
                                                          "on any free port."),
                                           QStringLiteral("HOST:PORT"));
    parser.addOptions({listenOption, targetOption, routeOption, timeoutOption, retriesOption, noAnswerOption, readOnlyOption,
                       refuseOption, pipelineOption, faultsOption, seedOption, durationOption, quietOption, readyOption, metricsOption});
    const RecordOptions recordOptions;
    recordOptions.addTo(parser);
    if (!parser.parse(arguments)) {
        err << "mbscope tap: " << parser.errorText() << '\n';
        return kExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "tap");
        return kExitOk;
    }
    if (!parser.positionalArguments().isEmpty()) {
        err << "mbscope tap: unexpected argument '" << parser.positionalArguments().first() << "'\n";
        return kExitUsage;
    }
    RecordSettings record;
    if (!recordOptions.read(parser, QStringLiteral("tap"), record, err))
        return kExitUsage;
    if (!parser.isSet(listenOption)) {
        err << "mbscope tap: --listen URL is required (where masters connect, e.g. --listen tcp://127.0.0.1:5020)\n";
        return kExitUsage;
    }

    TapSettings settings;
    for (const QString &text : parser.values(routeOption)) {
        const TapRoute::Result route = TapRoute::parse(text);
        if (!route.route) {
            err << "mbscope tap: --route " << route.error << '\n';
            return kExitUsage;
        }
        settings.routes.append(*route.route);
    }
    if (parser.isSet(targetOption)) {
        const TapRoute::Result every = TapRoute::parseTarget(parser.value(targetOption));
        if (!every.route) {
            err << "mbscope tap: --target '" << parser.value(targetOption) << "': " << every.error << '\n';
            return kExitUsage;
        }
        settings.routes.append(*every.route); // after the routes: they take their units first
    }
    if (settings.routes.isEmpty()) {
        err << "mbscope tap: --target URL or --route UNITS=URL is required (where the requests go, e.g. --target "
               "rtu-tcp://127.0.0.1:4001)\n";
        return kExitUsage;
    }
    qint64 timeoutMs = settings.timeoutMs;
    qint64 durationMs = 0;
    if (!readMs(parser, timeoutOption, &timeoutMs, err) || !readMs(parser, durationOption, &durationMs, err))
        return kExitUsage;
    settings.timeoutMs = int(std::min<qint64>(timeoutMs, 3600000));
    if (!readCount(parser, retriesOption, 0, 100, &settings.retries, err)
        || !readCount(parser, pipelineOption, 1, 64, &settings.engine.pipelineDepth, err))
        return kExitUsage;
    if (parser.isSet(noAnswerOption)) {
        const QString v = parser.value(noAnswerOption);
        if (v == QLatin1String("auto"))
            settings.noAnswer = TapSettings::NoAnswer::Auto;
        else if (v == QLatin1String("exception"))
            settings.noAnswer = TapSettings::NoAnswer::Exception;
        else if (v == QLatin1String("silence"))
            settings.noAnswer = TapSettings::NoAnswer::Silence;
        else {
            err << "mbscope tap: --no-answer '" << v << "': expected auto, exception or silence\n";
            return kExitUsage;
        }
    }
    settings.readOnly = parser.isSet(readOnlyOption);
    if (parser.isSet(refuseOption)) {
        const QString v = parser.value(refuseOption);
        if (v != QLatin1String("exception") && v != QLatin1String("silence")) {
            err << "mbscope tap: --refuse '" << v << "': expected exception or silence\n";
            return kExitUsage;
        }
        if (!settings.readOnly) {
            err << "mbscope tap: --refuse says how --read-only refuses writes; without --read-only every write is forwarded\n";
            return kExitUsage;
        }
        settings.refusal = v == QLatin1String("silence") ? TapSettings::Refusal::Silence : TapSettings::Refusal::Exception;
    }
    std::optional<quint64> seed;
    if (parser.isSet(seedOption)) {
        bool ok = false;
        seed = parser.value(seedOption).toULongLong(&ok, 0);
        if (!ok) {
            err << "mbscope tap: --seed '" << parser.value(seedOption) << "' is not a number\n";
            return kExitUsage;
        }
    }
    DeviceProfile profile;
    profile.name = QStringLiteral("tap");
    std::optional<FaultRuleSet> faults;
    if (parser.isSet(faultsOption)) {
        FaultRulesLoadResult rules = ProfileLoader::loadFaults(parser.value(faultsOption));
        if (!rules.ok) {
            err << "mbscope tap: faults file '" << parser.value(faultsOption) << "':\n" << rules.errorText() << '\n';
            return kExitUsage;
        }
        faults = rules.rules;
        if (seed)
            faults->seed = *seed;
    }

    std::optional<ListenAddress> metricsAddress;
    if (parser.isSet(metricsOption)) {
        QString why;
        metricsAddress = ListenAddress::parse(parser.value(metricsOption), &why);
        if (!metricsAddress) {
            err << "mbscope tap: --metrics: " << why << '\n';
            return kExitUsage;
        }
    }

    ReadyFile ready;
    QString readyError;
    if (parser.isSet(readyOption) && !ready.prepare(parser.value(readyOption), &readyError)) {
        err << "mbscope tap: " << readyError << '\n';
        return kExitUsage;
    }

    SimulateSession::Options options;
    options.quiet = parser.isSet(quietOption);
    SimulateSession session(out, options);
    QString error;
    if (!session.load(profile, faults, &error)) {
        err << "mbscope tap: " << error << '\n';
        return kExitUsage;
    }
    TapForwarder forwarder(settings);
    session.setRemote(&forwarder);
    if (!session.listen(parser.values(listenOption), &error)) {
        err << "mbscope tap: " << error << '\n';
        return kExitUsage;
    }
    TapMetrics metrics(QStringLiteral(MBSCOPE_VERSION));
    std::unique_ptr<MetricsEndpoint> metricsEndpoint;
    if (metricsAddress) {
        forwarder.setMetrics(&metrics);
        metricsEndpoint = std::make_unique<MetricsEndpoint>(metrics.registry());
        metricsEndpoint->setBeforeScrape([&metrics, &forwarder] { metrics.update(forwarder.counters(), forwarder.waiting()); });
        if (!metricsEndpoint->listen(*metricsAddress, &error)) {
            err << "mbscope tap: --metrics: " << error << '\n';
            return kExitUsage;
        }
    }
    QObject::connect(&forwarder, &TapForwarder::targetMessage, &forwarder, [&out](const QString &target, const QString &message) {
        out << "target " << target << ": " << message << Qt::endl;
    });

    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("tap"), arguments);
    metadata.role = TrafficMetadata::Role::Server;
    for (SimEndpoint *endpoint : session.simulator().endpoints())
        metadata.listen.append(endpoint->name());
    QStringList routes;
    for (const TapRoute &route : std::as_const(settings.routes))
        routes.append(route.describe());
    metadata.settings.insert(QStringLiteral("routes"), QJsonArray::fromStringList(routes));
    if (settings.routes.size() == 1)
        metadata.target = settings.routes.constFirst().target.toString();
    if (parser.isSet(faultsOption))
        metadata.settings.insert(QStringLiteral("faults_file"), QFileInfo(parser.value(faultsOption)).absoluteFilePath());
    if (!openRecording(recording, record, metadata, QStringLiteral("tap"), err))
        return kExitUsage;
    if (recording.isOpen()) {
        session.setTrafficLog(recording.log());
        forwarder.setTrafficLog(recording.log());
    }

    QEventLoop loop;
    InterruptWatcher interrupts;
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &loop, &QEventLoop::quit);
    QStringList listening;
    for (SimEndpoint *endpoint : session.simulator().endpoints()) {
        listening.append(endpoint->name());
        out << "listening " << endpoint->name() << '\n';
    }
    for (const QString &route : std::as_const(routes))
        out << "route " << route << '\n';
    if (metricsEndpoint)
        out << "metrics at " << metricsEndpoint->url().toString() << '\n';
    if (settings.readOnly)
        out << "read-only: writes are " << (settings.refusal == TapSettings::Refusal::Silence ? "dropped" : "refused with exception 01")
            << '\n';
    out.flush();

    std::unique_ptr<FaultsWatcher> faultsWatcher;
    if (parser.isSet(faultsOption))
        faultsWatcher = std::make_unique<FaultsWatcher>(parser.value(faultsOption), &session.faultInjector(), seed, out);
    if (durationMs > 0)
        QTimer::singleShot(std::chrono::milliseconds(durationMs), &loop, &QEventLoop::quit);
    session.start();
    if (!ready.publish(listening, &readyError)) {
        session.stop();
        err << "mbscope tap: " << readyError << '\n';
        return kExitUsage;
    }
    loop.exec();
    session.stop();
    session.setTrafficLog(nullptr);
    forwarder.setTrafficLog(nullptr);
    session.setRemote(nullptr);
    out << (interrupts.isInterrupted() ? "interrupted: " : "stopped: ") << session.summary() << '\n'
        << countsLine(forwarder.counters()) << Qt::endl;
    finishRecording(recording, err);
    return kExitOk;
}

} // namespace mbscope::app
