#pragma once

#include "fleet/watchcounters.h"
#include "fleet/watchlinkstate.h"

#include <QtWidgets/QWidget>

class QLabel;
class QTableView;

namespace mbscope {

class WatchTableModel;

// One watch window of the workspace: its table of values and, below it, its counters (polls,
// ok, exceptions, timeouts, the last error and when) and its link's state. Double-click (or F2
// on) a writable value asks the workspace to write it.
class WatchWindow : public QWidget
{
    Q_OBJECT
public:
    explicit WatchWindow(QWidget *parent = nullptr);

    [[nodiscard]] WatchTableModel *model() const { return m_model; }
    [[nodiscard]] QTableView *view() const { return m_view; }
    [[nodiscard]] QLabel *countersLabel() const { return m_counters; }
    [[nodiscard]] const WatchCounters &counters() const { return m_lastCounters; }

    void setCounters(const WatchCounters &counters);
    void setLinkState(const WatchLinkState &state);
    // Whether the runner polls this watch now: said first in the status line.
    void setPolling(bool polling);
    [[nodiscard]] bool isPolling() const { return m_polling; }
    // The watch's link as last reported (Stopped before the first report).
    [[nodiscard]] WatchLinkState::State linkState() const { return m_hasLink ? m_link.state : WatchLinkState::State::Stopped; }
    // The counters of a watch whose runner was restarted (another watch started or stopped alone)
    // carried on: before's counts plus now's, the last error and latency the newest.
    [[nodiscard]] static WatchCounters carried(const WatchCounters &before, const WatchCounters &now);
    // The counters line as shown ("polls 12 · ok 11 · exceptions 0 · timeouts 1 · ...").
    [[nodiscard]] static QString countersText(const WatchCounters &counters);
    // The selected cells as tab-separated text (a header row first), for the clipboard.
    [[nodiscard]] QString selectionText() const;

Q_SIGNALS:
    void writeRequested(int row);
    // A right click in the table (row -1 outside the rows), at globalPos.
    void contextMenuRequested(int row, const QPoint &globalPos);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void updateStatus();

    WatchTableModel *m_model;
    QTableView *m_view;
    QLabel *m_counters;
    WatchCounters m_lastCounters;
    WatchLinkState m_link;
    bool m_hasLink = false;
    bool m_polling = false;
};

} // namespace mbscope
