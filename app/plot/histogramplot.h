#pragma once

#include <QtCore/QList>
#include <QtCore/QString>

#include <vector>

namespace mbscope::app {

// One latency histogram to draw: bin edges in nanoseconds (one more than the counts).
struct HistogramSeries {
    QString name; // the legend's text ("100 ms"); empty for a single series
    std::vector<double> edgesNs;
    std::vector<quint64> counts;
    bool logarithmic = false; // bins growing by a constant factor: drawn on a logarithmic axis
};

// A vertical line across the plot (the median, the 99th percentile).
struct HistogramMarker {
    QString label;
    double valueNs = 0;
};

// Latency histograms drawn with QCustomPlot into a PNG, for poll and sweep --histogram: bars for
// one series, step lines with a legend for several (a sweep's intervals on common bins). Needs a
// QApplication (QCustomPlot is a widget); with no display the offscreen platform renders it.
// In a build without the GUI (MBSCOPE_BUILD_UI=OFF) there is no QCustomPlot: isAvailable() is
// false and write() explains.
class HistogramPlot
{
public:
    [[nodiscard]] static bool isAvailable();
    // Why isAvailable() is false, for the error message.
    [[nodiscard]] static QString unavailableReason();

    // Whether a command line asks for a plot, so main() makes a QApplication instead of a
    // QCoreApplication: poll, sweep, analyze or export with --histogram (or --timeseries), and
    // conform with --pdf (the report's layout needs the GUI's fonts).
    [[nodiscard]] static bool isRequested(int argc, char *argv[]);
    // Renders without a display: QT_QPA_PLATFORM=offscreen unless the user chose a platform. A
    // PNG needs no window, and the offscreen platform gives the same picture with or without X.
    static void prepareOffscreenPlatform();

    // Draws and saves the plot (900 x 500; PNG, SVG or PDF by the file name: PlotFile), a note
    // in the top right corner ("2 above 0.315 ms").
    // Returns false with the reason in error.
    [[nodiscard]] static bool write(const QString &path, const QString &title, const QString &note,
                                    const QList<HistogramSeries> &series, const QList<HistogramMarker> &markers,
                                    QString *error);
};

} // namespace mbscope::app
