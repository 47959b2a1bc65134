#include "histogramplot.h"

#include "plotfile.h"

#include <QtCore/QByteArray>
#include <QtCore/QCoreApplication>

#include <cstring>

#ifdef MBSCOPE_HAVE_UI
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
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
}

#ifdef MBSCOPE_HAVE_UI

namespace {

struct AxisUnit {
    double ns;
    const char *name;
};

// Microseconds for a loopback's sub-millisecond latencies, milliseconds for devices.
AxisUnit unitFor(double maxNs)
{
    if (maxNs < 2e6)
        return {1e3, "µs"};
    if (maxNs < 20e9)
        return {1e6, "ms"};
    return {1e9, "s"};
}

const QColor kColours[] = {QColor(31, 119, 180), QColor(255, 127, 14), QColor(44, 160, 44), QColor(214, 39, 40),
                           QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194), QColor(127, 127, 127),
                           QColor(188, 189, 34), QColor(23, 190, 207)};

} // namespace

bool HistogramPlot::write(const QString &path, const QString &title, const QString &note,
                          const QList<HistogramSeries> &series, const QList<HistogramMarker> &markers, QString *error)
{
    if (!qobject_cast<QApplication *>(QCoreApplication::instance())) {
        *error = QStringLiteral("no QApplication: the plot needs one (mbscope starts it when --histogram is given)");
        return false;
    }
    bool logarithmic = false;
    for (const HistogramSeries &s : series)
        logarithmic = logarithmic || s.logarithmic;
    double lowNs = 0;
    double highNs = 0;
    quint64 highest = 0;
    bool first = true;
    for (const HistogramSeries &s : series) {
        if (s.edgesNs.size() < 2)
            continue;
        lowNs = first ? s.edgesNs.front() : qMin(lowNs, s.edgesNs.front());
        highNs = first ? s.edgesNs.back() : qMax(highNs, s.edgesNs.back());
        first = false;
        for (const quint64 c : s.counts)
            highest = qMax(highest, c);
    }

    QCustomPlot plot;
    plot.resize(900, 500);
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, title, QFont(QStringLiteral("Sans"), 11, QFont::Bold)));
    if (!note.isEmpty()) {
        plot.plotLayout()->insertRow(1);
        plot.plotLayout()->addElement(1, 0, new QCPTextElement(&plot, note, QFont(QStringLiteral("Sans"), 9)));
    }
    const AxisUnit unit = unitFor(highNs);
    plot.xAxis->setLabel(QStringLiteral("latency (%1)").arg(QString::fromUtf8(unit.name)));
    plot.yAxis->setLabel(QStringLiteral("transactions"));

    if (first) {
        auto *empty = new QCPItemText(&plot);
        empty->position->setType(QCPItemPosition::ptAxisRectRatio);
        empty->position->setCoords(0.5, 0.5);
        empty->setText(QStringLiteral("no answered transactions: no latency to show"));
        plot.xAxis->setRange(0, 1);
        plot.yAxis->setRange(0, 1);
    } else if (series.size() == 1 && logarithmic) {
        // Bins of unequal width: a filled outline rather than bars of one width.
        const HistogramSeries &s = series.constFirst();
        auto *graph = plot.addGraph();
        graph->setLineStyle(QCPGraph::lsStepLeft);
        graph->setPen(QPen(kColours[0].darker(130)));
        graph->setBrush(kColours[0]);
        for (std::size_t i = 0; i < s.counts.size(); ++i)
            graph->addData(s.edgesNs[i] / unit.ns, double(s.counts[i]));
        graph->addData(s.edgesNs.back() / unit.ns, 0);
    } else if (series.size() == 1) {
        const HistogramSeries &s = series.constFirst();
        auto *bars = new QCPBars(plot.xAxis, plot.yAxis);
        bars->setWidthType(QCPBars::wtPlotCoords);
        bars->setWidth((s.edgesNs[1] - s.edgesNs[0]) / unit.ns);
        bars->setPen(QPen(kColours[0].darker(130)));
        bars->setBrush(kColours[0]);
        for (std::size_t i = 0; i < s.counts.size(); ++i)
            bars->addData((s.edgesNs[i] + s.edgesNs[i + 1]) / 2 / unit.ns, double(s.counts[i]));
    } else {
        plot.legend->setVisible(true);
        plot.legend->setFont(QFont(QStringLiteral("Sans"), 9));
        for (qsizetype k = 0; k < series.size(); ++k) {
            const HistogramSeries &s = series.at(k);
            if (s.edgesNs.size() < 2)
                continue;
            // Steps drawn from each bin's left edge, closed at the last edge: the outline of bars.
            auto *graph = plot.addGraph();
            graph->setName(s.name);
            graph->setLineStyle(QCPGraph::lsStepLeft);
            graph->setPen(QPen(kColours[k % std::size(kColours)], 2));
            for (std::size_t i = 0; i < s.counts.size(); ++i)
                graph->addData(s.edgesNs[i] / unit.ns, double(s.counts[i]));
            graph->addData(s.edgesNs.back() / unit.ns, double(s.counts.empty() ? 0 : s.counts.back()));
            graph->addData(s.edgesNs.back() / unit.ns, 0);
        }
    }
    if (!first && logarithmic) {
        plot.xAxis->setScaleType(QCPAxis::stLogarithmic);
        plot.xAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
        plot.xAxis->setNumberFormat(QStringLiteral("g"));
        plot.xAxis->setRange(lowNs / unit.ns / 1.1, highNs / unit.ns * 1.1);
        plot.xAxis->setLabel(plot.xAxis->label() + QStringLiteral(", logarithmic"));
    } else if (!first) {
        const double margin = (highNs - lowNs) * 0.02;
        plot.xAxis->setRange((lowNs - margin) / unit.ns, (highNs + margin) / unit.ns);
    }
    if (!first) {
        // Head room above the highest bar for the markers' labels.
        plot.yAxis->setRange(0, double(highest) * 1.25 + 1);
        for (qsizetype k = 0; k < markers.size(); ++k) {
            const double x = markers.at(k).valueNs / unit.ns;
            auto *line = new QCPItemStraightLine(&plot);
            line->point1->setCoords(x, 0);
            line->point2->setCoords(x, 1);
            line->setPen(QPen(QColor(90, 90, 90), 1, Qt::DashLine));
            auto *label = new QCPItemText(&plot);
            label->position->setCoords(x, double(highest) * (1.19 - 0.07 * double(k)) + 1);
            label->setPositionAlignment(Qt::AlignLeft | Qt::AlignVCenter);
            label->setPadding(QMargins(4, 0, 0, 0));
            label->setText(markers.at(k).label);
            label->setFont(QFont(QStringLiteral("Sans"), 9));
        }
    }
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
