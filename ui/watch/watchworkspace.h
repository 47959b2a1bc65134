#pragma once

#include "watchfactory.h"

#include "watch/watchdefinition.h"

#include "fleet/watchcounters.h"
#include "exchange/trafficentry.h"

#include <QtCore/QMap>
#include <QtCore/QSet>
#include <QtWidgets/QWidget>

#include <functional>
#include <optional>

class QAction;
class QLabel;
class QMdiArea;
class QMdiSubWindow;
class QMenu;

namespace mbscope {

class WatchDialog;
class WatchLogControl;
class TrafficLog;
class WatchRunner;
class WatchWindow;
struct WatchCounters;
struct WatchLinkState;
struct WatchRuleEvent;
struct WatchSample;

// The Watches tab: the session's watches, each in a window of an MDI area (tabbed or tiled, the
// user's choice), polled together by a WatchRunner (core/fleet: an engine per link in its own
// thread) when started. It keeps the definitions (SessionWatches, saved in the session) and the
// actions of the Watches menu; the windows show what the runner reports.
class WatchWorkspace : public QWidget
{
    Q_OBJECT
public:
    explicit WatchWorkspace(QWidget *parent = nullptr);
    ~WatchWorkspace() override;

    [[nodiscard]] const SessionWatches &watches() const { return m_watches; }
    // The session's watches (opened or new): the windows are made anew, a running runner stopped.
    void setWatches(const SessionWatches &watches);

    [[nodiscard]] int count() const { return int(m_watches.watches.size()); }
    [[nodiscard]] WatchWindow *window(int index) const;
    [[nodiscard]] int currentIndex() const;
    void setCurrentIndex(int index);
    [[nodiscard]] QMdiArea *area() const { return m_area; }

    int addWatch(const WatchDefinition &watch);
    void replaceWatch(int index, const WatchDefinition &watch);
    void removeWatch(int index);
    void moveWatch(int index, int delta);
    void duplicateWatch(int index);
    // Names of every watch but index's.
    [[nodiscard]] QStringList namesExcept(int index = -1) const;

    // The composer's read as a watch (the shell knows the composer and the connection bar).
    using RequestSource = std::function<WatchFromRequest(const QStringList &taken)>;
    void setRequestSource(RequestSource source) { m_requestSource = std::move(source); }
    // The connection bar's target: the default of new watches.
    void setTargetSource(std::function<QString()> source) { m_targetSource = std::move(source); }
    // The session document's path: a log directory that is not absolute is relative to it.
    void setSessionPathSource(std::function<QString()> source);
    bool addFromRequest(QString *error);
    // A watch per group of entries of unit of the profile (a shipped name or a file), none asking
    // more than its limits.maxQuantity; its limits.minGapMs and warmUpMs become the target link's
    // gapMs and warmUpMs (at least). How many watches were made.
    int addFromProfile(const QString &profile, int unit, const QString &target, int intervalMs, QString *error);

    void startAll();
    void stopAll();
    [[nodiscard]] bool isRunning() const;
    // One watch on its own: started (a watch that is off, "Poll this watch" unticked, is turned on),
    // or stopped while the others go on polling. The runner takes the new set of polled watches.
    void startWatch(int index);
    void stopWatch(int index);
    // Whether the runner polls watch index now.
    [[nodiscard]] bool isPolling(int index) const;
    [[nodiscard]] WatchRunner *runner() const { return m_runner; }
    // The window's recording (LinkController::trafficLog, shared): every link's frames go there,
    // now and in every run; nullptr: none (returns once no engine writes the old one).
    void setTrafficLog(TrafficLog *log);

    // Writes text into row of watch index's table (a writable point): false with the reason.
    bool writeValue(int index, int row, const QString &text, QString *error);

    [[nodiscard]] bool isTabbed() const;
    void setTabbed(bool tabbed);
    [[nodiscard]] WatchLogControl *logControl() const { return m_log; }

    // The Watches menu's actions, in order (separators as null).
    [[nodiscard]] QList<QAction *> menuActions() const;
    [[nodiscard]] QAction *newAction() const { return m_newAction; }
    [[nodiscard]] QAction *fromRequestAction() const { return m_fromRequestAction; }
    [[nodiscard]] QAction *fromProfileAction() const { return m_fromProfileAction; }
    [[nodiscard]] QAction *startAction() const { return m_startAction; }
    [[nodiscard]] QAction *stopAction() const { return m_stopAction; }
    [[nodiscard]] QAction *nextAction() const { return m_nextAction; }
    [[nodiscard]] QAction *writeAction() const { return m_writeAction; }
    [[nodiscard]] QAction *tabbedAction() const { return m_tabbedAction; }
    [[nodiscard]] QAction *closeAction() const { return m_closeAction; }
    [[nodiscard]] QAction *copyAction() const { return m_copyAction; }
    // Starts or stops the current watch (checked while it polls).
    [[nodiscard]] QAction *pollThisAction() const { return m_pollThisAction; }
    // Asks for the current value of the current watch in the Register trends.
    [[nodiscard]] QAction *trendAction() const { return m_trendAction; }
    // The actions of a watch window's context menu, in order (separators as null).
    [[nodiscard]] QList<QAction *> windowMenuActions() const;

    // How the workspace asks: a watch dialog (true: accepted), a value to write. Replaceable, so
    // tests answer without a modal dialog.
    using DialogRunner = std::function<bool(WatchDialog &dialog)>;
    using TextPrompt = std::function<std::optional<QString>(const QString &title, const QString &label, const QString &current)>;
    void setDialogRunner(DialogRunner runner) { m_dialogRunner = std::move(runner); }
    void setTextPrompt(TextPrompt prompt) { m_textPrompt = std::move(prompt); }

Q_SIGNALS:
    // The definitions changed by the user (the session is modified).
    void changed();
    // The definitions changed, by the user or by a session opened (names, links, points).
    void definitionsChanged();
    // A line for the status bar.
    void message(const QString &text);
    void runningChanged(bool running);
    // Every batch of the runner's samples, as the windows got them (trends, latency panels, counters).
    void sampled(const QList<mbscope::WatchSample> &samples);
    // Every frame of every link the watches poll, as its engine logs it (the traffic view).
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    // The user asked for a value of a watch in the Register trends ("Trend this value"); the
    // point is named by its name, or by its address when it has none.
    void trendRequested(const QString &watchName, quint16 address, const QString &pointName);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    int m_frontWhenShown = -1; // the watch to bring in front once the area is shown (a hidden one ignores it)
    void createActions();
    void rebuildWindows();
    QMdiSubWindow *addWindow(int index);
    void updateWindowTitle(int index);
    void updateActions();
    void watchesEdited();
    void newWatch();
    void editCurrent();
    void writeCurrent();
    void requestWrite(int index, int row);
    void trendCurrent();
    void showWindowMenu(int index, const QPoint &globalPos);
    void startRunner();
    void updatePolling();
    // The watches as the runner gets them: only those polled now are enabled.
    [[nodiscard]] SessionWatches runnerWatches() const;
    void onSampled(const QList<WatchSample> &samples, const QList<WatchCounters> &counters);
    void onRule(const WatchRuleEvent &event);
    void onLinkState(const WatchLinkState &state);
    [[nodiscard]] bool runDialog(WatchDialog &dialog);

    SessionWatches m_watches;
    QSet<QString> m_polled; // names of the watches polled while the runner runs
    // Starting or stopping one watch alone restarts the runner's links, and its counters start
    // anew: the windows carry on counting. A watch's counters that went back (its polls no more
    // than last time) were restarted; what it had counted is added to what comes. Edited
    // definitions, Start all and a runner started afresh count from zero (m_carrying false).
    bool m_carrying = false;
    QMap<QString, WatchCounters> m_lastCounters; // as the runner last sent them, per watch name
    QMap<QString, WatchCounters> m_carried;      // counted before the runner's restarts
    [[nodiscard]] WatchCounters shownCounters(const WatchCounters &counters);
    QMdiArea *m_area;
    QLabel *m_hint;
    QList<WatchWindow *> m_windows;
    WatchRunner *m_runner = nullptr;
    TrafficLog *m_trafficLog = nullptr;
    WatchLogControl *m_log = nullptr;
    RequestSource m_requestSource;
    std::function<QString()> m_targetSource;
    DialogRunner m_dialogRunner;
    TextPrompt m_textPrompt;

    QAction *m_newAction = nullptr;
    QAction *m_fromRequestAction = nullptr;
    QAction *m_fromProfileAction = nullptr;
    QAction *m_editAction = nullptr;
    QAction *m_duplicateAction = nullptr;
    QAction *m_closeAction = nullptr;
    QAction *m_moveLeftAction = nullptr;
    QAction *m_moveRightAction = nullptr;
    QAction *m_startAction = nullptr;
    QAction *m_stopAction = nullptr;
    QAction *m_nextAction = nullptr;
    QAction *m_writeAction = nullptr;
    QAction *m_copyAction = nullptr;
    QAction *m_tabbedAction = nullptr;
    QAction *m_pollThisAction = nullptr;
    QAction *m_trendAction = nullptr;
};

} // namespace mbscope
