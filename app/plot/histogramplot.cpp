#include "plot/histogramplot.h"

#include "common/platformnoise.h"
#include "plot/plotfile.h"

#include <QtCore/QByteArray>
#include <QtCore/QCoreApplication>

#include <cstring>

#ifdef MBSCOPE_HAVE_UI
#include "common/histogramchart.h"

#include <QtWidgets/QApplication>
#include <qcustomplot.h>
#endif

namespace mbscope::app {

bool HistogramPlot::isAvailable()
{
#ifdef MBSCOPE_HAVE_UI
    return true;
#else
    return false;
#endif
}

QString HistogramPlot::unavailableReason()
{
    return QStringLiteral("this mbscope was built without the GUI (MBSCOPE_BUILD_UI=OFF), and the plots are drawn "
                          "with its QCustomPlot: leave out --histogram (--json gives the histogram's bins and counts)");
}

bool HistogramPlot::isRequested(int argc, char *argv[])
{
    if (argc >= 2 && std::strcmp(argv[1], "conform") == 0) { // --pdf: a QTextDocument laid out with the GUI's fonts
        for (int i = 2; i < argc && std::strcmp(argv[i], "--") != 0; ++i) {
            if (std::strcmp(argv[i], "--pdf") == 0 || std::strncmp(argv[i], "--pdf=", 6) == 0)
                return true;
        }
        return false;
    }
    const bool plots = argc >= 2
                       && (std::strcmp(argv[1], "poll") == 0 || std::strcmp(argv[1], "sweep") == 0
                           || std::strcmp(argv[1], "analyze") == 0 || std::strcmp(argv[1], "export") == 0);
    if (!plots)
        return false;
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--") == 0)
            return false;
        if (std::strcmp(argv[i], "--histogram") == 0 || std::strncmp(argv[i], "--histogram=", 12) == 0
            || std::strcmp(argv[i], "--timeseries") == 0 || std::strncmp(argv[i], "--timeseries=", 13) == 0)
            return true;
    }
    return false;
}

void HistogramPlot::prepareOffscreenPlatform()
{
    PlatformNoise::suppress();
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
}

#ifdef MBSCOPE_HAVE_UI

// The drawing is the window's (HistogramChart): the CLI adds the title and the note above it.
bool HistogramPlot::write(const QString &path, const QString &title, const QString &note,
                          const QList<HistogramSeries> &series, const QList<HistogramMarker> &markers, QString *error)
{
    if (!qobject_cast<QApplication *>(QCoreApplication::instance())) {
        *error = QStringLiteral("no QApplication: the plot needs one (mbscope starts it when --histogram is given)");
        return false;
    }
    QList<HistogramChart::Series> chartSeries;
    chartSeries.reserve(series.size());
    for (const HistogramSeries &s : series)
        chartSeries.append({s.name, s.edgesNs, s.counts, s.logarithmic});
    QList<HistogramChart::Marker> chartMarkers;
    chartMarkers.reserve(markers.size());
    for (const HistogramMarker &m : markers)
        chartMarkers.append({m.label, m.valueNs, QColor()});

    QCustomPlot plot;
    plot.resize(900, 500);
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, title, QFont(QStringLiteral("Sans"), 11, QFont::Bold)));
    if (!note.isEmpty()) {
        plot.plotLayout()->insertRow(1);
        plot.plotLayout()->addElement(1, 0, new QCPTextElement(&plot, note, QFont(QStringLiteral("Sans"), 9)));
    }
    HistogramChart::draw(plot, chartSeries, chartMarkers);
    return PlotFile::save(plot, path, 900, 500, error);
}

#else

bool HistogramPlot::write(const QString &, const QString &, const QString &, const QList<HistogramSeries> &,
                          const QList<HistogramMarker> &, QString *error)
{
    *error = unavailableReason();
    return false;
}

#endif

} // namespace mbscope::app
