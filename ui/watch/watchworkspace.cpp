#include "watchworkspace.h"

#include <QtCore/QTimer>

#include "watchdialog.h"
#include "watchlogcontrol.h"
#include "watchtablemodel.h"
#include "watchwindow.h"

#include "fleet/watchrunner.h"
#include "profile/profileloader.h"

#include <QtGui/QAction>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMdiArea>
#include <QtWidgets/QMdiSubWindow>
#include <QtWidgets/QMenu>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace mbscope {

WatchWorkspace::WatchWorkspace(QWidget *parent)
    : QWidget(parent)
    , m_area(new QMdiArea(this))
    , m_hint(new QLabel(this))
{
    setObjectName(QStringLiteral("watchWorkspace"));
    m_area->setObjectName(QStringLiteral("watchArea"));
    m_area->setDocumentMode(true);
    m_area->setTabsClosable(false);
    m_area->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    m_area->setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    m_log = new WatchLogControl(this);
    connect(m_log, &WatchLogControl::message, this, &WatchWorkspace::message);
    connect(m_log, &WatchLogControl::settingsChanged, this, [this] {
        m_watches.log = m_log->settings();
        Q_EMIT changed();
    });
    createActions();

    auto *bar = new QToolBar(this);
    bar->setObjectName(QStringLiteral("watchToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addAction(m_newAction);
    bar->addAction(m_fromRequestAction);
    bar->addAction(m_fromProfileAction);
    bar->addSeparator();
    bar->addAction(m_startAction);
    bar->addAction(m_stopAction);
    bar->addAction(m_pollThisAction);
    bar->addSeparator();
    bar->addAction(m_tabbedAction);
    bar->addAction(m_log->logAction());

    m_hint->setObjectName(QStringLiteral("watchHint"));
    m_hint->setWordWrap(true);
    m_hint->setAlignment(Qt::AlignCenter);
    // The hint takes the room there is: its wrapped height must not raise the main area's minimum.
    m_hint->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    m_hint->setText(tr("No watches yet. A watch polls a block of a device at its own interval and shows its values "
                       "with names, units and rule colours. Make one with Workspace \u2192 New watch (%1), from the "
                       "composer's read request (%2) or from a device profile (%3); Start all (%4) polls them together.")
                        .arg(m_newAction->shortcut().toString(QKeySequence::NativeText),
                             m_fromRequestAction->shortcut().toString(QKeySequence::NativeText),
                             m_fromProfileAction->shortcut().toString(QKeySequence::NativeText),
                             m_startAction->shortcut().toString(QKeySequence::NativeText)));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(bar);
    layout->addWidget(m_hint);
    layout->addWidget(m_area, 1);
    setTabbed(true);
    connect(m_area, &QMdiArea::subWindowActivated, this, &WatchWorkspace::updateActions);
    updateActions();
}

WatchWorkspace::~WatchWorkspace()
{
    delete m_runner;
    m_runner = nullptr;
}

void WatchWorkspace::setTrafficLog(TrafficLog *log)
{
    m_trafficLog = log;
    if (m_runner)
        m_runner->setTrafficLog(log);
}

WatchWindow *WatchWorkspace::window(int index) const
{
    return index >= 0 && index < m_windows.size() ? m_windows.at(index) : nullptr;
}

int WatchWorkspace::currentIndex() const
{
    QMdiSubWindow *sub = m_area->currentSubWindow();
    if (!sub)
        sub = m_area->activeSubWindow();
    for (int i = 0; i < m_windows.size(); ++i) {
        if (sub && sub->widget() == m_windows.at(i))
            return i;
    }
    return m_windows.isEmpty() ? -1 : 0;
}

void WatchWorkspace::setCurrentIndex(int index)
{
    if (WatchWindow *w = window(index)) {
        if (auto *sub = qobject_cast<QMdiSubWindow *>(w->parentWidget()))
            m_area->setActiveSubWindow(sub);
    }
}

bool WatchWorkspace::isTabbed() const
{
    return m_area->viewMode() == QMdiArea::TabbedView;
}

void WatchWorkspace::setTabbed(bool tabbed)
{
    m_area->setViewMode(tabbed ? QMdiArea::TabbedView : QMdiArea::SubWindowView);
    if (!tabbed) {
        for (QMdiSubWindow *sub : m_area->subWindowList())
            sub->showNormal();
        m_area->tileSubWindows();
    }
    if (m_tabbedAction->isChecked() != tabbed)
        m_tabbedAction->setChecked(tabbed);
}

QStringList WatchWorkspace::namesExcept(int index) const
{
    QStringList names;
    for (int i = 0; i < m_watches.watches.size(); ++i) {
        if (i != index)
            names << m_watches.watches.at(i).name;
    }
    return names;
}

QMdiSubWindow *WatchWorkspace::addWindow(int index)
{
    auto *w = new WatchWindow;
    w->model()->setDefinition(m_watches.watches.at(index));
    connect(w, &WatchWindow::writeRequested, this, [this, w](int row) { requestWrite(int(m_windows.indexOf(w)), row); });
    connect(w, &WatchWindow::contextMenuRequested, this,
            [this, w](int, const QPoint &globalPos) { showWindowMenu(int(m_windows.indexOf(w)), globalPos); });
    connect(w->view()->selectionModel(), &QItemSelectionModel::currentChanged, this, &WatchWorkspace::updateActions);
    m_windows.insert(index, w);
    QMdiSubWindow *sub = m_area->addSubWindow(w);
    sub->setAttribute(Qt::WA_DeleteOnClose, false);
    // No application icon in every tab: a see-through pixel (a bare QPixmap(1, 1) is not filled
    // and drew a stray dot before each tab's name).
    QPixmap none(1, 1);
    none.fill(Qt::transparent);
    sub->setWindowIcon(QIcon(none));
    // The window's own keys (Ctrl+W, Ctrl+F4 in its system menu) would close the window and
    // leave the watch: Close watch does both, and closing by the title bar's button goes there.
    if (QMenu *menu = sub->systemMenu()) {
        for (QAction *action : menu->actions())
            action->setShortcut(QKeySequence());
    }
    sub->installEventFilter(this);
    sub->show();
    updateWindowTitle(index);
    if (!isTabbed())
        m_area->tileSubWindows();
    return sub;
}

bool WatchWorkspace::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Close) {
        if (auto *sub = qobject_cast<QMdiSubWindow *>(watched)) {
            const int index = int(m_windows.indexOf(qobject_cast<WatchWindow *>(sub->widget())));
            if (index >= 0) {
                event->ignore();
                // Not from inside the window's own close handling: it is deleted by the removal.
                QMetaObject::invokeMethod(this, [this, sub] {
                    removeWatch(int(m_windows.indexOf(qobject_cast<WatchWindow *>(sub->widget()))));
                }, Qt::QueuedConnection);
                return true;
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

void WatchWorkspace::updateWindowTitle(int index)
{
    const WatchDefinition &watch = m_watches.watches.at(index);
    if (WatchWindow *w = window(index)) {
        // While others poll, a watch stopped on its own says so; "off" is the saved "Poll this watch".
        const bool stopped = isRunning() && watch.enabled && !isPolling(index);
        w->setWindowTitle(!watch.enabled ? tr("%1 (off)").arg(watch.name) : stopped ? tr("%1 (stopped)").arg(watch.name) : watch.name);
        w->setPolling(isPolling(index));
        w->setToolTip(tr("%1, unit %2, every %3 ms").arg(watch.target).arg(watch.unit).arg(watch.intervalMs));
    }
}

void WatchWorkspace::rebuildWindows()
{
    const int current = currentIndex();
    for (QMdiSubWindow *sub : m_area->subWindowList()) {
        m_area->removeSubWindow(sub);
        sub->deleteLater();
    }
    m_windows.clear();
    for (int i = 0; i < m_watches.watches.size(); ++i)
        addWindow(i);
    if (!isTabbed())
        m_area->tileSubWindows();
    setCurrentIndex(qMin(current, count() - 1));
    updateActions();
}

void WatchWorkspace::setWatches(const SessionWatches &watches)
{
    stopAll();
    m_watches = watches;
    m_log->setSettings(watches.log.value_or(WatchLogSettings()));
    rebuildWindows();
    // A session opens with its first watch in front (the MDI area left the last one added there);
    // a hidden area does not take the choice, so it is made again when the area is shown.
    if (count() > 0) {
        setCurrentIndex(0);
        m_frontWhenShown = isVisible() ? -1 : 0;
    }
    Q_EMIT definitionsChanged();
}

void WatchWorkspace::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_frontWhenShown >= 0) {
        const int index = m_frontWhenShown;
        m_frontWhenShown = -1;
        QTimer::singleShot(0, this, [this, index] { setCurrentIndex(index); });
    }
}

void WatchWorkspace::watchesEdited()
{
    if (m_runner && m_runner->isRunning()) {
        // Edited definitions: their counters start anew.
        m_carrying = false;
        m_carried.clear();
        m_runner->setWatches(runnerWatches()); // the CSV files follow the watches (and their indices)
    }
    updateActions();
    Q_EMIT definitionsChanged();
    Q_EMIT changed();
}

int WatchWorkspace::addWatch(const WatchDefinition &watch)
{
    m_watches.watches.append(watch);
    if (isRunning() && watch.enabled)
        m_polled.insert(watch.name); // a watch made while the others poll polls too
    const int index = count() - 1;
    addWindow(index);
    setCurrentIndex(index);
    watchesEdited();
    return index;
}

void WatchWorkspace::replaceWatch(int index, const WatchDefinition &watch)
{
    if (index < 0 || index >= count())
        return;
    const WatchDefinition &before = m_watches.watches.at(index);
    if (before.name != watch.name && m_polled.remove(before.name))
        m_polled.insert(watch.name);
    // "Poll this watch" ticked in the dialog while the others poll: it polls too.
    if (isRunning() && !before.enabled && watch.enabled)
        m_polled.insert(watch.name);
    m_watches.watches[index] = watch;
    m_windows.at(index)->model()->setDefinition(watch);
    updateWindowTitle(index);
    watchesEdited();
}

void WatchWorkspace::removeWatch(int index)
{
    if (index < 0 || index >= count())
        return;
    m_polled.remove(m_watches.watches.at(index).name);
    m_watches.watches.removeAt(index);
    WatchWindow *w = m_windows.takeAt(index);
    if (auto *sub = qobject_cast<QMdiSubWindow *>(w->parentWidget())) {
        m_area->removeSubWindow(sub);
        sub->deleteLater();
    }
    if (!isTabbed())
        m_area->tileSubWindows();
    watchesEdited();
}

void WatchWorkspace::moveWatch(int index, int delta)
{
    const int to = index + delta;
    if (index < 0 || index >= count() || to < 0 || to >= count())
        return;
    m_watches.watches.move(index, to);
    rebuildWindows();
    setCurrentIndex(to);
    watchesEdited();
}

void WatchWorkspace::duplicateWatch(int index)
{
    if (index < 0 || index >= count())
        return;
    WatchDefinition copy = m_watches.watches.at(index);
    copy.name = WatchFactory::uniqueName(copy.name, namesExcept());
    addWatch(copy);
}

bool WatchWorkspace::runDialog(WatchDialog &dialog)
{
    if (m_dialogRunner)
        return m_dialogRunner(dialog);
    return dialog.exec() == QDialog::Accepted;
}

void WatchWorkspace::newWatch()
{
    WatchDialog dialog(this);
    WatchDefinition watch;
    watch.name = WatchFactory::uniqueName(tr("watch"), namesExcept());
    watch.target = m_targetSource ? m_targetSource() : QString();
    watch.quantity = 10;
    dialog.setWatch(watch);
    dialog.setTakenNames(namesExcept());
    if (!runDialog(dialog))
        return;
    QStringList problems;
    const WatchDefinition made = dialog.watch(&problems);
    if (problems.isEmpty())
        addWatch(made);
}

void WatchWorkspace::editCurrent()
{
    const int index = currentIndex();
    if (index < 0)
        return;
    WatchDialog dialog(this);
    dialog.setWatch(m_watches.watches.at(index));
    dialog.setTakenNames(namesExcept(index));
    if (!runDialog(dialog))
        return;
    QStringList problems;
    const WatchDefinition edited = dialog.watch(&problems);
    if (problems.isEmpty())
        replaceWatch(index, edited);
}

void WatchWorkspace::setSessionPathSource(std::function<QString()> source)
{
    m_log->setSessionPathSource(std::move(source));
}

bool WatchWorkspace::addFromRequest(QString *error)
{
    if (!m_requestSource) {
        *error = tr("No composer to take a request from.");
        return false;
    }
    const WatchFromRequest made = m_requestSource(namesExcept());
    if (!made.error.isEmpty()) {
        *error = made.error;
        return false;
    }
    addWatch(made.watch);
    Q_EMIT message(tr("Watch '%1' made from the composer's request").arg(made.watch.name));
    return true;
}

int WatchWorkspace::addFromProfile(const QString &profileName, int unit, const QString &target, int intervalMs, QString *error)
{
    const ProfileLoadResult loaded = ProfileLoader::load(profileName);
    if (!loaded.ok) {
        *error = tr("The profile %1 was not loaded: %2").arg(profileName, loaded.errorText());
        return 0;
    }
    const QList<WatchDefinition> made = WatchFactory::fromProfile(loaded.profile, quint8(unit), target, intervalMs, namesExcept());
    if (made.isEmpty()) {
        *error = tr("The profile %1 has no unit %2 with registers or bits to watch").arg(profileName).arg(unit);
        return 0;
    }
    // The device's least gap between requests (limits.minGapMs) and its warm-up after connecting
    // (limits.warmUpMs), with some to spare (DeviceLimits::clientGap), become its link's gapMs and
    // warmUpMs unless those already wait longer: the watches never ask it too soon.
    const int gap = int(loaded.profile.limits.clientGap().count());
    const int warmUp = int(loaded.profile.limits.clientWarmUp().count());
    if (gap > 0 || warmUp > 0) {
        auto link = std::find_if(m_watches.links.begin(), m_watches.links.end(),
                                 [&](const WatchLinkSettings &l) { return l.target == target; });
        if (link == m_watches.links.end())
            link = m_watches.links.insert(m_watches.links.end(), WatchLinkSettings{.target = target});
        link->gapMs = qMax(link->gapMs, gap);
        link->warmUpMs = qMax(link->warmUpMs, warmUp);
    }
    for (const WatchDefinition &watch : made)
        addWatch(watch);
    return int(made.size());
}

void WatchWorkspace::startAll()
{
    if (m_watches.watches.isEmpty()) {
        Q_EMIT message(tr("No watches to start: make one first (Workspace \u2192 New watch)"));
        return;
    }
    m_polled.clear();
    for (const WatchDefinition &watch : std::as_const(m_watches.watches)) {
        if (watch.enabled)
            m_polled.insert(watch.name);
    }
    startRunner();
    Q_EMIT message(tr("Polling %n watch(es)", nullptr, int(m_polled.size())));
}

void WatchWorkspace::startRunner()
{
    m_carrying = false;
    m_carried.clear();
    m_lastCounters.clear();
    delete m_runner;
    m_runner = new WatchRunner(runnerWatches(), this);
    m_runner->setFramesPublished(true);
    connect(m_runner, &WatchRunner::framesLogged, this, &WatchWorkspace::framesLogged);
    if (m_trafficLog)
        m_runner->setTrafficLog(m_trafficLog);
    connect(m_runner, &WatchRunner::sampled, this, &WatchWorkspace::onSampled);
    connect(m_runner, &WatchRunner::ruleChanged, this, &WatchWorkspace::onRule);
    connect(m_runner, &WatchRunner::linkStateChanged, this, &WatchWorkspace::onLinkState);
    connect(m_runner, &WatchRunner::writeFinished, this,
            [this](quint64, int, quint16, bool ok, const QString &text) {
                Q_EMIT message(ok ? tr("Written: %1").arg(text) : tr("Not written: %1").arg(text));
            });
    m_log->start(m_runner);
    m_runner->start();
    updatePolling();
    Q_EMIT runningChanged(true);
}

void WatchWorkspace::stopAll()
{
    if (!m_runner || !m_runner->isRunning())
        return;
    m_runner->stop();
    m_polled.clear();
    m_log->watchesStopped();
    updatePolling();
    Q_EMIT runningChanged(false);
    Q_EMIT message(tr("Watches stopped"));
}

bool WatchWorkspace::isRunning() const
{
    return m_runner && m_runner->isRunning();
}

bool WatchWorkspace::isPolling(int index) const
{
    return isRunning() && index >= 0 && index < count() && m_watches.watches.at(index).enabled
        && m_polled.contains(m_watches.watches.at(index).name);
}

SessionWatches WatchWorkspace::runnerWatches() const
{
    SessionWatches polled = m_watches;
    for (WatchDefinition &watch : polled.watches)
        watch.enabled = watch.enabled && m_polled.contains(watch.name);
    return polled;
}

void WatchWorkspace::startWatch(int index)
{
    if (index < 0 || index >= count() || isPolling(index))
        return;
    WatchDefinition &watch = m_watches.watches[index];
    if (!watch.enabled) {
        watch.enabled = true; // asked for by name: its "Poll this watch" is ticked (saved in the session)
        m_windows.at(index)->model()->setDefinition(watch);
        Q_EMIT changed();
    }
    if (isRunning()) {
        // The runner takes the new set: its links open again and its counters start anew, so
        // the windows carry on what they counted (this watch's too, from before it stopped).
        m_carrying = true;
        m_polled.insert(watch.name);
        m_runner->setWatches(runnerWatches());
        updatePolling();
    } else {
        m_polled.insert(watch.name);
        startRunner();
    }
    Q_EMIT message(tr("Polling watch '%1'").arg(watch.name));
}

void WatchWorkspace::stopWatch(int index)
{
    if (!isPolling(index))
        return;
    const QString name = m_watches.watches.at(index).name;
    m_polled.remove(name);
    if (m_polled.isEmpty()) {
        stopAll();
    } else {
        m_carrying = true;
        m_runner->setWatches(runnerWatches());
        updatePolling();
    }
    Q_EMIT message(tr("Watch '%1' stopped").arg(name));
}

WatchCounters WatchWorkspace::shownCounters(const WatchCounters &counters)
{
    const QString &name = counters.watchName;
    if (m_carrying) {
        const auto last = m_lastCounters.constFind(name);
        // Each batch of one run counts more polls than the one before: fewer is a new run.
        if (last != m_lastCounters.cend() && counters.polls <= last->polls)
            m_carried.insert(name, WatchWindow::carried(m_carried.value(name), *last));
    }
    m_lastCounters.insert(name, counters);
    const auto carried = m_carried.constFind(name);
    return carried == m_carried.cend() ? counters : WatchWindow::carried(*carried, counters);
}

void WatchWorkspace::updatePolling()
{
    for (int i = 0; i < count(); ++i)
        updateWindowTitle(i);
    updateActions();
}

void WatchWorkspace::trendCurrent()
{
    const int index = currentIndex();
    WatchWindow *w = window(index);
    if (!w || !w->view()->currentIndex().isValid()) {
        Q_EMIT message(tr("Choose a value in a watch's table to trend"));
        return;
    }
    const int row = w->view()->currentIndex().row();
    const WatchPointValue &value = w->model()->valueAt(row);
    Q_EMIT trendRequested(m_watches.watches.at(index).name, value.address, value.name);
}

void WatchWorkspace::onSampled(const QList<WatchSample> &samples, const QList<WatchCounters> &counters)
{
    for (const WatchSample &sample : samples) {
        WatchWindow *w = window(sample.watch);
        // A batch posted before the watches changed: its indices are the old ones.
        if (!w || m_watches.watches.at(sample.watch).name != sample.watchName)
            continue;
        w->model()->applySample(sample);
    }
    for (const WatchCounters &c : counters) {
        if (WatchWindow *w = window(c.watch); w && m_watches.watches.at(c.watch).name == c.watchName) {
            w->setCounters(shownCounters(c));
        }
    }
    Q_EMIT sampled(samples);
}

void WatchWorkspace::onRule(const WatchRuleEvent &event)
{
    WatchWindow *w = window(event.watch);
    if (!w || m_watches.watches.at(event.watch).name != event.watchName)
        return;
    w->model()->applyRule(event);
    if (event.fired)
        Q_EMIT message(QStringLiteral("%1: %2").arg(event.watchName, event.message));
}

void WatchWorkspace::onLinkState(const WatchLinkState &state)
{
    for (int i = 0; i < count(); ++i) {
        if (m_watches.watches.at(i).target == state.target)
            m_windows.at(i)->setLinkState(state);
    }
}

} // namespace mbscope
