#include "mainwindow.h"

#include "protocol/functionspec.h"

#include "analysis/analysisdock.h"
#include "common/appicon.h"
#include "link/connectionbar.h"
#include "decode/decodepanel.h"
#include "docknavigator.h"
#include "analysis/latencyanalysis.h"
#include "analysis/latencysource.h"
#include "analysis/registertrendpanel.h"
#include "link/linkcontroller.h"
#include "linkstatuswidget.h"
#include "common/noticebanner.h"
#include "plotdockheight.h"
#include "preferencesdialog.h"
#include "session/recordingcontrol.h"
#include "compose/rawrequesteditor.h"
#include "registers/registertable.h"
#include "registers/registertablemodel.h"
#include "session/replaycontroller.h"
#include "compose/requestcomposer.h"
#include "compose/savedrequests.h"
#include "session/sessioncontroller.h"
#include "sim/simulatorpanel.h"
#include "sessiontools.h"
#include "simulatornotice.h"
#include "tapmode.h"
#include "toolsmenu.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"
#include "windowlayout.h"
#include "decode/transactionview.h"
#include "analysis/trendpanels.h"
#include "watch/watchfactory.h"
#include "watch/watchworkspace.h"

#include "protocol/adubuilder.h"

#include <QtCore/QTimer>
#include <QtCore/QCoreApplication>
#include <QtCore/QFileInfo>
#include <QtCore/QSettings>
#include <QtGui/QCloseEvent>
#include <QtGui/QAction>
#include <QtGui/QKeySequence>
#include <QtGui/QShortcut>
#include <QtWidgets/QApplication>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QSplitter>
#include <QtWidgets/QStatusBar>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_controller(new LinkController(this))
    , m_simulator(new EmbeddedSimulator(this))
{
    setWindowTitle(QStringLiteral("mbscope"));
    setWindowIcon(applicationIcon());
    if (QApplication::windowIcon().isNull())
        QApplication::setWindowIcon(windowIcon()); // dialogs and other windows
    buildUi();
    buildDocks();
    connectPanels();
    connectDocks();
    new TapMode(this, m_connectionBar, m_controller, m_traffic, m_composer, statusBar()); // the bar's Tap
    m_session = new SessionController(this, m_connectionBar, m_composer);
    connect(m_session, &SessionController::titleChanged, this, &QMainWindow::setWindowTitle);
    connect(m_session, &SessionController::targetApplied, this, &MainWindow::useSessionTarget);
    connect(m_session, &SessionController::saveNotice, this, [this](const QString &text) { statusBar()->showMessage(text, 15000); });
    // Replay and test plans: the Session menu and the Replay and Test plan docks beside Traffic.
    m_sessionTools = new SessionTools(this, m_controller, m_session, m_traffic, m_trafficDock);
    // The Latency histogram and Compare tabs of the Analysis dock; an opened capture is shown there too.
    m_latency = new LatencyAnalysis(m_analysis, m_controller, this);
    connect(m_sessionTools->replay(), &ReplayController::captureAnalysed, m_latency, &LatencyAnalysis::showTransactions);
    // Latency over time, Register trends and Sweep tabs; a sweep polls the composer's request.
    m_trends = new TrendPanels(m_analysis, m_controller, m_registers, [this] { return m_composer->bytes(); }, this);
    m_latency->feedTimePanel(m_trends->latency());
    // Every connection recorded into the capture folder; a journal a crash left is offered back.
    m_recording = new RecordingControl(m_controller, m_session, m_sessionTools->replay(), this);
    connect(m_recording, &RecordingControl::message, this, [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    if (auto *layout = qobject_cast<QVBoxLayout *>(centralWidget()->layout()))
        layout->insertWidget(layout->indexOf(m_banner) + 1, m_recording->recoveryBanner());
    m_recording->offerRecovery();
    buildWorkspace();
    DockNavigator(this).makeScrollable(m_trafficDock);
    createMenus();
    statusBar()->showMessage(tr("Ready"), 3000);
    resize(1400, 900);
}

MainWindow::~MainWindow()
{
    // The engine's link goes first, so the simulator does not log a client vanishing mid-request.
    delete m_controller;
    m_controller = nullptr;
    delete m_plotHeight; // before the docks go: their hiding must not resize a window being taken apart
    m_simulator->stop();
}

void MainWindow::buildUi()
{
    m_connectionBar = new ConnectionBar(this);
    m_connectionBar->setObjectName(QStringLiteral("connectionBar"));
    m_banner = new NoticeBanner(this);
    m_simulatorNotice = new SimulatorNotice(m_simulator, m_controller, m_banner, this);
    m_composer = new RequestComposer(this);
    m_composer->setObjectName(QStringLiteral("requestComposer"));
    m_answerView = new TransactionView(this);
    m_answerView->setObjectName(QStringLiteral("answerView"));
    m_decodePanel = new DecodePanel(this);
    m_decodePanel->setObjectName(QStringLiteral("decodePanel"));

    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("viewTabs"));
    m_tabs->setDocumentMode(true);
    m_tabs->addTab(m_answerView, tr("&Answer"));
    m_tabs->addTab(m_decodePanel, tr("&Decode any frame"));
    m_workspace = new WatchWorkspace(this);
    // No accelerator: every letter of the word is taken in the window; Ctrl+F6 and the Watches
    // menu bring the tab forward.
    m_tabs->addTab(m_workspace, tr("Watches"));

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->addWidget(m_composer);
    m_splitter->addWidget(m_tabs);
    m_splitter->setStretchFactor(0, 0);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setSizes({470, 930});
    m_splitter->setChildrenCollapsible(false);

    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->addWidget(m_connectionBar);
    layout->addWidget(m_banner);
    layout->addWidget(m_splitter, 1);
    setCentralWidget(central);

    m_linkStatus = new LinkStatusWidget(this);
    statusBar()->addPermanentWidget(m_linkStatus);

    m_composer->setFraming(m_connectionBar->framing());
    m_composer->setUnitId(m_connectionBar->unitId());
}

void MainWindow::connectPanels()
{
    ConnectionBar *bar = m_connectionBar;
    LinkController *link = m_controller;
    connect(bar, &ConnectionBar::connectRequested, link, &LinkController::connectTo);
    connect(bar, &ConnectionBar::listenRequested, link, &LinkController::listenTo);
    connect(bar, &ConnectionBar::disconnectRequested, link, &LinkController::disconnectLink);
    connect(bar, &ConnectionBar::framingChanged, m_composer, &RequestComposer::setFraming);
    connect(bar, &ConnectionBar::unitIdChanged, m_composer, &RequestComposer::setUnitId);
    connect(m_composer, &RequestComposer::unitIdSeen, bar, &ConnectionBar::setUnitId);

    connect(link, &LinkController::stateChanged, this, [this, bar](LinkController::State state, const QString &message) {
        const bool connected = state != LinkController::State::Disconnected;
        bar->setConnected(connected);
        // The traffic list names the link its frames travel on (set when the target is, before
        // the first request: Connected comes only once the link answered).
        if (state == LinkController::State::Ready) {
            m_traffic->model()->setCurrentLink(m_controller->url().toString());
            updateRegisterProfile();
        }
        m_composer->setLinkReady(connected);
        m_composer->setListenOnly(m_controller->isListening());
        m_linkStatus->setState(state, message);
        if (m_simulator->isRunning() && !m_banner->isHidden())
            m_simulatorNotice->follow(state);
        if (state == LinkController::State::Failed)
            bar->showLinkFailure(message);
        else if (state == LinkController::State::Connected) {
            bar->clearError();
            bar->addRecent(m_controller->url());
        }
    });
    connect(link, &LinkController::countersChanged, m_linkStatus, &LinkStatusWidget::setCounters);
    connect(link, &LinkController::pollingChanged, m_composer, &RequestComposer::setPolling);
    connect(link, &LinkController::latestTransaction, this, [this](const Transaction &transaction) {
        m_answerView->showTransaction(transaction, m_controller->url().framing());
    });
    connect(link, &LinkController::pollFinished, this, [this](const PollReport &report) {
        m_answerView->flush();
        statusBar()->showMessage(LinkController::describe(report), 15000);
    });

    // A new Send or Poll asks for new answers: the Answer tab follows the link again.
    connect(m_composer, &RequestComposer::sendRequested, this, [this](const QByteArray &bytes) {
        m_tabs->setCurrentWidget(m_answerView);
        m_answerView->backToLive();
        m_controller->send(bytes);
    });
    connect(m_composer, &RequestComposer::pollRequested, this, [this](const QByteArray &bytes, int intervalMs, quint64 count) {
        m_tabs->setCurrentWidget(m_answerView);
        m_answerView->backToLive();
        m_controller->startPoll(bytes, intervalMs, count);
    });
    connect(m_composer, &RequestComposer::stopPollRequested, link, &LinkController::stopPoll);
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    if (!m_fitted) {
        m_fitted = true;
        fitPanelsToWindow();
    }
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    // What the next start puts back is not lost: an untitled session asks only about the rest.
    if (!m_session->maybeSaveBeforeQuit(!PreferencesDialog::startsSimulator())) {
        event->ignore();
        return;
    }
    saveLayout();
    // The next start opens this session again (none: the last target is put back).
    QSettings settings;
    settings.setValue(QStringLiteral("session/last"), m_session->filePath());
    settings.setValue(QStringLiteral("composer/intervalMs"), m_composer->intervalSpin()->value());
    settings.setValue(QStringLiteral("composer/count"), m_composer->countSpin()->value());
    settings.setValue(QStringLiteral("composer/request"), m_composer->state().requestText);
    m_registers->storeFormats();
    QMainWindow::closeEvent(event);
}

bool MainWindow::restoreLayout()
{
    const WindowLayout::Restored restored = WindowLayout::restore(*this, WindowLayout::screenSize(*this));
    m_layoutRestored = restored.state;
    return restored.geometry || restored.state;
}

void MainWindow::saveLayout() const
{
    WindowLayout::save(*this, WindowLayout::screenSize(*this));
}

// The composer needs about 450 px for its poll row; the answer gets the rest. The docks take a
// bit over a quarter of the height: enough rows of traffic to follow a poll, the answer's two
// trees keep most of it.
void MainWindow::fitPanelsToWindow()
{
    const int composerWidth = qBound(420, width() / 3, 520);
    m_splitter->setSizes({composerWidth, qMax(200, m_splitter->width() - composerWidth)});
    if (!m_layoutRestored)
        resizeDocks({m_trafficDock}, {qBound(160, height() * 28 / 100, 320)}, Qt::Vertical);
}

void MainWindow::buildDocks()
{
    setDockOptions(dockOptions() | QMainWindow::AllowTabbedDocks);
    m_traffic = new TrafficMonitor(this);
    m_traffic->setObjectName(QStringLiteral("trafficMonitor"));
    m_trafficDock = new QDockWidget(tr("Traffic"), this);
    m_trafficDock->setObjectName(QStringLiteral("trafficDock"));
    m_trafficDock->setWidget(m_traffic);
    addDockWidget(Qt::BottomDockWidgetArea, m_trafficDock);

    m_registers = new RegisterTable(this);
    m_registers->setObjectName(QStringLiteral("registerTable"));
    m_registersDock = new QDockWidget(tr("Registers"), this);
    m_registersDock->setObjectName(QStringLiteral("registersDock"));
    m_registersDock->setWidget(m_registers);
    addDockWidget(Qt::BottomDockWidgetArea, m_registersDock);
    tabifyDockWidget(m_trafficDock, m_registersDock);

    m_analysis = new AnalysisDock(this);
    m_analysis->setObjectName(QStringLiteral("analysis"));
    m_analysisDock = new QDockWidget(tr("Analysis"), this);
    m_analysisDock->setObjectName(QStringLiteral("analysisDock"));
    m_analysisDock->setWidget(m_analysis);
    addDockWidget(Qt::BottomDockWidgetArea, m_analysisDock);
    tabifyDockWidget(m_registersDock, m_analysisDock);

    m_simulatorPanel = new SimulatorPanel(this);
    m_simulatorPanel->setObjectName(QStringLiteral("simulatorPanel"));
    m_simulatorDock = new QDockWidget(tr("Simulator"), this);
    m_simulatorDock->setObjectName(QStringLiteral("simulatorDock"));
    m_simulatorDock->setWidget(m_simulatorPanel);
    addDockWidget(Qt::BottomDockWidgetArea, m_simulatorDock);
    tabifyDockWidget(m_analysisDock, m_simulatorDock);
    m_plotHeight = new PlotDockHeight(this, m_analysisDock); // the plots get half the window in front
    m_trafficDock->raise();
}

void MainWindow::connectDocks()
{
    // Every transaction goes to the traffic list; a row picked there is shown in the Answer tab.
    connect(m_controller, &LinkController::framesLogged, m_traffic, &TrafficMonitor::appendLinkFrames);
    // A listen-only link has no engine to log frames: its exchanges are listed as it pairs them.
    connect(m_controller, &LinkController::transactionsFinished, this, [this](const QList<Transaction> &transactions) {
        if (!m_controller->isListening())
            return;
        m_traffic->model()->setCurrentLink(m_controller->url().toString());
        m_traffic->appendTransactions(transactions);
    });
    connect(m_traffic, &TrafficMonitor::frameSelected, this, [this](const FrameExchange &exchange) {
        m_tabs->setCurrentWidget(m_answerView);
        m_answerView->showExchange(exchange);
    });
    // Back to live: the row that was picked is no longer what the Answer tab shows.
    connect(m_answerView, &TransactionView::wentLive, m_traffic, [this] { m_traffic->selectRow(-1); });
    // Answers to reads (a poll's, a single send's) fill the register table; its edits are sent.
    connect(m_controller, &LinkController::latestTransaction, this, &MainWindow::showInRegisterTable);
    connect(m_registers, &RegisterTable::writeRequested, this, &MainWindow::sendWrite);
    // The first-run simulator is one of the simulator panel's entries.
    connect(m_simulator, &EmbeddedSimulator::hostStarted, m_simulatorPanel, [this](SimulatorHost *host) {
        m_simulatorPanel->addRunning(host, m_simulator->profileName(), true);
    });
}

void MainWindow::showInRegisterTable(const Transaction &transaction)
{
    if (!transaction.isOk())
        return;
    const Framing framing = m_controller->url().framing();
    const AduParts request = AduBuilder::parse(transaction.request, framing);
    // Only reads (01-04, 17) have values to show; a write's answer would replace them with a complaint.
    const quint8 function = request.pdu.isEmpty() ? 0 : quint8(request.pdu.at(0));
    if (!functionReadsValues(function))
        return;
    m_lastRead = transaction.request;
    m_registers->showTransaction(transaction, framing);
}

void MainWindow::buildWorkspace()
{
    // New watches start from what the window shows: the connection bar's target, the composer's
    // read and its poll interval.
    m_workspace->setTargetSource([this] {
        const std::optional<LinkUrl> url = m_connectionBar->url();
        return url ? url->toString() : QString();
    });
    m_workspace->setRequestSource([this](const QStringList &taken) {
        const std::optional<LinkUrl> url = m_connectionBar->url();
        if (!url) {
            WatchFromRequest none;
            none.error = tr("The connection bar names no target: %1").arg(m_connectionBar->errorText());
            return none;
        }
        return WatchFactory::fromRequest(m_composer->bytes(), url->framing(), url->toString(),
                                         m_composer->intervalSpin()->value(), taken);
    });
    connect(m_workspace, &WatchWorkspace::message, this, [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    // The watches are part of the session: saved with it, put back when one is opened.
    m_session->setWatchesAccess([this] { return m_workspace->watches(); },
                                [this](const SessionWatches &watches) { m_workspace->setWatches(watches); });
    // A log directory that is not absolute is relative to the session document.
    m_workspace->setSessionPathSource([this] { return m_session->filePath(); });
    connect(m_workspace, &WatchWorkspace::changed, m_session, &SessionController::refreshModified);
    // The watches reach the Analysis dock (Register trends take their values, the latency panels
    // their polls) and the status bar (their traffic beside the bench's).
    connect(m_workspace, &WatchWorkspace::definitionsChanged, this, [this] {
        m_trends->trends()->setWatches(m_workspace->watches());
        m_latency->source()->setWatches(m_workspace->watches());
    });
    connect(m_workspace, &WatchWorkspace::sampled, m_trends->trends(), &RegisterTrendPanel::addWatchSamples);
    connect(m_workspace, &WatchWorkspace::sampled, m_latency->source(), &LatencySource::addWatchSamples);
    connect(m_workspace, &WatchWorkspace::sampled, m_linkStatus, &LinkStatusWidget::addWatchTraffic);
    // Their frames go to the traffic list and the window's recording, beside the composer's; a
    // recording that ends is let go of before it closes (a direct connection).
    connect(m_workspace, &WatchWorkspace::framesLogged, m_traffic, &TrafficMonitor::appendLinkFrames);
    m_workspace->setTrafficLog(m_controller->trafficLog());
    connect(m_controller, &LinkController::trafficLogChanged, m_workspace, &WatchWorkspace::setTrafficLog, Qt::DirectConnection);
    connect(m_workspace, &WatchWorkspace::trendRequested, this, [this](const QString &watch, quint16 address, const QString &point) {
        RegisterTrendPanel *trends = m_trends->trends();
        const int index = trends->addWatchValue(watch, address, point);
        m_analysisDock->show();
        m_analysisDock->raise();
        m_analysis->showPanel(trends);
        statusBar()->showMessage(tr("Plotting %1 in Analysis \u2192 Register trends").arg(trends->series(index).label()), 10000);
    });
    m_session->markClean();
}

bool MainWindow::showTab(const QString &name)
{
    const QString key = name.trimmed().toLower();
    QWidget *tab = key == QLatin1String("answer") ? static_cast<QWidget *>(m_answerView)
        : key == QLatin1String("decode")          ? static_cast<QWidget *>(m_decodePanel)
        : key == QLatin1String("watches")         ? static_cast<QWidget *>(m_workspace)
                                                  : nullptr;
    if (!tab)
        return false;
    m_tabs->setCurrentWidget(tab);
    return true;
}

void MainWindow::focusNextDock()
{
    if (QDockWidget *next = DockNavigator(this).focusNext())
        statusBar()->showMessage(tr("%1 dock (F6: the next one)").arg(next->windowTitle().remove(QLatin1Char('&'))), 3000);
}

void MainWindow::useSessionTarget()
{
    // The bar shows the session's target; sending anywhere else would put one link's framing on
    // another (MBAP bytes read as RTU, an RTU frame as a broken MBAP header).
    const std::optional<LinkUrl> target = m_connectionBar->url();
    if (!target) {
        if (m_controller->isConnected())
            m_controller->disconnectLink();
        statusBar()->showMessage(tr("Disconnected: the session names no target that can be used (%1)")
                                     .arg(m_connectionBar->errorText()),
                                 15000);
        return;
    }
    m_controller->connectTo(*target);
    statusBar()->showMessage(tr("Connecting to the session's target %1").arg(target->toString()), 10000);
}

void MainWindow::sendWrite(const QByteArray &pdu, const QString &description)
{
    if (!m_controller->isConnected()) {
        statusBar()->showMessage(tr("Not sent (%1): connect first").arg(description), 5000);
        return;
    }
    AduOptions options;
    options.framing = m_controller->url().framing();
    options.unitId = quint8(m_connectionBar->unitId());
    options.transactionId = 1; // the engine gives it the connection's next one (LinkController::send)
    m_controller->send(AduBuilder::complete(pdu, options));
    // The table shows what the device holds, not what was typed: the read it came from goes out
    // again after the write (queued behind it), unless a poll reads it anyway.
    if (!m_lastRead.isEmpty() && !m_controller->isPolling()) {
        m_controller->send(m_lastRead);
        statusBar()->showMessage(tr("Sent: %1; reading it back").arg(description), 5000);
        return;
    }
    statusBar()->showMessage(tr("Sent: %1").arg(description), 5000);
}

bool MainWindow::startAsConfigured(const QString &url)
{
    QSettings settings;
    const bool firstRun = !settings.value(QStringLiteral("startup/started")).toBool();
    settings.setValue(QStringLiteral("startup/started"), true);
    // The poll interval and count as they were left, on the simulator too (a session opened
    // next sets its own).
    if (settings.contains(QStringLiteral("composer/intervalMs"))) {
        m_composer->intervalSpin()->setValue(settings.value(QStringLiteral("composer/intervalMs")).toInt());
        m_composer->countSpin()->setValue(settings.value(QStringLiteral("composer/count")).toInt());
    }
    if (firstRun || PreferencesDialog::startsSimulator())
        return startWithSimulator(url);
    m_registers->restoreFormats(); // the value columns as they were left
    const QString last = settings.value(QStringLiteral("session/last")).toString();
    if (!last.isEmpty() && QFileInfo::exists(last) && m_session->open(last))
        return false;
    const QStringList recent = m_connectionBar->recentTargets();
    if (!recent.isEmpty()) {
        if (const std::optional<LinkUrl> lastTarget = LinkUrl::parse(recent.constFirst()).url) {
            m_connectionBar->setUrl(*lastTarget);
            m_composer->setFraming(lastTarget->framing());
            statusBar()->showMessage(tr("Not connected: press Connect to use %1 again").arg(lastTarget->toString()), 15000);
        }
    }
    // The request the composer held at the last close, in the framing of the target put back.
    const QString request = settings.value(QStringLiteral("composer/request")).toString();
    if (!request.trimmed().isEmpty())
        m_composer->setRequestText(request);
    m_session->markClean();
    return false;
}

bool MainWindow::startWithSimulator(const QString &url)
{
    const EmbeddedSimulator::Started started = m_simulator->start(QString::fromLatin1(kFirstRunProfile), url);
    if (!started.ok) {
        m_connectionBar->showError(started.error);
        return false;
    }
    m_connectionBar->setUrl(started.url);
    m_connectionBar->setUnitId(1);
    m_composer->setFraming(started.url.framing());
    const SavedRequest read = SavedRequests::rosRaoRead();
    m_composer->rawEditor()->setText(read.hex);
    m_composer->showRawTab();
    m_composer->rawEditor()->editor()->setFocus();
    if (const std::optional<LinkUrl> target = m_connectionBar->url())
        m_controller->connectTo(*target);
    updateRegisterProfile();
    if (const UnitProfile *unit = m_simulator->profile().unit(1))
        m_trends->setProfile(*unit, m_simulator->profile().name);
    m_session->markClean(); // the first run's target and request are where an untitled session starts

    m_simulatorNotice->showStarted(QString::fromLatin1(kFirstRunProfile), started.note);
    return true;
}

void MainWindow::updateRegisterProfile()
{
    // The built-in simulator's profile names the simulator's registers, no other device's (issue
    // 26 item 15: "Profile: rosrao-gamma" stayed after connecting to another device). Back on the
    // simulator, its names come back.
    const LinkUrl &url = m_controller->url();
    const LinkUrl &simulator = m_simulator->started().url;
    const bool onSimulator = m_simulator->isRunning() && url.kind == simulator.kind && url.host == simulator.host
        && url.port == simulator.port;
    const UnitProfile *unit = onSimulator ? m_simulator->profile().unit(1) : nullptr;
    if (unit)
        m_registers->setProfile(*unit, m_simulator->profile().name);
    else
        m_registers->clearProfile();
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    m_session->addMenuActions(file);
    file->addSeparator();
    file->addAction(m_traffic->saveAction());
    file->addSeparator();
    // Closing the window (not quitting the application outright) asks about unsaved changes.
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);

    m_composer->addMenu(menuBar());

    m_sessionTools->addMenu(menuBar());

    // "Watches" has no letter the window does not use already (nor the Indonesian words).
    QMenu *watches = menuBar()->addMenu(tr("Wor&kspace"));
    for (QAction *action : m_workspace->menuActions()) {
        if (!action) {
            watches->addSeparator();
            continue;
        }
        watches->addAction(action);
        // What the menu does happens in the Watches tab: it comes forward.
        connect(action, &QAction::triggered, this, [this] { m_tabs->setCurrentWidget(m_workspace); });
    }

    QMenu *view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_trafficDock->toggleViewAction());
    view->addAction(m_registersDock->toggleViewAction());
    view->addAction(m_analysisDock->toggleViewAction());
    view->addAction(m_simulatorDock->toggleViewAction());
    QAction *find = view->addAction(tr("&Find in traffic"), this, [this] {
        m_trafficDock->show();
        m_trafficDock->raise();
        m_traffic->focusSearch();
    });
    find->setShortcut(QKeySequence::Find);
    // The list's own Ctrl+F would make the window's ambiguous inside the dock, and Qt then fires
    // neither: the window's action serves the dock too.
    for (QShortcut *shortcut : m_traffic->findChildren<QShortcut *>()) {
        if (shortcut->key() == QKeySequence(QKeySequence::Find))
            shortcut->setEnabled(false);
    }
    QAction *nextDock = view->addAction(tr("&Next dock"), this, &MainWindow::focusNextDock);
    nextDock->setObjectName(QStringLiteral("nextDockAction"));
    nextDock->setShortcut(QKeySequence(Qt::Key_F6));

    m_tools = new ToolsMenu(this, m_controller, m_connectionBar, m_traffic, m_recording);
    m_tools->addMenus(menuBar());
    // "Add as watches": the units a scan found become watch windows of the workspace.
    connect(m_tools, &ToolsMenu::watchesFound, this, &MainWindow::addWatchesFromScan);
}

ScanDialog *MainWindow::scanDialog()
{
    return m_tools->scanDialog();
}

// The units a scan found become watch windows of the workspace, each name made unique in the
// session ("unit 3" again becomes "unit 3 (2)").
void MainWindow::addWatchesFromScan(const QList<WatchDefinition> &found)
{
    QStringList taken;
    for (const WatchDefinition &w : m_workspace->watches().watches)
        taken.append(w.name);
    for (WatchDefinition watch : found) {
        const QString base = watch.name;
        for (int n = 2; taken.contains(watch.name); ++n)
            watch.name = QStringLiteral("%1 (%2)").arg(base).arg(n);
        taken.append(watch.name);
        m_workspace->addWatch(watch);
    }
    m_tabs->setCurrentWidget(m_workspace);
    statusBar()->showMessage(tr("%n watch(es) added from the scan: Workspace > Start all (F5) polls them.", nullptr, int(found.size())),
                             10000);
}

} // namespace mbscope
