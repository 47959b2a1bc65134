#include "histogramchart.h"

#include <algorithm>

#include <QtCore/QCoreApplication>
#include <qcustomplot.h>

#include <cmath>
#include <iterator>

namespace mbscope {

namespace {

const QColor kColours[] = {QColor(31, 119, 180), QColor(255, 127, 14), QColor(44, 160, 44), QColor(214, 39, 40),
                           QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194), QColor(127, 127, 127),
                           QColor(188, 189, 34), QColor(23, 190, 207)};

QString tr(const char *text)
{
    return QCoreApplication::translate("mbscope::HistogramChart", text);
}

} // namespace

QColor HistogramChart::seriesColour(qsizetype k)
{
    return kColours[std::size_t(k) % std::size(kColours)];
}

// Microseconds for a loopback's sub-millisecond latencies, milliseconds for devices.
HistogramChart::Unit HistogramChart::unitFor(double maxNs)
{
    if (maxNs < 2e6)
        return {1e3, QStringLiteral("µs")};
    if (maxNs < 20e9)
        return {1e6, QStringLiteral("ms")};
    return {1e9, QStringLiteral("s")};
}

bool HistogramChart::draw(QCustomPlot &plot, const QList<Series> &series, const QList<Marker> &markers)
{
    plot.clearPlottables();
    plot.clearItems();
    plot.legend->setVisible(false);
    plot.xAxis->setScaleType(QCPAxis::stLinear);
    plot.xAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
    plot.xAxis->setNumberFormat(QStringLiteral("gbd")); // QCustomPlot's default

    bool logarithmic = false;
    for (const Series &s : series)
        logarithmic = logarithmic || s.logarithmic;
    double lowNs = 0;
    double highNs = 0;
    quint64 highest = 0;
    bool first = true;
    for (const Series &s : series) {
        if (s.edgesNs.size() < 2)
            continue;
        lowNs = first ? s.edgesNs.front() : qMin(lowNs, s.edgesNs.front());
        highNs = first ? s.edgesNs.back() : qMax(highNs, s.edgesNs.back());
        first = false;
        for (const quint64 c : s.counts)
            highest = qMax(highest, c);
    }

    const Unit unit = unitFor(highNs);
    plot.xAxis->setLabel(tr("latency (%1)").arg(unit.name));
    plot.yAxis->setLabel(tr("transactions"));

    if (first) {
        auto *empty = new QCPItemText(&plot);
        empty->position->setType(QCPItemPosition::ptAxisRectRatio);
        empty->position->setCoords(0.5, 0.5);
        empty->setText(tr("no answered transactions: no latency to show"));
        plot.xAxis->setRange(0, 1);
        plot.yAxis->setRange(0, 1);
        return false;
    }
    if (series.size() == 1 && logarithmic) {
        // Bins of unequal width: a filled outline rather than bars of one width.
        const Series &s = series.constFirst();
        auto *graph = plot.addGraph();
        graph->setLineStyle(QCPGraph::lsStepLeft);
        graph->setPen(QPen(kColours[0].darker(130)));
        graph->setBrush(kColours[0]);
        for (std::size_t i = 0; i < s.counts.size(); ++i)
            graph->addData(s.edgesNs[i] / unit.ns, double(s.counts[i]));
        graph->addData(s.edgesNs.back() / unit.ns, 0);
    } else if (series.size() == 1) {
        const Series &s = series.constFirst();
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
            const Series &s = series.at(k);
            if (s.edgesNs.size() < 2)
                continue;
            // Steps drawn from each bin's left edge, closed at the last edge: the outline of bars.
            auto *graph = plot.addGraph();
            graph->setName(s.name);
            graph->setLineStyle(QCPGraph::lsStepLeft);
            graph->setPen(QPen(kColours[std::size_t(k) % std::size(kColours)], 2));
            for (std::size_t i = 0; i < s.counts.size(); ++i)
                graph->addData(s.edgesNs[i] / unit.ns, double(s.counts[i]));
            graph->addData(s.edgesNs.back() / unit.ns, double(s.counts.empty() ? 0 : s.counts.back()));
            graph->addData(s.edgesNs.back() / unit.ns, 0);
        }
    }
    if (logarithmic) {
        plot.xAxis->setScaleType(QCPAxis::stLogarithmic);
        plot.xAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
        plot.xAxis->setNumberFormat(QStringLiteral("g"));
        plot.xAxis->setRange(lowNs / unit.ns / 1.1, highNs / unit.ns * 1.1);
        plot.xAxis->setLabel(tr("latency (%1), logarithmic").arg(unit.name));
    } else {
        // One sample (or all alike) spans nothing: a range of zero width stacks the tick labels.
        const double margin = highNs > lowNs ? (highNs - lowNs) * 0.02 : std::max(double(lowNs) * 0.1, unit.ns);
        plot.xAxis->setRange((lowNs - margin) / unit.ns, (highNs + margin) / unit.ns);
    }
    // Head room above the highest bar for the markers' labels.
    plot.yAxis->setRange(0, double(highest) * 1.25 + 1);
    for (qsizetype k = 0; k < markers.size(); ++k) {
        const double x = markers.at(k).valueNs / unit.ns;
        auto *line = new QCPItemStraightLine(&plot);
        line->point1->setCoords(x, 0);
        line->point2->setCoords(x, 1);
        const QColor colour = markers.at(k).colour;
        line->setPen(QPen(colour.isValid() ? colour : QColor(90, 90, 90), 1, Qt::DashLine));
        auto *label = new QCPItemText(&plot);
        label->position->setCoords(x, double(highest) * (1.19 - 0.07 * double(k)) + 1);
        // A line in the right third gets its label on its left, inside the plot.
        const QCPRange shown = plot.xAxis->range();
        const double where = logarithmic ? std::log(x / shown.lower) / std::log(shown.upper / shown.lower)
                                         : (x - shown.lower) / shown.size();
        const bool leftOfLine = where > 0.7;
        label->setPositionAlignment((leftOfLine ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignVCenter);
        label->setPadding(leftOfLine ? QMargins(0, 0, 4, 0) : QMargins(4, 0, 0, 0));
        label->setColor(colour.isValid() ? colour : QColor(Qt::black));
        label->setText(markers.at(k).label);
        label->setFont(QFont(QStringLiteral("Sans"), 9));
    }
    return true;
}

} // namespace mbscope
