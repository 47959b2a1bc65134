#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtGui/QColor>

#include <vector>

class QCustomPlot;

namespace mbscope {

// Latency histograms drawn on a QCustomPlot: bars for one series of equal bins, a filled outline
// for one series of logarithmic bins, step lines with a legend for several series on common bins,
// and labelled dashed vertical lines (the median, the 99th percentile). Shared by the window's
// analysis panels and the CLI's --histogram, so both draw the same picture.
class HistogramChart
{
public:
    // One histogram: bin edges in nanoseconds (one more than the counts).
    struct Series {
        QString name; // the legend's text; empty for a single series
        std::vector<double> edgesNs;
        std::vector<quint64> counts;
        bool logarithmic = false; // bins growing by a constant factor: drawn on a logarithmic axis
    };
    // A vertical line across the plot.
    struct Marker {
        QString label;
        double valueNs = 0;
        QColor colour; // the line's and the label's; by default a grey line and a black label
    };
    // The colour series k is drawn in (markers of a series use it too).
    [[nodiscard]] static QColor seriesColour(qsizetype k);
    // The unit the latency axis is shown in, chosen from the largest edge.
    struct Unit {
        double ns;
        QString name;
    };
    [[nodiscard]] static Unit unitFor(double maxNs);

    // Removes what a previous draw() put on plot (plottables, items, legend) and draws series and
    // markers, the axes fitted to them. Does not replot. Returns false when no series had a bin
    // (then the plot says there is no latency to show).
    static bool draw(QCustomPlot &plot, const QList<Series> &series, const QList<Marker> &markers);
};

} // namespace mbscope
