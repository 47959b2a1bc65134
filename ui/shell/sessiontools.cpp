#include "sessiontools.h"

#include "link/linkcontroller.h"
#include "session/plancontroller.h"
#include "session/planpanel.h"
#include "session/replaycontroller.h"
#include "session/replaypanel.h"
#include "session/replayserver.h"
#include "session/sessioncontroller.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"

#include <QtCore/QFileInfo>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QMainWindow>
#include <QtWidgets/QMenu>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QStatusBar>

namespace mbscope {

SessionTools::SessionTools(QMainWindow *window, LinkController *link, SessionController *session, TrafficMonitor *traffic,
                           QDockWidget *besideDock)
    : QObject(window)
    , m_window(window)
    , m_link(link)
    , m_session(session)
    , m_traffic(traffic)
    , m_replay(new ReplayController(link, this))
    , m_plan(new PlanController(link, this))
{
    m_replayPanel = new ReplayPanel(m_replay, window);
    m_planPanel = new PlanPanel(
        m_plan,
        [session] {
            SessionDocument document = session->currentDocument();
            if (document.name.isEmpty() && !session->filePath().isEmpty())
                document.name = QFileInfo(session->filePath()).completeBaseName();
            return document;
        },
        window);
    // A session opened (or a new one) changes the title: the plan panel says what it now holds.
    connect(session, &SessionController::titleChanged, m_planPanel, &PlanPanel::showDocumentHint);
    m_replayDock = new QDockWidget(tr("Replay"), window);
    m_replayDock->setObjectName(QStringLiteral("replayDock"));
    m_replayDock->setWidget(m_replayPanel);
    m_planDock = new QDockWidget(tr("Test plan"), window);
    m_planDock->setObjectName(QStringLiteral("planDock"));
    m_planDock->setWidget(m_planPanel);
    window->addDockWidget(Qt::BottomDockWidgetArea, m_replayDock);
    window->addDockWidget(Qt::BottomDockWidgetArea, m_planDock);
    if (besideDock) {
        window->tabifyDockWidget(besideDock, m_replayDock);
        window->tabifyDockWidget(besideDock, m_planDock);
        besideDock->raise();
    }

    // An analysed capture replaces what the traffic list shows; its Link column names the file.
    connect(m_replay, &ReplayController::captureAnalysed, this, [this](const QString &title, const QList<Transaction> &transactions) {
        m_traffic->clear();
        m_traffic->model()->setCurrentLink(title);
        m_traffic->appendRecordedTransactions(transactions);
        m_traffic->model()->setCurrentLink(m_link->isConnected() ? m_link->url().toString() : QString());
        status(m_replay->sourceSummary());
    });
    // What a replay or a test plan sends and gets is traffic with the device like any other: listed
    // and counted in the status bar.
    connect(m_replay, &ReplayController::transactionsReplayed, this, [this](const QList<Transaction> &transactions) {
        m_traffic->model()->setCurrentLink(m_link->url().toString());
        m_traffic->appendTransactions(transactions);
        m_link->countTransactions(transactions);
    });
    connect(m_plan, &PlanController::framesLogged, this, [this](const QList<TrafficFrame> &frames, const QString &url) {
        m_traffic->appendLinkFrames(frames, url);
        m_link->countFrames(frames);
    });
    connect(m_replay, &ReplayController::sourceFailed, this, &SessionTools::status);
    connect(m_replay, &ReplayController::replayFinished, this, &SessionTools::status);
    connect(m_plan, &PlanController::finished, this, [this](const QString &summary) { status(summary); });
}

QMenu *SessionTools::addMenu(QMenuBar *menuBar)
{
    QMenu *menu = menuBar->addMenu(tr("&Session"));
    menu->addAction(tr("&Open capture for analysis and replay…"), this, [this] {
        showDock(m_replayDock);
        m_replayPanel->chooseAndOpen();
    });
    QAction *sessionCapture = menu->addAction(tr("&Analyse the session's capture"), this, [this] {
        showDock(m_replayDock);
        m_replayPanel->open(m_session->filePath());
    });
    menu->addSeparator();
    QAction *replay = menu->addAction(tr("&Replay to the target"), this, [this] {
        showDock(m_replayDock);
        m_replayPanel->replay();
    });
    QAction *stopReplay = menu->addAction(tr("S&top the replay"), m_replay, &ReplayController::stopReplay);
    QAction *serve = menu->addAction(tr("Ser&ve the recorded answers"), this, [this] {
        showDock(m_replayDock);
        m_replayPanel->toggleServing();
    });
    serve->setCheckable(true);
    menu->addSeparator();
    QAction *run = menu->addAction(tr("Run the test &plan"), this, [this] {
        showDock(m_planDock);
        m_planPanel->run();
    });
    run->setShortcut(QKeySequence(Qt::Key_F9));
    QAction *stopPlan = menu->addAction(tr("Stop the test p&lan"), m_plan, &PlanController::stop);
    QAction *junit = menu->addAction(tr("E&xport test results as JUnit XML…"), m_planPanel, &PlanPanel::exportJUnit);
    menu->addSeparator();
    menu->addAction(m_replayDock->toggleViewAction());
    menu->addAction(m_planDock->toggleViewAction());

    connect(menu, &QMenu::aboutToShow, this, [=, this] {
        sessionCapture->setEnabled(!m_session->filePath().isEmpty() && m_session->currentDocument().capture.has_value());
        replay->setEnabled(m_replay->hasSource() && !m_replay->isReplaying());
        stopReplay->setEnabled(m_replay->isReplaying());
        serve->setEnabled(m_replay->hasSource() || m_replay->server()->isServing());
        serve->setChecked(m_replay->server()->isServing());
        run->setEnabled(!m_plan->isRunning());
        stopPlan->setEnabled(m_plan->isRunning());
        junit->setEnabled(!m_plan->isRunning() && m_plan->lastResult().has_value());
    });
    return menu;
}

void SessionTools::showDock(QDockWidget *dock)
{
    dock->show();
    dock->raise();
}

void SessionTools::status(const QString &text)
{
    m_window->statusBar()->showMessage(text.section(QLatin1Char('\n'), 0, 0), 10000);
}

} // namespace mbscope
