#pragma once

#include <QtCore/QObject>

class QDockWidget;
class QMainWindow;
class QMenu;
class QMenuBar;

namespace mbscope {

class LinkController;
class PlanController;
class PlanPanel;
class ReplayController;
class ReplayPanel;
class SessionController;
class TrafficMonitor;

// The Session menu and what it drives: replay (offline re-analysis of a capture, replay to the
// connected target, serving the recorded answers) in a Replay dock, and the session's test plan
// in a Test plan dock, both beside the Traffic dock. MainWindow makes one and adds its menu.
class SessionTools : public QObject
{
    Q_OBJECT
public:
    SessionTools(QMainWindow *window, LinkController *link, SessionController *session, TrafficMonitor *traffic,
                 QDockWidget *besideDock);

    // "Session": open a capture, analyse the session's capture, replay, serve, run the plan...
    QMenu *addMenu(QMenuBar *menuBar);

    [[nodiscard]] ReplayController *replay() const { return m_replay; }
    [[nodiscard]] PlanController *plan() const { return m_plan; }
    [[nodiscard]] ReplayPanel *replayPanel() const { return m_replayPanel; }
    [[nodiscard]] PlanPanel *planPanel() const { return m_planPanel; }
    [[nodiscard]] QDockWidget *replayDock() const { return m_replayDock; }
    [[nodiscard]] QDockWidget *planDock() const { return m_planDock; }

private:
    void showDock(QDockWidget *dock);
    void status(const QString &text);

    QMainWindow *m_window;
    LinkController *m_link;
    SessionController *m_session;
    TrafficMonitor *m_traffic;
    ReplayController *m_replay;
    PlanController *m_plan;
    ReplayPanel *m_replayPanel;
    PlanPanel *m_planPanel;
    QDockWidget *m_replayDock;
    QDockWidget *m_planDock;
};

} // namespace mbscope
