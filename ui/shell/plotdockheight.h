#pragma once

#include <QtCore/QObject>

class QDockWidget;
class QMainWindow;

namespace mbscope {

// A dock of plots (Analysis) is as tall as the traffic list when they share the bottom area: at
// 1400x900 that left its plots 140 px. While the plots' dock is in front, the bottom area grows to
// half the window (the plots get 300 px and more from 1400x900 up); when another dock of the area
// comes forward, the height it had comes back, unless the user dragged the edge meanwhile.
class PlotDockHeight : public QObject
{
    Q_OBJECT

public:
    PlotDockHeight(QMainWindow *window, QDockWidget *plots);

    // The bottom area's share of the window's height while the plots are in front.
    static constexpr int kSharePercent = 50;

private:
    void follow(bool visible);

    QMainWindow *m_window;
    QDockWidget *m_plots;
    int m_before = 0; // the area's height before the plots came forward (0: not grown)
    int m_grownTo = 0;
};

} // namespace mbscope
