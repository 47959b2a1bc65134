#include "plotfollower.h"

#include <QtGui/QAction>
#include <qcustomplot.h>

namespace mbscope {

PlotFollower::PlotFollower(QCustomPlot *plot, int redrawMs, QObject *parent)
    : QObject(parent)
    , m_plot(plot)
    , m_follow(new QAction(tr("&Follow"), this))
    , m_clear(new QAction(tr("C&lear"), this))
{
    m_follow->setCheckable(true);
    m_follow->setChecked(true);
    connect(m_follow, &QAction::toggled, this, &PlotFollower::setFollowing);
    // Zooming or panning by hand means the user is looking at something: stop following.
    const auto byHand = [this]() {
        if (!m_fitting)
            m_follow->setChecked(false);
    };
    connect(m_plot->xAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this, byHand);
    connect(m_plot->yAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this, byHand);
    m_redrawTimer.setSingleShot(true);
    m_redrawTimer.setInterval(redrawMs);
    connect(&m_redrawTimer, &QTimer::timeout, this, [this] {
        if (m_redraw)
            m_redraw();
    });
}

void PlotFollower::setFollowing(bool following)
{
    m_following = following;
    m_follow->setChecked(following);
    if (following) {
        fit();
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
}

void PlotFollower::fitIfFollowing()
{
    if (m_following)
        fit();
}

void PlotFollower::fit()
{
    if (!m_fit)
        return;
    m_fitting = true;
    m_fit();
    m_fitting = false;
}

void PlotFollower::scheduleRedraw()
{
    if (!m_redrawTimer.isActive())
        m_redrawTimer.start();
}

void PlotFollower::redrawNow()
{
    m_redrawTimer.stop();
    if (m_redraw)
        m_redraw();
    m_plot->replot();
}

} // namespace mbscope
