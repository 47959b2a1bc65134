#pragma once

#include <QtCore/QString>

class QCPGraph;
class QCustomPlot;

namespace mbscope {

// The graphs of a latency-over-time plot, drawn alike by the window's LatencyTimePanel and by
// `mbscope analyze/export --timeseries`: answered transactions as blue dots, exceptions as orange
// ones (the device answered, so they have a latency), and requests that got no usable answer
// (timeouts, CRC errors, malformed, unexpected, link errors) as red crosses on the time axis.
struct LatencyTimeGraphs {
    QCPGraph *answered = nullptr;
    QCPGraph *exceptions = nullptr;
    QCPGraph *failed = nullptr;

    // Adds the three graphs to plot (points, no lines), in that order.
    [[nodiscard]] static LatencyTimeGraphs addTo(QCustomPlot *plot);
    // Legend names with the number of points: "answered (120)", "exceptions (3)",
    // "no usable answer (2), drawn at 0".
    void nameWithCounts(qsizetype answeredCount, qsizetype exceptionCount, qsizetype failedCount) const;
};

} // namespace mbscope
