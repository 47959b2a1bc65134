#pragma once

#include <QtCore/QObject>
#include <QtCore/QTimer>

#include <functional>

class QAction;
class QCustomPlot;

namespace mbscope {

// What every plot of values over time does the same way (the latency and register trend panels):
// a Follow action that keeps everything in view while data arrives and turns itself off when the
// user zooms or pans by hand, a Clear action, and redraws coalesced to at most one every
// redrawMs so that a long poll costs one append per point, not one replot.
// The panel gives the two things only it knows: how to fit its axes and how to redraw.
class PlotFollower : public QObject
{
    Q_OBJECT
public:
    PlotFollower(QCustomPlot *plot, int redrawMs, QObject *parent);

    void setFit(std::function<void()> fit) { m_fit = std::move(fit); }
    void setRedraw(std::function<void()> redraw) { m_redraw = std::move(redraw); }

    [[nodiscard]] QAction *followAction() const { return m_follow; }
    [[nodiscard]] QAction *clearAction() const { return m_clear; }

    void setFollowing(bool following);
    [[nodiscard]] bool isFollowing() const { return m_following; }
    // Fits the axes when following; the plot's range changes this makes keep Follow on.
    void fitIfFollowing();
    // A redraw within redrawMs (several requests make one).
    void scheduleRedraw();
    // The pending redraw now, and the plot replotted at once (tests, screenshots).
    void redrawNow();

private:
    void fit();

    QCustomPlot *m_plot;
    QAction *m_follow;
    QAction *m_clear;
    QTimer m_redrawTimer;
    std::function<void()> m_fit;
    std::function<void()> m_redraw;
    bool m_following = true;
    bool m_fitting = false; // our own range changes do not turn Follow off
};

} // namespace mbscope
