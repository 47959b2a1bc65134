#pragma once

#include "link/linkcontroller.h"
#include "sim/embeddedsimulator.h"

#include "exchange/transaction.h"

#include <QtWidgets/QMainWindow>

class QDockWidget;
class QSplitter;
class QTabWidget;

namespace mbscope {

class AnalysisDock;
class ConnectionBar;
class DecodePanel;
class LatencyAnalysis;
class LinkController;
class LinkStatusWidget;
class NoticeBanner;
class PlotDockHeight;
class RecordingControl;
class RegisterTable;
class RequestComposer;
class SessionController;
class ScanDialog;
class SessionTools;
class SimulatorNotice;
class SimulatorPanel;
class ToolsMenu;
class TrafficMonitor;
class TrendPanels;
class TransactionView;
class WatchWorkspace;
struct WatchDefinition;

// The window only assembles: the connection bar, the composer, the answer and decode views, the
// status bar and the menus are their own classes; LinkController talks to the engine. Here they
// are laid out and connected, nothing more.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    // Where a first run serves the RosRao detector: the port its serial device server uses.
    static constexpr const char *kFirstRunUrl = "rtu-tcp://127.0.0.1:4001";
    static constexpr const char *kFirstRunProfile = "rosrao-gamma";

    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    // The first run: the built-in simulator with the RosRao profile (on url, or a free loopback
    // port when that one is taken), connected, with the RosRao read ready in the composer.
    // False (and the reason in the connection bar) when the simulator cannot start.
    bool startWithSimulator(const QString &url = QString::fromLatin1(kFirstRunUrl));
    // A start without a session named: the first run (or every run, when Preferences says so)
    // is startWithSimulator(url); a later one opens the session open at the last close, or puts
    // back the last target, disconnected. True when the simulator was started.
    bool startAsConfigured(const QString &url = QString::fromLatin1(kFirstRunUrl));

    [[nodiscard]] DecodePanel *decodePanel() const { return m_decodePanel; }
    [[nodiscard]] ConnectionBar *connectionBar() const { return m_connectionBar; }
    [[nodiscard]] RequestComposer *composer() const { return m_composer; }
    [[nodiscard]] TransactionView *answerView() const { return m_answerView; }
    [[nodiscard]] LinkController *controller() const { return m_controller; }
    // Tools > Scan (made on first use): for the workspace to take its watchesRequested().
    [[nodiscard]] ScanDialog *scanDialog();
    [[nodiscard]] LinkStatusWidget *linkStatus() const { return m_linkStatus; }
    [[nodiscard]] NoticeBanner *banner() const { return m_banner; }
    [[nodiscard]] EmbeddedSimulator *simulator() const { return m_simulator; }
    [[nodiscard]] QTabWidget *viewTabs() const { return m_tabs; }
    [[nodiscard]] TrafficMonitor *trafficMonitor() const { return m_traffic; }
    [[nodiscard]] RegisterTable *registerTable() const { return m_registers; }
    [[nodiscard]] SessionController *session() const { return m_session; }
    // The bottom dock whose tabs hold the analysis panels (histogram, trends, sweep...).
    [[nodiscard]] AnalysisDock *analysisDock() const { return m_analysis; }
    [[nodiscard]] LatencyAnalysis *latencyAnalysis() const { return m_latency; }
    [[nodiscard]] TrendPanels *trendPanels() const { return m_trends; }
    [[nodiscard]] SessionTools *sessionTools() const { return m_sessionTools; }
    [[nodiscard]] RecordingControl *recording() const { return m_recording; }
    [[nodiscard]] SimulatorPanel *simulatorPanel() const { return m_simulatorPanel; }
    // The Watches tab of the main area: the session's watch windows (ui/watch).
    [[nodiscard]] WatchWorkspace *watchWorkspace() const { return m_workspace; }
    // Shows the main area's tab: "answer", "decode" or "watches"; false for another name.
    bool showTab(const QString &name);

    // Window geometry and dock layout kept in QSettings per screen size (WindowLayout):
    // restoreLayout() puts back what the last close on this screen saved (or on any screen, when
    // none was made on this one); false when nothing was saved.
    bool restoreLayout();
    void saveLayout() const;

protected:
    void showEvent(QShowEvent *event) override;
    void closeEvent(QCloseEvent *event) override;

private:
    void fitPanelsToWindow();
    void buildUi();
    void buildDocks();
    void connectPanels();
    void connectDocks();
    void showInRegisterTable(const Transaction &transaction);
    // After a session was opened: connect to the target its bar shows, or disconnect and say why.
    void useSessionTarget();
    // F6: focus moves to the next visible dock (tabbed docks are raised).
    void focusNextDock();
    void sendWrite(const QByteArray &pdu, const QString &description);
    void createMenus();
    void buildWorkspace();
    void addWatchesFromScan(const QList<WatchDefinition> &found);
    // The first-run banner for the link's state: on the simulator, listening to it, or disconnected.
    // The Registers dock names registers by the simulator's profile on the simulator only.
    void updateRegisterProfile();

    LinkController *m_controller = nullptr;
    ToolsMenu *m_tools = nullptr; // Tools and Help menus, the scan dialog
    EmbeddedSimulator *m_simulator = nullptr;
    ConnectionBar *m_connectionBar = nullptr;
    NoticeBanner *m_banner = nullptr;
    RequestComposer *m_composer = nullptr;
    QSplitter *m_splitter = nullptr;
    QTabWidget *m_tabs = nullptr;
    TransactionView *m_answerView = nullptr;
    DecodePanel *m_decodePanel = nullptr;
    LinkStatusWidget *m_linkStatus = nullptr;
    TrafficMonitor *m_traffic = nullptr;
    RegisterTable *m_registers = nullptr;
    QDockWidget *m_trafficDock = nullptr;
    QDockWidget *m_registersDock = nullptr;
    AnalysisDock *m_analysis = nullptr;
    QDockWidget *m_analysisDock = nullptr;
    LatencyAnalysis *m_latency = nullptr;
    TrendPanels *m_trends = nullptr;
    SessionController *m_session = nullptr;
    SessionTools *m_sessionTools = nullptr;
    RecordingControl *m_recording = nullptr;
    SimulatorPanel *m_simulatorPanel = nullptr;
    QDockWidget *m_simulatorDock = nullptr;
    PlotDockHeight *m_plotHeight = nullptr;
    WatchWorkspace *m_workspace = nullptr;
    SimulatorNotice *m_simulatorNotice = nullptr; // the banner about the built-in simulator
    QByteArray m_lastRead; // the read whose answer the register table shows: sent again after a write
    bool m_layoutRestored = false; // the docks' sizes came from QSettings: the first show keeps them
    bool m_fitted = false; // panel proportions set on the first show, then left to the user
};

} // namespace mbscope
