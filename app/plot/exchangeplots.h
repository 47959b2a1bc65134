#pragma once

#include "plot/timeseriesplot.h"

#include "capture/captureexchange.h"
#include "exchange/statistics.h"

#include <QtCore/QString>

namespace mbscope::app {

// The plots analyze and export draw from a capture's exchanges: the latency histogram (from
// the analysis' Statistics, as poll draws it) and the latency over time (kept only when asked).
class ExchangePlots
{
public:
    explicit ExchangePlots(bool keepTimeSeries) : m_keep(keepTimeSeries) {}

    void add(const CaptureExchange &exchange);

    // "Latency, capture.pcapng: 1000 answer(s)", median and p99 marked; slow outliers beyond
    // twice the p99 counted in a note rather than squeezing the bins.
    [[nodiscard]] static bool writeHistogram(const QString &path, const QString &source, const Statistics &statistics, QString *error);
    [[nodiscard]] bool writeTimeSeries(const QString &path, const QString &source, QString *error) const;

private:
    bool m_keep;
    qint64 m_startNs = 0;
    LatencyTimeSeries m_series;
};

} // namespace mbscope::app
