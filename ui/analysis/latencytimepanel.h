#pragma once

#include "latencytimegraphs.h"

#include "common/decimatedseries.h"

#include "exchange/transaction.h"

#include <QtCore/QList>
#include <QtWidgets/QWidget>

class QCustomPlot;
class QLabel;
class QToolBar;

namespace mbscope {

class PlotCursor;
class PlotExportMenu;
class PlotFollower;

// Latency over time for the Analysis dock: every transaction of the poll a point at its send
// time (seconds since the first one shown), answered ones at their latency, exceptions in their
// own colour, requests without a usable answer (timeouts first of all) as red crosses on the time
// axis. Late answers and broadcasts are not points: a late answer's request is already a cross.
//
// Each graph holds at most DecimatedSeries::kDefaultBudget points: past that, a bucket of time
// keeps its lowest and highest latency (spikes stay where they were), so a poll left running all
// day neither grows the window's memory nor slows the drawing; the counts stay those of every
// transaction. Redrawn at most every kRedrawMs. While "Follow" is on the axes show everything; the
// wheel zooms, dragging pans (and turns Follow off), a click pins the cursor.
class LatencyTimePanel : public QWidget
{
    Q_OBJECT

public:
    static constexpr int kRedrawMs = 50;

    explicit LatencyTimePanel(QWidget *parent = nullptr);

    void addTransactions(const QList<Transaction> &transactions);
    void clear();

    void setFollowing(bool following);
    [[nodiscard]] bool isFollowing() const;

    [[nodiscard]] QCustomPlot *plot() const { return m_plot; }
    [[nodiscard]] const LatencyTimeGraphs &graphs() const { return m_graphs; }
    // The points behind each graph (answered, exceptions, failed), every one counted.
    [[nodiscard]] const DecimatedSeries &answeredSeries() const { return m_answered; }
    [[nodiscard]] PlotCursor *cursor() const { return m_cursor; }
    [[nodiscard]] PlotExportMenu *exportMenu() const { return m_export; }
    [[nodiscard]] QString summary() const;
    // Puts the choice of whose latency is shown (LatencySource) first in the tool bar.
    void addSourceChoice(QWidget *choice);
    // Draws now what is pending (tests, screenshots): otherwise within kRedrawMs.
    void redrawNow();

private:
    void redraw();
    void fitAxes();

    QCustomPlot *m_plot;
    LatencyTimeGraphs m_graphs;
    DecimatedSeries m_answered;
    DecimatedSeries m_exceptions;
    DecimatedSeries m_failed;
    PlotCursor *m_cursor;
    PlotExportMenu *m_export;
    QLabel *m_summary;
    QToolBar *m_tools = nullptr;
    PlotFollower *m_follower;
    qint64 m_startNs = 0;
    double m_lastSeconds = 0;
    double m_maxLatencyMs = 0;
};

} // namespace mbscope
