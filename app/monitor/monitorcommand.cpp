#include "monitor/monitorcommand.h"

#include "common/cli.h"
#include "common/interruptwatcher.h"
#include "monitor/monitorreport.h"
#include "common/progressline.h"
#include "common/recordoptions.h"
#include "common/transactionreport.h"

#include "monitor/busmonitor.h"
#include "time/duration.h"
#include "traffic/trafficrecording.h"
#include "transport/linkurl.h"
#include "transport/monotonicclock.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QJsonDocument>
#include <QtCore/QTextStream>
#include <QtCore/QTimer>

namespace mbscope::app {

namespace {

// A duration option: false (with the message on err) when it is not one, or not above zero.
bool readDuration(const QCommandLineParser &parser, const QCommandLineOption &option, qint64 *ns, QTextStream &err)
{
    if (!parser.isSet(option))
        return true;
    const DurationResult d = parseDuration(parser.value(option));
    if (!d.ok() || d.ns <= 0) {
        err << "mbscope monitor: --" << option.names().constFirst() << ": "
            << (d.ok() ? QStringLiteral("'%1' is not above zero").arg(parser.value(option)) : d.error) << '\n';
        return false;
    }
    *ns = d.ns;
    return true;
}

} // namespace

int runMonitor(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Listens to a bus that another master drives and never sends a byte: an RS485 line through a serial port "
        "(rtu://, ascii://) or a serial device server's port (rtu-tcp://, ascii-tcp://). The serial port is opened for "
        "reading only. Frames are cut by the length rules and by the silence between them (t3.5 of the URL's baud "
        "rate, at least 2 ms; 20 ms on a device server), told apart as requests and answers (function code, the "
        "request waiting, the answer's length), paired by order, unit and function as analyze pairs a capture, and "
        "judged as poll judges an answer. Each exchange is printed as it is seen; the statistics at the end are "
        "those poll prints. Latency is the time from the request's last byte to the answer's last byte.\n"
        "Example (not run by the tests: it needs a bus another master drives; docs/guide/command-line.md runs one on a "
        "simulated bus):\n"
        "  mbscope monitor \"rtu:///dev/ttyUSB0?baud=9600&parity=N\" --duration 60s --record bus.mbscope.journal\n"
        "A live line is shown on a terminal; Ctrl-C stops and prints the statistics.\n"
        "Exit status: 0 every exchange ok, 1 some failed or damaged frames were seen, 2 usage or link error (the "
        "port cannot be opened, or was lost), 3 nothing was heard (not one byte)."));
    parser.addHelpOption();
    const QCommandLineOption countOpt(QStringLiteral("count"), QStringLiteral("Stop after N transactions."), QStringLiteral("N"));
    const QCommandLineOption durationOpt(QStringLiteral("duration"),
                                         QStringLiteral("Stop after this long (60s, 500ms, 2min, 1h; a bare number is milliseconds)."),
                                         QStringLiteral("TIME"));
    const QCommandLineOption timeoutOpt(QStringLiteral("timeout"),
                                        QStringLiteral("How long a request waits for its answer before it counts as a timeout "
                                                       "(default: the URL's timeout=, else 1s)."),
                                        QStringLiteral("TIME"));
    const QCommandLineOption silenceOpt(QStringLiteral("silence"),
                                        QStringLiteral("The quiet time that ends a frame (default: t3.5 of the baud rate, at "
                                                       "least 2ms; 20ms on rtu-tcp and ascii-tcp)."),
                                        QStringLiteral("TIME"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print the statistics as JSON (poll --json's shape, with \"bus\": what "
                                                    "the line carried) and no line per exchange."));
    const QCommandLineOption quietOpt(QStringLiteral("quiet"), QStringLiteral("No line per exchange: the statistics only."));
    parser.addOptions({countOpt, durationOpt, timeoutOpt, silenceOpt, jsonOpt, quietOpt});
    const RecordOptions recordOptions;
    recordOptions.addTo(parser);
    parser.addPositionalArgument(QStringLiteral("url"),
                                 QStringLiteral("The line: rtu:///dev/ttyUSB0?baud=9600&parity=N, ascii://..., "
                                                "rtu-tcp://host:4001 or ascii-tcp://host:port."));
    if (!parser.parse(arguments)) {
        err << "mbscope monitor: " << parser.errorText() << '\n';
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << subcommandHelp(parser.helpText(), "monitor");
        return ExitOk;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1) {
        err << "mbscope monitor: "
            << (positional.isEmpty() ? QStringLiteral("no URL given") : QStringLiteral("one URL at a time"))
            << ": mbscope monitor URL [options], e.g. mbscope monitor \"rtu:///dev/ttyUSB0?baud=9600&parity=N\"\n";
        return ExitUsage;
    }
    const LinkUrl::Result parsed = LinkUrl::parse(positional.constFirst());
    if (!parsed.url) {
        err << "mbscope monitor: " << parsed.error << '\n';
        return ExitUsage;
    }
    const LinkUrl url = *parsed.url;
    const QString unsupported = BusMonitor::unsupportedReason(url);
    if (!unsupported.isEmpty()) {
        err << "mbscope monitor: " << positional.constFirst() << ": " << unsupported << '\n';
        return ExitUsage;
    }
    quint64 count = 0;
    if (parser.isSet(countOpt)) {
        bool ok = false;
        count = parser.value(countOpt).toULongLong(&ok);
        if (!ok || count == 0) {
            err << "mbscope monitor: --count '" << parser.value(countOpt) << "' is not a whole number above zero\n";
            return ExitUsage;
        }
    }
    qint64 durationNs = 0;
    BusMonitor::Options options;
    if (!readDuration(parser, durationOpt, &durationNs, err) || !readDuration(parser, timeoutOpt, &options.answerTimeoutNs, err)
        || !readDuration(parser, silenceOpt, &options.silenceNs, err))
        return ExitUsage;
    if (parser.isSet(timeoutOpt) && url.responseTimeoutMs > 0) {
        err << "mbscope monitor: --timeout and the URL's timeout= both say how long a request waits: give one\n";
        return ExitUsage;
    }
    RecordSettings record;
    if (!recordOptions.read(parser, QStringLiteral("monitor"), record, err))
        return ExitUsage;
    const bool json = parser.isSet(jsonOpt);
    const bool lines = !json && !parser.isSet(quietOpt);

    BusMonitor monitor(url, options);
    TrafficRecording recording;
    TrafficMetadata metadata = commandMetadata(QStringLiteral("monitor"), arguments);
    metadata.role = TrafficMetadata::Role::Client; // read back as the master saw the line
    metadata.target = url.toString();
    metadata.settings.insert(QStringLiteral("listen_only"), true);
    metadata.settings.insert(QStringLiteral("timeout_ms"), double(url.responseTimeoutMs > 0 ? url.responseTimeoutMs * 1'000'000LL
                                                                                             : options.answerTimeoutNs) / 1e6);
    if (!openRecording(recording, record, metadata, QStringLiteral("monitor"), err))
        return ExitUsage;
    if (recording.isOpen())
        monitor.setTrafficLog(recording.log());

    QEventLoop loop;
    InterruptWatcher interrupts;
    ProgressLine line;
    QElapsedTimer clock;
    MonitorStop stop = MonitorStop::Count;
    bool linkLost = false;
    bool wasOpen = false;
    QString linkMessage;
    qint64 lastLatencyNs = -1;
    const auto finish = [&](MonitorStop why) {
        stop = why;
        loop.quit();
    };
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &loop, [&] { finish(MonitorStop::Interrupted); });
    QObject::connect(&monitor, &BusMonitor::linkFailed, &loop, [&](const QString &message) {
        linkLost = true;
        linkMessage = message;
        finish(MonitorStop::LinkLost);
    });
    QObject::connect(&monitor, &BusMonitor::opened, &loop, [&] {
        wasOpen = true;
        clock.start();
        err << "mbscope monitor: listening on " << url.toString() << " (listen-only: nothing is sent)\n";
        err.flush();
    });
    QObject::connect(&monitor, &BusMonitor::exchangeObserved, &loop, [&](const CaptureExchange &exchange) {
        if (exchange.transaction.latencyNs() >= 0 && exchange.kind == CaptureExchange::Kind::Transaction)
            lastLatencyNs = exchange.transaction.latencyNs();
        if (lines) {
            line.clear();
            out << MonitorReport::exchangeLine(exchange) << '\n';
            out.flush();
        }
        if (count > 0 && monitor.statistics().count() >= count)
            finish(MonitorStop::Count);
    });
    QTimer durationTimer;
    durationTimer.setSingleShot(true);
    durationTimer.setTimerType(Qt::PreciseTimer); // a coarse timer may end a 1 s run 50 ms early
    if (durationNs > 0) {
        QObject::connect(&monitor, &BusMonitor::opened, &durationTimer, [&] {
            durationTimer.start(std::chrono::milliseconds(qMax<qint64>(1, durationNs / 1'000'000)));
        });
        QObject::connect(&durationTimer, &QTimer::timeout, &loop, [&] { finish(MonitorStop::Duration); });
    }
    QTimer liveTimer;
    if (line.isEnabled()) {
        QObject::connect(&liveTimer, &QTimer::timeout, &loop, [&] {
            if (!wasOpen)
                return;
            const Statistics &s = monitor.statistics();
            QString text = QStringLiteral("%1 transactions").arg(s.count());
            if (count > 0)
                text += QStringLiteral("/%1").arg(count);
            text += QStringLiteral("  ok %1  failed %2  crc errors %3").arg(s.ok()).arg(s.failed()).arg(monitor.bus().crcErrors);
            if (lastLatencyNs >= 0)
                text += QStringLiteral("  last %1").arg(latencyText(lastLatencyNs));
            text += QStringLiteral("  %1 s  (Ctrl-C stops)").arg(QString::number(double(clock.nsecsElapsed()) / 1e9, 'f', 1));
            line.show(text);
        });
        liveTimer.start(200);
    }

    monitor.start();
    loop.exec();
    const qint64 elapsedNs = wasOpen ? clock.nsecsElapsed() : 0;
    monitor.stop();
    line.clear();
    finishRecording(recording, err);
    if (linkLost && !wasOpen) {
        err << "mbscope monitor: " << linkMessage << '\n';
        return ExitLinkError;
    }
    if (json)
        out << QJsonDocument(MonitorReport::json(monitor, elapsedNs, stop)).toJson(QJsonDocument::Indented);
    else
        out << MonitorReport::text(monitor, elapsedNs, stop);
    out.flush();
    if (linkLost) {
        err << "mbscope monitor: " << linkMessage << '\n';
        return ExitLinkError;
    }
    const int status = MonitorReport::exitStatus(monitor);
    if (status == ExitNothingHeard)
        err << "mbscope monitor: nothing was heard: not one byte came from " << url.toString() << " in "
            << QString::number(double(elapsedNs) / 1e9, 'f', 1)
            << " s (an idle bus, or a wrong port, baud rate or wiring); exit status 3\n";
    return status;
}

} // namespace mbscope::app
