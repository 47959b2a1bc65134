#include "plot/timeseriesplot.h"

#include "plot/histogramplot.h"
#include "plot/plotfile.h"

#include <QtCore/QCoreApplication>

#ifdef MBSCOPE_HAVE_UI
#include "analysis/latencytimegraphs.h"

#include <QtWidgets/QApplication>
#include <qcustomplot.h>
#endif

#include <algorithm>

namespace mbscope::app {

#ifdef MBSCOPE_HAVE_UI

namespace {

QVector<double> toVector(const std::vector<double> &values, double scale)
{
    QVector<double> out;
    out.reserve(qsizetype(values.size()));
    for (const double v : values)
        out.append(v / scale);
    return out;
}

} // namespace

bool TimeSeriesPlot::write(const QString &path, const QString &title, const LatencyTimeSeries &series, QString *error)
{
    if (!qobject_cast<QApplication *>(QCoreApplication::instance())) {
        *error = QStringLiteral("no QApplication: the plot needs one (mbscope starts it when --timeseries is given)");
        return false;
    }
    const QString problem = PlotFile::formatProblem(path);
    if (!problem.isEmpty()) {
        *error = problem;
        return false;
    }
    double maxNs = 0;
    for (const double v : series.okLatencyNs)
        maxNs = std::max(maxNs, v);
    for (const double v : series.exceptionLatencyNs)
        maxNs = std::max(maxNs, v);
    const bool micro = maxNs < 2e6;
    const double unit = micro ? 1e3 : 1e6;

    QCustomPlot plot;
    plot.resize(900, 500);
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, title, QFont(QStringLiteral("Sans"), 11, QFont::Bold)));
    plot.xAxis->setLabel(QStringLiteral("time since the first request (s)"));
    plot.yAxis->setLabel(QStringLiteral("latency (%1)").arg(micro ? QStringLiteral("µs") : QStringLiteral("ms")));
    plot.legend->setVisible(true);
    plot.legend->setFont(QFont(QStringLiteral("Sans"), 9));

    // The window's latency-over-time panel draws the same graphs; names stay English here (the
    // command line is never translated) and a graph with no points is left out of the legend.
    const LatencyTimeGraphs graphs = LatencyTimeGraphs::addTo(&plot);
    graphs.answered->setName(QStringLiteral("answered (%1)").arg(series.okSeconds.size()));
    graphs.answered->setData(toVector(series.okSeconds, 1), toVector(series.okLatencyNs, unit), true);
    graphs.exceptions->setName(QStringLiteral("exceptions (%1)").arg(series.exceptionSeconds.size()));
    graphs.exceptions->setData(toVector(series.exceptionSeconds, 1), toVector(series.exceptionLatencyNs, unit), true);
    graphs.failed->setName(QStringLiteral("no usable answer (%1), drawn at 0").arg(series.failedSeconds.size()));
    graphs.failed->setData(toVector(series.failedSeconds, 1), QVector<double>(qsizetype(series.failedSeconds.size()), 0.0), true);
    if (series.exceptionSeconds.empty())
        plot.removeGraph(graphs.exceptions);
    if (series.failedSeconds.empty())
        plot.removeGraph(graphs.failed);
    plot.rescaleAxes();
    plot.yAxis->setRangeLower(0);
    plot.yAxis->setRangeUpper(std::max(plot.yAxis->range().upper * 1.1, 1.0));
    if (series.okSeconds.empty() && series.exceptionSeconds.empty() && series.failedSeconds.empty()) {
        auto *empty = new QCPItemText(&plot);
        empty->position->setType(QCPItemPosition::ptAxisRectRatio);
        empty->position->setCoords(0.5, 0.5);
        empty->setText(QStringLiteral("no transactions to show"));
        plot.xAxis->setRange(0, 1);
    }
    return PlotFile::save(plot, path, 900, 500, error);
}

#else

bool TimeSeriesPlot::write(const QString &, const QString &, const LatencyTimeSeries &, QString *error)
{
    *error = HistogramPlot::unavailableReason();
    return false;
}

#endif

} // namespace mbscope::app
