#include "poll/polloptions.h"

#include "poll/devicepace.h"
#include "poll/profilelimits.h"

#include "time/duration.h"
#include "plot/histogramplot.h"
#include "common/outputpath.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

// Far more in flight than any gateway buffers; MBAP transaction ids would allow 65536.
constexpr int kMaxPipeline = 1000;

} // namespace

PollOptions::PollOptions(bool sweep)
    : m_sweep(sweep)
    , m_command(sweep ? QStringLiteral("sweep") : QStringLiteral("poll"))
    , m_requests(RequestOptions::Hex | RequestOptions::Read | RequestOptions::Write, true)
    , m_interval(QStringList{QStringLiteral("l"), QStringLiteral("interval")},
                 QStringLiteral("Time from the start of one cycle to the start of the next: 100ms, 1s..., a bare number "
                                "in milliseconds as mbpoll's -l (default 1s; 0: back to back)."),
                 QStringLiteral("duration"), QStringLiteral("1s"))
    , m_intervals(QStringLiteral("intervals"),
                  QStringLiteral("The poll intervals to run, in order, separated by commas: 100,200,300 (bare numbers "
                                 "are milliseconds) or 100ms,1s."),
                  QStringLiteral("list"))
    , m_count(QStringLiteral("count"),
              sweep ? QStringLiteral("Cycles (polls) per interval.") : QStringLiteral("Cycles (polls) to run; each cycle "
                                                                                      "sends every request once."),
              QStringLiteral("n"))
    , m_duration(QStringLiteral("duration"),
                 sweep ? QStringLiteral("How long each interval runs (with or instead of --count): 60s, 5min...")
                       : QStringLiteral("How long to poll (with or instead of --count): 60s, 5min... Without --count and "
                                        "--duration the poll runs until Ctrl-C."),
                 QStringLiteral("duration"))
    , m_once(QStringList{QStringLiteral("1"), QStringLiteral("once")},
             QStringLiteral("Poll once: --count 1 (mbpoll's -1)."))
    , m_pipeline(QStringLiteral("pipeline"),
                 QStringLiteral("Requests in flight at once, with distinct transaction ids (tcp, tls and udp targets; "
                                "default 1)."),
                 QStringLiteral("n"), QStringLiteral("1"))
    , m_stats(QStringLiteral("stats"),
              QStringLiteral("Detailed statistics: the latency histogram as text, and what the engine counted "
                             "(retries, late and unsolicited answers, bytes, connections)%1.")
                  .arg(sweep ? QStringLiteral("; each interval's full statistics") : QString()))
    , m_histogram(QStringLiteral("histogram"),
                  QStringLiteral("Draw the latency histogram into the file: .png, .svg or .pdf by its extension (no display needed)."),
                  QStringLiteral("file"))
    , m_json(QStringLiteral("json"), QStringLiteral("Print the statistics as JSON."))
    , m_print(!sweep)
    , m_csv(QStringLiteral("csv"),
            QStringLiteral("Write one CSV row per transaction as it happens: time, item, status, latency_ms, then the values "
                           "(a column per --format)."),
            QStringLiteral("file"))
    , m_gap(QStringLiteral("gap"),
            QStringLiteral("The device's pace: no request sooner than this after the previous one was sent or its "
                           "exchange ended (answer or timeout): 50ms... (default: the --profile's minGapMs and 1 ms, "
                           "else 0)."),
            QStringLiteral("duration"))
    , m_warmUp(QStringLiteral("warm-up"),
               QStringLiteral("After the link opens (each time), wait this long before the first request: 2s... "
                              "(default: the --profile's warmUpMs and a tenth, at least 2 ms, else 0)."),
               QStringLiteral("duration"))
    , m_profile(QStringLiteral("profile"),
                QStringLiteral("Honour the limits of a device profile (shipped name or JSON file, as scan --profile-out "
                               "writes them): its minGapMs and warmUpMs (unless --gap or --warm-up is given), and reads "
                               "built with --function or -t that ask more than its maxQuantity are cut into "
                               "several; a device that hangs up after each answer (closesAfterAnswer) gets a new connection for "
                               "each request."),
                QStringLiteral("profile"))
{
}

void PollOptions::addTo(QCommandLineParser &parser) const
{
    m_target.addTo(parser);
    m_requests.addTo(parser);
    parser.addOption(m_sweep ? m_intervals : m_interval);
    parser.addOptions({m_count, m_duration, m_pipeline, m_gap, m_warmUp, m_profile, m_stats, m_histogram, m_json});
    if (!m_sweep)
        parser.addOptions({m_once, m_csv});
    m_print.addTo(parser);
    m_record.addTo(parser);
}

bool PollOptions::read(const QCommandLineParser &parser, PollConfig &out, QTextStream &err) const
{
    const QString prefix = QStringLiteral("mbscope %1: ").arg(m_command);
    if (!m_target.read(parser, m_command, out.target, err))
        return false;

    if (m_sweep) {
        if (!parser.isSet(m_intervals)) {
            err << prefix << "--intervals is required: the poll intervals to compare, e.g. --intervals 100,200,300,400\n";
            return false;
        }
        const DurationListResult list = parseDurationList(parser.value(m_intervals));
        if (!list.ok) {
            err << prefix << "--intervals: " << list.error << '\n';
            return false;
        }
        out.settings.intervalsNs = list.ns;
    } else {
        const DurationResult interval = parseDuration(parser.value(m_interval));
        if (!interval.ok()) {
            err << prefix << "--interval: " << interval.error << '\n';
            return false;
        }
        out.settings.poll.intervalNs = interval.ns;
        out.settings.intervalsNs = {interval.ns};
    }

    if (parser.isSet(m_count)) {
        const IntegerResult count = parseInteger(QStringLiteral("--count"), parser.value(m_count), 1,
                                                 1'000'000'000LL, QStringLiteral("cycles"));
        if (!count.ok) {
            err << prefix << count.error << '\n';
            return false;
        }
        out.settings.poll.count = quint64(count.value);
    }
    if (!m_sweep && parser.isSet(m_once)) {
        if (parser.isSet(m_count) || parser.isSet(m_duration)) {
            err << prefix << "-1/--once is --count 1: give it without --count and --duration\n";
            return false;
        }
        out.settings.poll.count = 1;
    }
    if (parser.isSet(m_duration)) {
        const DurationResult duration = parseDuration(parser.value(m_duration));
        if (!duration.ok()) {
            err << prefix << "--duration: " << duration.error << '\n';
            return false;
        }
        if (duration.ns == 0) {
            err << prefix << "--duration 0 would poll nothing: give a length such as 60s\n";
            return false;
        }
        out.settings.poll.durationNs = duration.ns;
    }
    if (m_sweep && out.settings.poll.count == 0 && out.settings.poll.durationNs == 0) {
        err << prefix << "give --count (cycles per interval) or --duration (time per interval): without them the "
            << "first interval would never end\n";
        return false;
    }

    const IntegerResult pipeline = parseInteger(QStringLiteral("--pipeline"), parser.value(m_pipeline), 1, kMaxPipeline);
    if (!pipeline.ok) {
        err << prefix << pipeline.error << '\n';
        return false;
    }
    const Framing framing = out.target.url.framing();
    const bool mbap = !out.target.url.delimited.enabled && (framing == Framing::Tcp || framing == Framing::Udp);
    if (pipeline.value > 1 && !mbap) {
        err << prefix << "--pipeline " << pipeline.value << ": pipelining needs MBAP transaction ids to tell answers "
            << "apart (tcp://, tls:// and udp:// targets); " << LinkUrl::schemeName(out.target.url.kind) << "://"
            << (out.target.url.delimited.enabled ? " with delimited framing" : "")
            << " carries one request at a time\n";
        return false;
    }
    out.engine.pipelineDepth = int(pipeline.value);
    DeviceLimits limits;
    if (parser.isSet(m_profile)) {
        out.profile = parser.value(m_profile);
        QString error;
        const std::optional<DeviceLimits> loaded = ProfileLimits::load(out.profile, &error);
        if (!loaded) {
            err << prefix << "--profile " << out.profile << ":\n" << error << '\n';
            return false;
        }
        limits = *loaded;
    }
    // The profile's waits with some to spare (DeviceLimits::clientGap); --gap and --warm-up win;
    // the target's own (gap=, warmup=) holds when longer, as the engine keeps it
    // (EngineOptions::withPaceOf).
    const QString ofProfile = QStringLiteral(" of --profile %1").arg(out.profile);
    const LinkUrl &url = out.target.url;
    const struct {
        const QCommandLineOption *option;
        std::chrono::nanoseconds *value;
        std::chrono::nanoseconds fromProfile;
        std::chrono::nanoseconds fromTarget;
        QString what;
        QString limit;
        const char *urlKey;
    } waits[] = {
        {&m_gap, &out.engine.requestGap, limits.clientGap(), url.gap, QStringLiteral("gap %1 between requests"),
         QStringLiteral("minGapMs %1%2, 1 ms to spare").arg(limits.minGapMs).arg(ofProfile), "gap"},
        {&m_warmUp, &out.engine.warmUp, limits.clientWarmUp(), url.warmUp, QStringLiteral("warm-up %1 after connecting"),
         QStringLiteral("warmUpMs %1%2, a tenth to spare").arg(limits.warmUpMs).arg(ofProfile), "warmup"},
    };
    for (const auto &wait : waits) {
        QString source = wait.limit;
        *wait.value = wait.fromProfile;
        if (parser.isSet(*wait.option)) {
            const DurationResult d = parseDuration(parser.value(*wait.option));
            if (!d.ok()) {
                err << prefix << "--" << wait.option->names().constFirst() << ": " << d.error << '\n';
                return false;
            }
            *wait.value = std::chrono::nanoseconds(d.ns);
            source = QStringLiteral("--") + wait.option->names().constFirst();
        }
        if (wait.fromTarget > *wait.value) {
            *wait.value = wait.fromTarget;
            source = QStringLiteral("%1= of --target").arg(QLatin1String(wait.urlKey));
        }
        // A wait turned off with --gap 0 or --warm-up 0 is said too: it overrides the profile's.
        if (wait.value->count() > 0)
            out.pace.append(wait.what.arg(formatDuration(wait.value->count())) + QStringLiteral(" (%1)").arg(source));
        else if (parser.isSet(*wait.option))
            out.pace.append(QStringLiteral("no %1 (%2 0)").arg(QLatin1String(wait.urlKey) == QLatin1String("gap") ? QStringLiteral("gap")
                                                                                                               : QStringLiteral("warm-up"),
                                                           source));
    }
    out.engine.closeAfterAnswer = limits.closesAfterAnswer || url.closeAfterAnswer;
    if (out.engine.closeAfterAnswer)
        out.pace.append(QStringLiteral("a new connection for each request (%1)")
                            .arg(url.closeAfterAnswer ? QStringLiteral("close=each of --target")
                                                      : QStringLiteral("closesAfterAnswer") + ofProfile));
    if (!out.profile.isEmpty() && !limits.limitsRequests() && !limits.closesAfterAnswer)
        out.pace.append(QStringLiteral("none from --profile %1: it has no minGapMs, warmUpMs, maxQuantity or closesAfterAnswer")
                            .arg(out.profile));
    // One request at a time when each must wait for the one before it.
    if (out.engine.pipelineDepth > 1 && (out.engine.requestGap.count() > 0 || out.engine.closeAfterAnswer)) {
        err << prefix << "--pipeline " << out.engine.pipelineDepth << ": one request at a time: "
            << (out.engine.closeAfterAnswer ? "the device hangs up after each answer" : "each request waits the gap after the one before it")
            << Qt::endl;
        out.engine.pipelineDepth = 1;
    }

    // --record and --force first: --force is the policy for --histogram and --csv too.
    if (!m_record.read(parser, m_command, out.record, err,
                       parser.isSet(m_histogram) || (!m_sweep && parser.isSet(m_csv)) || m_print.frameLogSet(parser)))
        return false;
    const bool force = out.record.overwrite;
    if (!m_print.read(parser, m_command, force, out.print, err))
        return false;
    if (parser.isSet(m_histogram)) {
        if (!HistogramPlot::isAvailable()) {
            err << prefix << "--histogram: " << HistogramPlot::unavailableReason() << '\n';
            return false;
        }
        const QString path = parser.value(m_histogram);
        // Said now, not after a 60 s poll: the name, the folder and the format the name says.
        const QString problem = OutputPath::plotProblem(QStringLiteral("--histogram"), path, force);
        if (!problem.isEmpty()) {
            err << prefix << problem << '\n';
            return false;
        }
        out.histogramPath = path;
    }
    out.stats = parser.isSet(m_stats);
    out.json = parser.isSet(m_json);
    if (out.print.values) {
        if (out.json) {
            err << prefix << "--print values writes text lines, --json one JSON document: give one of them (--csv FILE "
                << "keeps every answer's values with --json)\n";
            return false;
        }
        out.printValues = true;
    }
    if (!m_sweep && parser.isSet(m_csv)) {
        const QString path = parser.value(m_csv);
        const QString problem = OutputPath::problem(QStringLiteral("--csv"), path, QStringLiteral("--csv poll.csv"), force);
        if (!problem.isEmpty()) {
            err << prefix << problem << '\n';
            return false;
        }
        out.csvPath = path;
    }
    if (!m_requests.read(parser, m_command, out.target, out.plan, err))
        return false;
    // Said before the first request: what the poll sends differs from what was typed, or the
    // device is likely to refuse it.
    const DevicePace::Fit fit = DevicePace::fitReads(out.plan, limits.maxQuantity, out.target.url,
                                                     QStringLiteral("--profile %1").arg(out.profile));
    for (const QString &note : fit.notes)
        err << prefix << note << '\n';
    err.flush();
    if (!limits.maxQuantity.isEmpty()) {
        QStringList largest;
        for (auto it = limits.maxQuantity.cbegin(); it != limits.maxQuantity.cend(); ++it)
            largest.append(QStringLiteral("%1 %2").arg(DeviceLimits::functionKey(it.key())).arg(it.value()));
        const QString of = QStringLiteral("maxQuantity %1%2").arg(largest.join(QStringLiteral(", ")), ofProfile);
        // Said as it happened: a read cut, one sent over the limit as given (--hex, a write), or none over it.
        QStringList said;
        if (fit.cut > 0)
            said.append(QStringLiteral("reads cut to %1").arg(of));
        if (fit.sentOver > 0)
            said.append(QStringLiteral("%1 request(s) over %2 sent as given").arg(fit.sentOver).arg(of));
        if (fit.unchecked > 0)
            said.append(QStringLiteral("%1 request(s) not checked against %2 (not a frame of the target's framing)")
                            .arg(fit.unchecked)
                            .arg(of));
        if (said.isEmpty())
            said.append(QStringLiteral("every request within %1").arg(of));
        out.pace.append(said);
    }
    for (const PlannedRequest &r : out.plan.requests)
        out.settings.poll.items.append(r.item);
    return true;
}

} // namespace mbscope::app
