#include "plot/exchangeplots.h"

#include "plot/histogramplot.h"
#include "common/transactionreport.h"

#include "exchange/histogram.h"

#include <QtCore/QFileInfo>

#include <algorithm>
#include <cmath>
#include <span>

namespace mbscope::app {

void ExchangePlots::add(const CaptureExchange &exchange)
{
    if (!m_keep || exchange.kind != CaptureExchange::Kind::Transaction)
        return;
    const Transaction &t = exchange.transaction;
    if (t.status == TransactionStatus::Late || t.status == TransactionStatus::Broadcast || t.sentNs == 0)
        return;
    if (m_startNs == 0)
        m_startNs = t.sentNs;
    const double seconds = double(t.sentNs - m_startNs) / 1e9;
    if (t.status == TransactionStatus::Ok) {
        m_series.okSeconds.push_back(seconds);
        m_series.okLatencyNs.push_back(double(t.latencyNs()));
    } else if (t.status == TransactionStatus::Exception) {
        m_series.exceptionSeconds.push_back(seconds);
        m_series.exceptionLatencyNs.push_back(double(t.latencyNs()));
    } else {
        m_series.failedSeconds.push_back(seconds);
    }
}

bool ExchangePlots::writeHistogram(const QString &path, const QString &source, const Statistics &statistics, QString *error)
{
    const std::span<const qint64> sorted = statistics.latency().sorted();
    QList<HistogramSeries> series;
    QList<HistogramMarker> markers;
    QString note;
    if (!sorted.empty()) {
        const std::size_t n = sorted.size();
        const qint64 p99 = sorted[std::size_t(std::ceil(0.99 * double(n))) - 1];
        const qint64 limit = sorted.back() > 2 * p99 ? 2 * p99 : sorted.back();
        const auto end = std::upper_bound(sorted.begin(), sorted.end(), limit);
        const std::span<const qint64> kept = sorted.first(std::size_t(end - sorted.begin()));
        const qint64 median = kept[(kept.size() - 1) / 2];
        Histogram h;
        if (kept.back() > 10 * std::max<qint64>(median, 1)) {
            // A long tail: equal bins would put nearly every answer in the first one; ten bins
            // per decade show the bulk and the tail (as poll's histogram does).
            const qint64 low = std::max<qint64>(100, qint64(std::pow(10.0, std::floor(std::log10(double(std::max<qint64>(kept.front(), 1)))))));
            h = Histogram::logarithmic(10, low, kept.back() + 1);
            for (const qint64 ns : kept)
                h.add(ns);
        } else {
            h = Histogram::autoFixed(kept);
        }
        series.append(HistogramSeries{QString(), h.edgesNs(), h.counts(), h.isLogarithmic()});
        markers.append(HistogramMarker{QStringLiteral("median %1").arg(latencyText(statistics.latency().medianNs())),
                                       double(statistics.latency().medianNs())});
        markers.append(HistogramMarker{QStringLiteral("p99 %1").arg(latencyText(p99)), double(p99)});
        const auto above = std::size_t(sorted.end() - end);
        if (above > 0)
            note = QStringLiteral("not shown: %1 answer(s) above %2 (the slowest %3)")
                       .arg(above)
                       .arg(latencyText(limit), latencyText(sorted.back()));
    }
    const QString title = QStringLiteral("Latency, %1: %2 answer(s)").arg(QFileInfo(source).fileName()).arg(sorted.size());
    return HistogramPlot::write(path, title, note, series, markers, error);
}

bool ExchangePlots::writeTimeSeries(const QString &path, const QString &source, QString *error) const
{
    const QString title = QStringLiteral("Latency over time, %1").arg(QFileInfo(source).fileName());
    return TimeSeriesPlot::write(path, title, m_series, error);
}

} // namespace mbscope::app
