#include "latencytimegraphs.h"

#include <QtCore/QCoreApplication>
#include <qcustomplot.h>

namespace mbscope {

namespace {

QCPGraph *addDots(QCustomPlot *plot, const QColor &colour, QCPScatterStyle::ScatterShape shape, double size)
{
    auto *graph = plot->addGraph();
    graph->setLineStyle(QCPGraph::lsNone);
    graph->setScatterStyle(QCPScatterStyle(shape, colour, colour, size));
    return graph;
}

} // namespace

LatencyTimeGraphs LatencyTimeGraphs::addTo(QCustomPlot *plot)
{
    LatencyTimeGraphs graphs;
    graphs.answered = addDots(plot, QColor(31, 119, 180), QCPScatterStyle::ssDisc, 3);
    graphs.exceptions = addDots(plot, QColor(255, 127, 14), QCPScatterStyle::ssDisc, 4);
    graphs.failed = addDots(plot, QColor(214, 39, 40), QCPScatterStyle::ssCross, 7);
    return graphs;
}

void LatencyTimeGraphs::nameWithCounts(qsizetype answeredCount, qsizetype exceptionCount, qsizetype failedCount) const
{
    answered->setName(QCoreApplication::translate("mbscope::LatencyTimeGraphs", "answered (%1)").arg(answeredCount));
    exceptions->setName(QCoreApplication::translate("mbscope::LatencyTimeGraphs", "exceptions (%1)").arg(exceptionCount));
    failed->setName(QCoreApplication::translate("mbscope::LatencyTimeGraphs", "no usable answer (%1), drawn at 0").arg(failedCount));
}

} // namespace mbscope
