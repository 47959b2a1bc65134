#include "latencytimepanel.h"

#include "common/plotcursor.h"
#include "common/plotexportmenu.h"
#include "common/plotfollower.h"

#include <QtGui/QAction>
#include <QtWidgets/QLabel>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>

namespace mbscope {

LatencyTimePanel::LatencyTimePanel(QWidget *parent)
    : QWidget(parent)
    , m_plot(new QCustomPlot(this))
    , m_graphs(LatencyTimeGraphs::addTo(m_plot))
    , m_cursor(new PlotCursor(m_plot))
    , m_export(new PlotExportMenu(m_plot, QStringLiteral("latency-over-time")))
    , m_summary(new QLabel(this))
    , m_follower(new PlotFollower(m_plot, kRedrawMs, this))
{
    m_plot->setObjectName(QStringLiteral("latencyTimePlot"));
    m_plot->setMinimumSize(300, 200);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->xAxis->setLabel(tr("time since the first request (s)"));
    m_plot->yAxis->setLabel(tr("latency (ms)"));
    m_plot->legend->setVisible(true);
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    m_graphs.nameWithCounts(0, 0, 0);
    m_cursor->setXFormatter([](double x) { return tr("t = %1 s").arg(x, 0, 'f', 3); });
    const auto milliseconds = [](double ms) { return tr("%1 ms").arg(ms, 0, 'f', 3); };
    m_cursor->setValueFormatter(m_graphs.answered, milliseconds);
    m_cursor->setValueFormatter(m_graphs.exceptions, milliseconds);
    m_cursor->setValueFormatter(m_graphs.failed, [](double) { return QString(); });
    m_cursor->setLabel(m_graphs.answered, tr("answered"));
    m_cursor->setLabel(m_graphs.exceptions, tr("exception"));
    m_cursor->setLabel(m_graphs.failed, tr("no usable answer (timeout or bad answer)"));

    m_follower->setFit([this] { fitAxes(); });
    m_follower->setRedraw([this] { redraw(); });
    m_follower->followAction()->setToolTip(tr("Keep every transaction in view as new ones arrive"));
    m_follower->clearAction()->setToolTip(tr("Forget the points shown; new transactions start a new time axis"));
    connect(m_follower->clearAction(), &QAction::triggered, this, &LatencyTimePanel::clear);

    auto *tools = new QToolBar(this);
    m_tools = tools;
    tools->addAction(m_follower->followAction());
    tools->addAction(m_follower->clearAction());
    tools->addSeparator();
    tools->addAction(m_export->saveAction());
    tools->addAction(m_export->copyAction());
    tools->addSeparator();
    tools->addWidget(m_summary);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tools);
    layout->addWidget(m_plot, 1);
    clear();
}

void LatencyTimePanel::addTransactions(const QList<Transaction> &transactions)
{
    bool answered = false, exceptions = false, failed = false;
    for (const Transaction &t : transactions) {
        if (t.status == TransactionStatus::Late || t.status == TransactionStatus::Broadcast || t.sentNs == 0)
            continue;
        if (m_startNs == 0)
            m_startNs = t.sentNs;
        const double seconds = double(t.sentNs - m_startNs) / 1e9;
        m_lastSeconds = std::max(m_lastSeconds, seconds);
        if (t.status == TransactionStatus::Ok || t.status == TransactionStatus::Exception) {
            const double ms = double(t.latencyNs()) / 1e6;
            m_maxLatencyMs = std::max(m_maxLatencyMs, ms);
            (t.status == TransactionStatus::Ok ? m_answered : m_exceptions).add(seconds, ms);
            (t.status == TransactionStatus::Ok ? answered : exceptions) = true;
        } else {
            m_failed.add(seconds, 0.0);
            failed = true;
        }
    }
    // Send times only grow within a poll: the kept points are in key order.
    if (answered)
        m_graphs.answered->setData(m_answered.keys(), m_answered.values(), true);
    if (exceptions)
        m_graphs.exceptions->setData(m_exceptions.keys(), m_exceptions.values(), true);
    if (failed)
        m_graphs.failed->setData(m_failed.keys(), m_failed.values(), true);
    m_follower->scheduleRedraw();
}

void LatencyTimePanel::clear()
{
    m_graphs.answered->data()->clear();
    m_graphs.exceptions->data()->clear();
    m_graphs.failed->data()->clear();
    m_answered.clear();
    m_exceptions.clear();
    m_failed.clear();
    m_startNs = 0;
    m_lastSeconds = 0;
    m_maxLatencyMs = 0;
    m_cursor->hide();
    m_follower->setFollowing(true);
    redraw();
}

void LatencyTimePanel::setFollowing(bool following)
{
    m_follower->setFollowing(following);
}

bool LatencyTimePanel::isFollowing() const
{
    return m_follower->isFollowing();
}

QString LatencyTimePanel::summary() const
{
    const qint64 answered = m_answered.added();
    const qint64 exceptions = m_exceptions.added();
    const qint64 failed = m_failed.added();
    return tr("%1 transactions: %2 answered, %3 exceptions, %4 without a usable answer")
        .arg(answered + exceptions + failed)
        .arg(answered)
        .arg(exceptions)
        .arg(failed);
}

void LatencyTimePanel::addSourceChoice(QWidget *choice)
{
    QAction *first = m_tools->actions().value(0);
    m_tools->insertWidget(first, choice);
    if (first)
        m_tools->insertSeparator(first);
}

void LatencyTimePanel::redrawNow()
{
    m_follower->redrawNow();
}

void LatencyTimePanel::redraw()
{
    m_graphs.nameWithCounts(m_answered.added(), m_exceptions.added(), m_failed.added());
    // Only what happened is in the legend: most polls have no exceptions, some no failures.
    for (QCPGraph *graph : {m_graphs.exceptions, m_graphs.failed}) {
        if (graph->dataCount() > 0) // a graph with points was given some
            graph->addToLegend();
        else
            graph->removeFromLegend();
    }
    m_summary->setText(summary());
    m_follower->fitIfFollowing();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void LatencyTimePanel::fitAxes()
{
    m_plot->xAxis->setRange(0, std::max(m_lastSeconds * 1.02, 1.0));
    m_plot->yAxis->setRange(0, std::max(m_maxLatencyMs * 1.1, 1.0));
}

} // namespace mbscope
