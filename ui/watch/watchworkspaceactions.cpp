// WatchWorkspace's actions (the Workspace menu, a watch window's context menu, their keys) and
// what enables them; the rest of the class is in watchworkspace.cpp.
#include "watchworkspace.h"

#include "watchlogcontrol.h"
#include "watchprofiledialog.h"
#include "watchwindow.h"

#include <QtGui/QAction>
#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMdiArea>
#include <QtWidgets/QMenu>
#include <QtWidgets/QTableView>

namespace mbscope {

void WatchWorkspace::createActions()
{
    auto make = [this](const QString &text, const QKeySequence &keys, auto slot) {
        auto *action = new QAction(text, this);
        action->setShortcut(keys);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    m_newAction = make(tr("&New watch\u2026"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N), &WatchWorkspace::newWatch);
    m_newAction->setObjectName(QStringLiteral("newWatchAction"));
    m_newAction->setIconText(tr("New watch"));
    m_fromRequestAction = make(tr("New watch from the composer's &request"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R), [this] {
        QString error;
        if (!addFromRequest(&error))
            Q_EMIT message(error);
    });
    m_fromRequestAction->setIconText(tr("From request"));
    m_fromProfileAction = make(tr("New watches from a device &profile\u2026"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P), [this] {
        WatchProfileDialog dialog(this);
        dialog.setTarget(m_targetSource ? m_targetSource() : QString());
        if (dialog.exec() != QDialog::Accepted)
            return;
        QString error;
        const int made = addFromProfile(dialog.profile(), dialog.unit(), dialog.target(), dialog.intervalMs(), &error);
        Q_EMIT message(made ? tr("%n watch(es) made from %1", nullptr, made).arg(dialog.profile()) : error);
    });
    m_fromProfileAction->setIconText(tr("From profile"));
    m_editAction = make(tr("&Edit watch\u2026"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E), &WatchWorkspace::editCurrent);
    m_duplicateAction = make(tr("&Duplicate watch"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D), [this] { duplicateWatch(currentIndex()); });
    m_closeAction = make(tr("&Close watch"), QKeySequence(Qt::CTRL | Qt::Key_W), [this] { removeWatch(currentIndex()); });
    m_moveLeftAction = make(tr("Move watch le&ft"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_PageUp), [this] { moveWatch(currentIndex(), -1); });
    m_moveRightAction = make(tr("Move watch r&ight"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_PageDown), [this] { moveWatch(currentIndex(), 1); });
    m_startAction = make(tr("&Start all"), QKeySequence(Qt::Key_F5), &WatchWorkspace::startAll);
    m_startAction->setObjectName(QStringLiteral("startWatchesAction"));
    m_stopAction = make(tr("S&top all"), QKeySequence(Qt::SHIFT | Qt::Key_F5), &WatchWorkspace::stopAll);
    m_stopAction->setObjectName(QStringLiteral("stopWatchesAction"));
    m_nextAction = make(tr("Ne&xt watch"), QKeySequence(Qt::CTRL | Qt::Key_F6), [this] {
        m_area->activateNextSubWindow();
        if (WatchWindow *w = window(currentIndex()))
            w->view()->setFocus(Qt::ShortcutFocusReason);
    });
    m_nextAction->setObjectName(QStringLiteral("nextWatchAction"));
    m_writeAction = make(tr("&Write value\u2026"), QKeySequence(Qt::CTRL | Qt::Key_E), &WatchWorkspace::writeCurrent);
    m_writeAction->setObjectName(QStringLiteral("writeWatchValueAction"));
    m_copyAction = make(tr("C&opy values"), QKeySequence(QKeySequence::Copy), [this] {
        if (WatchWindow *w = window(currentIndex()))
            QGuiApplication::clipboard()->setText(w->selectionText());
    });
    m_pollThisAction = new QAction(tr("Poll t&his watch"), this);
    m_pollThisAction->setObjectName(QStringLiteral("pollThisWatchAction"));
    m_pollThisAction->setCheckable(true);
    m_pollThisAction->setIconText(tr("Poll this watch"));
    m_pollThisAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F5));
    m_pollThisAction->setToolTip(tr("Start or stop the current watch alone; the others go on as they are"));
    // triggered, not toggled: updateActions() sets the check to what the runner does.
    connect(m_pollThisAction, &QAction::triggered, this, [this](bool checked) {
        const int index = currentIndex();
        m_pollThisAction->setChecked(!checked); // the result, not the click, decides (updatePolling)
        if (checked)
            startWatch(index);
        else
            stopWatch(index);
    });
    m_trendAction = make(tr("Trend this &value"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G), &WatchWorkspace::trendCurrent);
    m_trendAction->setObjectName(QStringLiteral("trendWatchValueAction"));
    m_trendAction->setToolTip(tr("Plot the chosen value of this watch in Analysis \u2192 Register trends as it polls"));
    // What acts on the current watch (close, write, copy...) answers its keys only while the
    // focus is in the workspace: Ctrl+W in the composer must not close a watch out of sight.
    for (QAction *action : {m_editAction, m_duplicateAction, m_closeAction, m_moveLeftAction, m_moveRightAction,
                            m_writeAction, m_copyAction, m_pollThisAction, m_trendAction}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        addAction(action);
    }
    m_tabbedAction = new QAction(tr("T&abbed windows"), this);
    m_tabbedAction->setIconText(tr("Tabbed"));
    m_tabbedAction->setCheckable(true);
    m_tabbedAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    m_tabbedAction->setToolTip(tr("Watches as tabs, or as windows tiled side by side"));
    connect(m_tabbedAction, &QAction::toggled, this, &WatchWorkspace::setTabbed);
}

QList<QAction *> WatchWorkspace::menuActions() const
{
    return {m_newAction,   m_fromRequestAction, m_fromProfileAction, m_editAction,      m_duplicateAction,
            nullptr,       m_startAction,       m_stopAction,        m_pollThisAction,  nullptr,           m_nextAction,
            m_moveLeftAction, m_moveRightAction, m_closeAction,      nullptr,           m_writeAction,
            m_copyAction,  m_trendAction, nullptr,             m_tabbedAction,      m_log->logAction(), m_log->settingsAction()};
}

QList<QAction *> WatchWorkspace::windowMenuActions() const
{
    return {m_pollThisAction, nullptr, m_trendAction, m_writeAction, m_copyAction, nullptr, m_editAction, m_closeAction};
}

void WatchWorkspace::showWindowMenu(int index, const QPoint &globalPos)
{
    setCurrentIndex(index);
    updateActions();
    QMenu menu(this);
    for (QAction *action : windowMenuActions()) {
        if (action)
            menu.addAction(action);
        else
            menu.addSeparator();
    }
    menu.exec(globalPos);
}

void WatchWorkspace::updateActions()
{
    const bool any = count() > 0;
    const bool running = isRunning();
    m_hint->setVisible(!any);
    m_area->setVisible(any);
    for (QAction *action : {m_editAction, m_duplicateAction, m_closeAction, m_nextAction, m_writeAction, m_copyAction,
                            m_moveLeftAction, m_moveRightAction})
        action->setEnabled(any);
    m_startAction->setEnabled(any);
    m_stopAction->setEnabled(running);
    const int current = currentIndex();
    m_pollThisAction->setEnabled(any);
    m_pollThisAction->setChecked(isPolling(current));
    WatchWindow *w = window(current);
    m_trendAction->setEnabled(w && w->view()->currentIndex().isValid());
}

} // namespace mbscope
