#pragma once

#include <QtCore/QString>

#include <vector>

namespace mbscope::app {

// Latency over time: answered transactions as dots (exceptions in their own colour), requests
// that got no usable answer as marks along the time axis.
struct LatencyTimeSeries {
    std::vector<double> okSeconds;        // since the first request
    std::vector<double> okLatencyNs;
    std::vector<double> exceptionSeconds;
    std::vector<double> exceptionLatencyNs;
    std::vector<double> failedSeconds;    // timeouts, CRC errors, malformed, unexpected, link errors
};

// Drawn with QCustomPlot (900 x 500) into PNG, SVG or PDF (PlotFile). Needs a QApplication, as
// HistogramPlot does.
class TimeSeriesPlot
{
public:
    [[nodiscard]] static bool write(const QString &path, const QString &title, const LatencyTimeSeries &series, QString *error);
};

} // namespace mbscope::app
