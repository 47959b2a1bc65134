#include "poll/pollresults.h"

#include "common/cli.h"
#include "time/duration.h"
#include "plot/histogramplot.h"
#include "common/transactionreport.h"

#include "exchange/histogram.h"
#include "protocol/functioncode.h"

#include <QtCore/QJsonArray>

#include <algorithm>
#include <cmath>
#include <span>

namespace mbscope::app {

namespace {

QString padded(const QString &label)
{
    return label.leftJustified(14);
}

QString milliseconds(double ns)
{
    return QString::number(ns / 1e6, 'f', 3);
}

// The histogram to show people: a few slow answers (a 4 ms hiccup among 80 us answers) would
// squeeze every other answer into one bin, so the bins cover the answers up to twice the 99th
// percentile and the rest is counted apart ("2 above 0.315 ms, max 3.902 ms"). JSON keeps the
// full histogram.
struct ShownHistogram {
    Histogram histogram;
    quint64 above = 0;
    qint64 limitNs = 0;
    qint64 maxNs = 0;
};

ShownHistogram shownHistogram(std::span<const qint64> sorted)
{
    ShownHistogram shown;
    if (sorted.empty())
        return shown;
    const std::size_t n = sorted.size();
    const qint64 p99 = sorted[std::size_t(std::ceil(0.99 * double(n))) - 1];
    shown.maxNs = sorted.back();
    shown.limitNs = shown.maxNs > 2 * p99 ? 2 * p99 : shown.maxNs;
    const auto end = std::upper_bound(sorted.begin(), sorted.end(), shown.limitNs);
    shown.above = quint64(sorted.end() - end);
    const std::span<const qint64> kept = sorted.first(std::size_t(end - sorted.begin()));
    const qint64 median = kept[(kept.size() - 1) / 2];
    if (kept.back() > 10 * std::max<qint64>(median, 1)) {
        // A long tail (a loaded machine, a busy bus): equal bins would put most answers in the
        // first one; ten bins per decade show both the bulk and the tail.
        const qint64 low = std::max<qint64>(100, qint64(std::pow(10.0, std::floor(std::log10(double(std::max<qint64>(kept.front(), 1)))))));
        shown.histogram = Histogram::logarithmic(10, low, kept.back() + 1);
        for (const qint64 ns : kept)
            shown.histogram.add(ns);
    } else {
        shown.histogram = Histogram::autoFixed(kept);
    }
    return shown;
}

QString aboveText(const ShownHistogram &shown)
{
    if (shown.above == 0)
        return {};
    return QStringLiteral("not shown: %1 answer(s) above %2 (the slowest %3)")
        .arg(shown.above)
        .arg(latencyText(shown.limitNs), latencyText(shown.maxNs));
}

QJsonObject countersJson(const EngineCounters &c)
{
    return QJsonObject{
        {QStringLiteral("requests_sent"), double(c.requestsSent)},
        {QStringLiteral("retries"), double(c.retries)},
        {QStringLiteral("late"), double(c.late)},
        {QStringLiteral("unsolicited_frames"), double(c.unsolicitedFrames)},
        {QStringLiteral("duplicate_frames"), double(c.duplicateFrames)},
        {QStringLiteral("skipped_runs"), double(c.skippedRuns)},
        {QStringLiteral("skipped_bytes"), double(c.skippedBytes)},
        {QStringLiteral("bytes_in"), double(c.bytesIn)},
        {QStringLiteral("bytes_out"), double(c.bytesOut)},
        {QStringLiteral("connects"), double(c.connects)},
        {QStringLiteral("link_errors"), double(c.linkErrors)},
        {QStringLiteral("abandoned"), double(c.abandoned)},
    };
}

// The histogram as text bars, in the unit the latencies read best in.
QString histogramText(const ShownHistogram &shown)
{
    const Histogram &h = shown.histogram;
    if (!h.isValid() || h.total() == 0)
        return {};
    const std::vector<double> &edges = h.edgesNs();
    const bool micro = edges.back() < 2e6;
    const double unit = micro ? 1e3 : 1e6;
    const int decimals = micro ? 1 : 3;
    quint64 highest = 1;
    for (const quint64 c : h.counts())
        highest = std::max(highest, c);
    QStringList ranges;
    int width = 0;
    for (int i = 0; i < h.binCount(); ++i) {
        ranges.append(QStringLiteral("%1-%2")
                          .arg(QString::number(edges[std::size_t(i)] / unit, 'f', decimals),
                               QString::number(edges[std::size_t(i) + 1] / unit, 'f', decimals)));
        width = std::max(width, int(ranges.constLast().size()));
    }
    QString out = padded(QStringLiteral("histogram")) + QStringLiteral("latency %1, count\n").arg(micro ? QStringLiteral("µs") : QStringLiteral("ms"));
    for (int i = 0; i < h.binCount(); ++i) {
        const quint64 c = h.count(i);
        const int bar = int((c * 40 + highest - 1) / highest);
        out += padded(QString()) + ranges.at(i).rightJustified(width) + QStringLiteral("  ")
               + QString::number(c).rightJustified(7) + QStringLiteral("  ") + QString(bar, QLatin1Char('#'));
        while (out.endsWith(QLatin1Char(' ')))
            out.chop(1);
        out += QLatin1Char('\n');
    }
    if (shown.above > 0)
        out += padded(QString()) + aboveText(shown) + QLatin1Char('\n');
    return out;
}

} // namespace

QString PollResults::heading(const char *what) const
{
    QString text = QStringLiteral("%1 %2  ").arg(QLatin1String(what), m_config.target.url.toString());
    const RequestPlan &plan = m_config.plan;
    if (plan.built && plan.requests.size() == 1) {
        text += plan.requests.constFirst().description;
    } else if (plan.built) {
        text += QStringLiteral("%1, %2 (%3 requests per cycle)")
                    .arg(QString::fromLatin1(functionName(plan.requests.constFirst().functionCode)), plan.summary)
                    .arg(plan.requests.size());
    } else if (plan.requests.size() == 1) {
        text += plan.requests.constFirst().item.name;
    } else {
        text += QStringLiteral("%1 requests per cycle").arg(plan.requests.size());
    }
    return text + QLatin1Char('\n');
}

QString PollResults::detail(const PollRun &run) const
{
    QString out;
    const EngineCounters &c = run.counters;
    out += padded(QStringLiteral("engine")) + QStringLiteral("%1 requests sent (%2 retries), %3 bytes out, %4 bytes in, %5 connection(s)\n")
                                                   .arg(c.requestsSent).arg(c.retries).arg(c.bytesOut).arg(c.bytesIn).arg(c.connects);
    out += padded(QString()) + QStringLiteral("unsolicited frames %1 (%2 second answers), skipped %3 bytes in %4 runs, "
                                              "link errors %5, abandoned %6\n")
                                   .arg(c.unsolicitedFrames).arg(c.duplicateFrames).arg(c.skippedBytes).arg(c.skippedRuns)
                                   .arg(c.linkErrors).arg(c.abandoned);
    out += histogramText(shownHistogram(run.statistics.overall().latency().sorted()));
    return out;
}

QString PollResults::pollText() const
{
    QString out = heading("POLL");
    if (m_outcome.report.runs.isEmpty())
        return out + QStringLiteral("nothing was sent\n");
    const PollRun &run = m_outcome.report.runs.constFirst();
    QString cycles = QStringLiteral("%1 in %2 s, %3 overrun(s)")
                         .arg(run.intervalNs == 0 ? QStringLiteral("back to back")
                                                  : QStringLiteral("every ") + formatDuration(run.intervalNs))
                         .arg(QString::number(double(run.elapsedNs) / 1e9, 'f', 3))
                         .arg(run.overruns);
    if (m_outcome.interrupted)
        cycles += QStringLiteral(", stopped by Ctrl-C");
    else if (run.stopped)
        cycles += QStringLiteral(", stopped");
    out += padded(QStringLiteral("cycles")) + QString::number(run.cycles).rightJustified(8) + QStringLiteral("  ") + cycles
           + QLatin1Char('\n');
    if (m_config.engine.pipelineDepth > 1)
        out += padded(QStringLiteral("pipeline")) + QString::number(m_config.engine.pipelineDepth).rightJustified(8)
               + QStringLiteral("  requests in flight at most\n");
    if (const QString pace = paceText(); !pace.isEmpty())
        out += padded(QStringLiteral("pace")) + QStringLiteral("          ") + pace + QLatin1Char('\n');
    out += run.statistics.itemCount() > 1 ? run.statistics.summary() : run.statistics.overall().summary();
    if (m_config.stats)
        out += detail(run);
    return out;
}

QJsonObject PollResults::runJson(const PollRun &run) const
{
    QJsonObject o = run.statistics.itemCount() > 1 ? run.statistics.toJson() : run.statistics.overall().toJson();
    o.insert(QStringLiteral("interval_ms"), double(run.intervalNs) / 1e6);
    o.insert(QStringLiteral("cycles"), double(run.cycles));
    o.insert(QStringLiteral("overruns"), double(run.overruns));
    o.insert(QStringLiteral("elapsed_ms"), double(run.elapsedNs) / 1e6);
    o.insert(QStringLiteral("stopped"), run.stopped);
    o.insert(QStringLiteral("error_rate"), run.statistics.overall().errorRate());
    o.insert(QStringLiteral("engine"), countersJson(run.counters));
    return o;
}

QJsonObject PollResults::pollJson() const
{
    QJsonObject o = m_outcome.report.runs.isEmpty() ? StatisticsSet().overall().toJson()
                                                    : runJson(m_outcome.report.runs.constFirst());
    QJsonArray requests;
    for (const PlannedRequest &r : m_config.plan.requests)
        requests.append(r.item.name);
    o.insert(QStringLiteral("target"), m_config.target.url.toString());
    o.insert(QStringLiteral("requests"), requests);
    o.insert(QStringLiteral("interrupted"), m_outcome.interrupted);
    o.insert(QStringLiteral("pipeline"), m_config.engine.pipelineDepth);
    o.insert(QStringLiteral("pace"), paceJson());
    return o;
}

QString PollResults::paceText() const
{
    return m_config.pace.join(QStringLiteral(", "));
}

QJsonObject PollResults::paceJson() const
{
    return QJsonObject{
        {QStringLiteral("gap_ms"), double(m_config.engine.requestGap.count()) / 1e6},
        {QStringLiteral("warm_up_ms"), double(m_config.engine.warmUp.count()) / 1e6},
        {QStringLiteral("new_connection_each"), m_config.engine.closeAfterAnswer},
        {QStringLiteral("profile"), m_config.profile.isEmpty() ? QJsonValue() : QJsonValue(m_config.profile)},
    };
}

QString PollResults::sweepText() const
{
    QString out = heading("SWEEP");
    const SweepSettings &s = m_config.settings;
    QStringList per;
    if (s.poll.count > 0)
        per.append(QStringLiteral("%1 cycles").arg(s.poll.count));
    if (s.poll.durationNs > 0)
        per.append(QStringLiteral("at most %1").arg(formatDuration(s.poll.durationNs)));
    out += per.join(QStringLiteral(", ")) + QStringLiteral(" per interval") + QLatin1Char('\n');
    if (const QString pace = paceText(); !pace.isEmpty())
        out += QStringLiteral("pace: ") + pace + QLatin1Char('\n');
    out += QLatin1Char('\n');

    QList<QStringList> rows;
    rows.append({QStringLiteral("INTERVAL"), QStringLiteral("CYCLES"), QStringLiteral("OVERRUNS"), QStringLiteral("COUNT"), QStringLiteral("OK"),
                 QStringLiteral("FAILED"), QStringLiteral("ERROR RATE"), QStringLiteral("MIN ms"), QStringLiteral("MEAN ms"),
                 QStringLiteral("P50 ms"), QStringLiteral("P99 ms"), QStringLiteral("MAX ms")});
    for (const PollRun &run : m_outcome.report.runs) {
        const Statistics &st = run.statistics.overall();
        const LatencySamples &l = st.latency();
        const bool any = !l.isEmpty();
        const auto figure = [any](double ns) { return any ? milliseconds(ns) : QStringLiteral("-"); };
        QString interval = formatDuration(run.intervalNs);
        if (run.stopped)
            interval += QLatin1Char('*');
        rows.append({interval, QString::number(run.cycles), QString::number(run.overruns), QString::number(st.count()), QString::number(st.ok()),
                     QString::number(st.failed()), QString::number(100.0 * st.errorRate(), 'f', 2) + QStringLiteral(" %"),
                     figure(double(l.minNs())), figure(l.meanNs()), figure(double(l.medianNs())),
                     figure(double(l.percentileNs(99))), figure(double(l.maxNs()))});
    }
    QList<int> widths(rows.constFirst().size(), 0);
    for (const QStringList &row : rows) {
        for (qsizetype c = 0; c < row.size(); ++c)
            widths[c] = std::max(widths.at(c), int(row.at(c).size()));
    }
    for (const QStringList &row : rows) {
        QString line = row.at(0).leftJustified(widths.at(0));
        for (qsizetype c = 1; c < row.size(); ++c)
            line += QStringLiteral("  ") + row.at(c).rightJustified(widths.at(c));
        out += line + QLatin1Char('\n');
    }
    const qsizetype planned = s.intervalsNs.size();
    if (m_outcome.report.stopped || m_outcome.report.runs.size() < planned) {
        out += QStringLiteral("\n* stopped%1 before its end; %2 of %3 intervals run\n")
                   .arg(m_outcome.interrupted ? QStringLiteral(" by Ctrl-C") : QString())
                   .arg(m_outcome.report.runs.size())
                   .arg(planned);
    }
    if (m_config.stats) {
        for (const PollRun &run : m_outcome.report.runs) {
            out += QStringLiteral("\nINTERVAL %1: %2 cycles in %3 s, %4 overrun(s)\n")
                       .arg(formatDuration(run.intervalNs))
                       .arg(run.cycles)
                       .arg(QString::number(double(run.elapsedNs) / 1e9, 'f', 3))
                       .arg(run.overruns);
            out += run.statistics.itemCount() > 1 ? run.statistics.summary() : run.statistics.overall().summary();
            out += detail(run);
        }
    }
    return out;
}

QJsonObject PollResults::sweepJson() const
{
    QJsonArray runs;
    for (const PollRun &run : m_outcome.report.runs)
        runs.append(runJson(run));
    QJsonArray requests;
    for (const PlannedRequest &r : m_config.plan.requests)
        requests.append(r.item.name);
    QJsonArray intervals;
    for (const qint64 ns : m_config.settings.intervalsNs)
        intervals.append(double(ns) / 1e6);
    const PollSettings &p = m_config.settings.poll;
    return QJsonObject{
        {QStringLiteral("target"), m_config.target.url.toString()},
        {QStringLiteral("requests"), requests},
        {QStringLiteral("intervals_ms"), intervals},
        {QStringLiteral("count"), p.count > 0 ? QJsonValue(double(p.count)) : QJsonValue()},
        {QStringLiteral("duration_ms"), p.durationNs > 0 ? QJsonValue(double(p.durationNs) / 1e6) : QJsonValue()},
        {QStringLiteral("pipeline"), m_config.engine.pipelineDepth},
        {QStringLiteral("pace"), paceJson()},
        {QStringLiteral("stopped"), m_outcome.report.stopped},
        {QStringLiteral("interrupted"), m_outcome.interrupted},
        {QStringLiteral("runs"), runs},
    };
}

bool PollResults::writeHistogram(QString *error) const
{
    QList<HistogramSeries> series;
    QList<HistogramMarker> markers;
    const QList<PollRun> &runs = m_outcome.report.runs;
    // One set of bins for every interval of a sweep, so that their shapes compare.
    std::vector<qint64> all;
    for (const PollRun &run : runs) {
        const auto sorted = run.statistics.overall().latency().sorted();
        all.insert(all.end(), sorted.begin(), sorted.end());
    }
    std::sort(all.begin(), all.end());
    const ShownHistogram shown = shownHistogram(all);
    if (runs.size() == 1) {
        const LatencySamples &l = runs.constFirst().statistics.overall().latency();
        if (shown.histogram.isValid())
            series.append(HistogramSeries{QString(), shown.histogram.edgesNs(), shown.histogram.counts(),
                                          shown.histogram.isLogarithmic()});
        if (!l.isEmpty()) {
            markers.append({QStringLiteral("median %1").arg(latencyText(l.medianNs())), double(l.medianNs())});
            markers.append({QStringLiteral("p99 %1").arg(latencyText(l.percentileNs(99))), double(l.percentileNs(99))});
        }
    } else if (shown.histogram.isValid()) {
        for (const PollRun &run : runs) {
            Histogram h = shown.histogram;
            h.clear();
            for (const qint64 ns : run.statistics.overall().latency().sorted()) {
                if (ns <= shown.limitNs)
                    h.add(ns);
            }
            series.append(HistogramSeries{QStringLiteral("every %1 (%2)").arg(formatDuration(run.intervalNs)).arg(h.total()),
                                          h.edgesNs(), h.counts(), h.isLogarithmic()});
        }
    }
    QString title = QStringLiteral("Latency, %1: %2 answer(s)").arg(m_config.target.url.toString()).arg(all.size());
    if (runs.size() == 1)
        title += runs.constFirst().intervalNs == 0 ? QStringLiteral(", back to back")
                                                   : QStringLiteral(", every ") + formatDuration(runs.constFirst().intervalNs);
    return HistogramPlot::write(m_config.histogramPath, title, aboveText(shown), series, markers, error);
}

int PollResults::exitStatus() const
{
    if (m_outcome.linkFailed)
        return ExitLinkError;
    for (const PollRun &run : m_outcome.report.runs) {
        if (run.statistics.overall().failed() > 0)
            return ExitFailure;
    }
    return ExitOk;
}

} // namespace mbscope::app
