#include "plotdockheight.h"

#include <QtCore/QTimer>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QMainWindow>

namespace mbscope {

PlotDockHeight::PlotDockHeight(QMainWindow *window, QDockWidget *plots)
    : QObject(plots)
    , m_window(window)
    , m_plots(plots)
{
    connect(plots, &QDockWidget::visibilityChanged, this, &PlotDockHeight::follow);
}

void PlotDockHeight::follow(bool visible)
{
    if (m_plots->isFloating() || m_window->dockWidgetArea(m_plots) != Qt::BottomDockWidgetArea)
        return;
    if (visible) {
        int wanted = m_window->height() * kSharePercent / 100;
        // Never below what the central area needs (at 1024x700 the composer's rows overlapped):
        // the menu bar, the status bar and the dock's title and tabs take about 100 px besides.
        if (const QWidget *central = m_window->centralWidget())
            wanted = qMin(wanted, m_window->height() - central->minimumSizeHint().height() - 100);
        if (m_plots->height() >= wanted)
            return;
        m_before = m_plots->height();
        m_window->resizeDocks({m_plots}, {wanted}, Qt::Vertical);
        m_grownTo = m_plots->height();
        // The new height is known once the layout ran.
        QTimer::singleShot(0, this, [this] { m_grownTo = m_plots->height(); });
        return;
    }
    if (m_before == 0)
        return;
    // Another dock of the area came forward (the plots' dock is still open, behind it): its
    // height comes back, unless the user set the area's height himself meanwhile.
    const int before = m_before;
    m_before = 0;
    if (m_plots->height() != m_grownTo)
        return;
    // The dock that came forward is shown once the tab switch is done.
    QTimer::singleShot(0, this, [this, before] {
        for (QDockWidget *other : m_window->tabifiedDockWidgets(m_plots)) {
            if (other->isVisible()) {
                m_window->resizeDocks({other}, {before}, Qt::Vertical);
                return;
            }
        }
    });
}

} // namespace mbscope
