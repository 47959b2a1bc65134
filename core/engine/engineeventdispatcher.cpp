#include "engineeventdispatcher.h"

#include "transport/directsocketnotifier.h"
#include "transport/monotonicclock.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QEvent>
#include <QtCore/QMetaMethod>
#include <QtCore/QSocketNotifier>
#include <QtCore/QVarLengthArray>

#include <algorithm>
#include <cerrno>
#include <ctime>

#include <sys/eventfd.h>
#include <unistd.h>

namespace mbscope {

namespace {

constexpr qint64 kNsPerMs = 1000000;

// What poll() reports that wakes each kind of notifier (as Qt's Unix dispatcher does: an error
// or a hang-up wakes them all, so that the owner finds out by reading or writing).
short wakingEvents(QSocketNotifier::Type type)
{
    switch (type) {
    case QSocketNotifier::Read:
        return POLLIN | POLLHUP | POLLERR;
    case QSocketNotifier::Write:
        return POLLOUT | POLLHUP | POLLERR;
    case QSocketNotifier::Exception:
        return POLLPRI | POLLHUP | POLLERR;
    }
    return POLLHUP | POLLERR;
}

short polledEvents(QSocketNotifier::Type type)
{
    switch (type) {
    case QSocketNotifier::Read:
        return POLLIN;
    case QSocketNotifier::Write:
        return POLLOUT;
    case QSocketNotifier::Exception:
        return POLLPRI;
    }
    return 0;
}

} // namespace

EngineEventDispatcher::EngineEventDispatcher(QObject *parent)
    : QAbstractEventDispatcher(parent)
    , m_wakeFd(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC))
{
    if (m_wakeFd < 0)
        qFatal("mbscope: the engine's event dispatcher cannot make its wake-up eventfd (errno %d)", errno);
}

EngineEventDispatcher::~EngineEventDispatcher()
{
    if (m_wakeFd >= 0)
        ::close(m_wakeFd);
}

bool EngineEventDispatcher::processEvents(QEventLoop::ProcessEventsFlags flags)
{
    m_interrupted.store(false, std::memory_order_relaxed);
    const bool observed = m_turnObservers.load(std::memory_order_relaxed) > 0;
    if (observed)
        Q_EMIT awake();
    QCoreApplication::sendPostedEvents();

    const bool includeTimers = !flags.testFlag(QEventLoop::X11ExcludeTimers);
    const bool includeNotifiers = !flags.testFlag(QEventLoop::ExcludeSocketNotifiers);
    const bool mayWait = flags.testFlag(QEventLoop::WaitForMoreEvents) && !m_interrupted.load(std::memory_order_relaxed);
    if (mayWait && observed)
        Q_EMIT aboutToBlock();
    if (m_interrupted.load(std::memory_order_relaxed))
        return false;

    qint64 timeoutNs = mayWait ? -1 : 0;
    if (mayWait && includeTimers)
        timeoutNs = nextTimerNs(monotonicNowNs());
    if (m_pollListStale)
        rebuildPollList();
    const nfds_t count = includeNotifiers ? nfds_t(m_pollList.size()) : 1;
    timespec timeout{};
    if (timeoutNs >= 0) {
        timeout.tv_sec = time_t(timeoutNs / 1000000000);
        timeout.tv_nsec = long(timeoutNs % 1000000000);
    }
    const int ready = ::ppoll(m_pollList.data(), count, timeoutNs >= 0 ? &timeout : nullptr, nullptr);
    if (ready < 0 && errno != EINTR)
        qWarning("mbscope: the engine's event dispatcher: ppoll() failed (errno %d)", errno);

    int handled = 0;
    if (ready > 0) {
        if (m_pollList.front().revents != 0) {
            drainWakeUp();
            ++handled;
        }
        if (includeNotifiers)
            handled += activateNotifiers();
    }
    if (includeTimers)
        handled += activateTimers();
    return handled > 0;
}

void EngineEventDispatcher::rebuildPollList()
{
    m_pollList.clear();
    m_pollList.push_back(pollfd{m_wakeFd, POLLIN, 0});
    m_polled.clear();
    for (QSocketNotifier *notifier : m_notifiers) {
        m_pollList.push_back(pollfd{int(notifier->socket()), polledEvents(notifier->type()), 0});
        m_polled.push_back(Polled{notifier, dynamic_cast<DirectSocketNotifier *>(notifier)});
    }
    m_pollListStale = false;
}

int EngineEventDispatcher::activateNotifiers()
{
    // The notifiers to wake, taken before any handler runs: a handler may disable, enable or
    // delete notifiers (its own too). m_polled matches m_pollList until the next rebuild.
    QVarLengthArray<Polled, 8> woken;
    for (size_t i = 1; i < m_pollList.size(); ++i) {
        const short revents = m_pollList[i].revents;
        if (revents == 0)
            continue;
        const Polled &polled = m_polled[i - 1];
        QSocketNotifier *notifier = polled.notifier;
        if (revents & POLLNVAL) {
            if (std::find(m_notifiers.cbegin(), m_notifiers.cend(), notifier) != m_notifiers.cend()) {
                qWarning("mbscope: the engine's event dispatcher: descriptor %d is not open; its notifier is disabled",
                         int(notifier->socket()));
                notifier->setEnabled(false);
            }
            continue;
        }
        if (revents & wakingEvents(notifier->type()))
            woken.append(polled);
    }
    int activated = 0;
    for (const Polled &polled : woken) {
        if (std::find(m_notifiers.cbegin(), m_notifiers.cend(), polled.notifier) == m_notifiers.cend())
            continue; // disabled or deleted by an earlier handler
        if (polled.direct) {
            polled.direct->activate();
        } else {
            QEvent event(QEvent::SockAct);
            QCoreApplication::sendEvent(polled.notifier, &event);
        }
        ++activated;
    }
    return activated;
}

int EngineEventDispatcher::activateTimers()
{
    if (m_timers.empty())
        return 0;
    const qint64 now = monotonicNowNs();
    // The due timers' ids first: their handlers may start, stop and restart timers.
    QVarLengthArray<int, 8> due;
    for (const Timer &t : m_timers) {
        if (!t.firing && t.dueNs <= now)
            due.append(t.id);
    }
    int fired = 0;
    for (const int id : due) {
        Timer *t = findTimer(id);
        if (!t || t->firing || t->dueNs > now)
            continue;
        // The next time counts from this one's due time, so that a repeating timer keeps its
        // rhythm, unless it fell a whole interval behind.
        const qint64 intervalNs = t->intervalMs * kNsPerMs;
        t->dueNs += intervalNs;
        if (t->dueNs <= now)
            t->dueNs = now + intervalNs;
        t->firing = true;
        QObject *object = t->object;
        QTimerEvent event(id);
        QCoreApplication::sendEvent(object, &event);
        ++fired;
        if (Timer *after = findTimer(id))
            after->firing = false;
    }
    return fired;
}

qint64 EngineEventDispatcher::nextTimerNs(qint64 nowNs) const
{
    qint64 next = -1;
    for (const Timer &t : m_timers) {
        if (t.firing)
            continue;
        const qint64 wait = qMax<qint64>(0, t.dueNs - nowNs);
        next = next < 0 ? wait : qMin(next, wait);
    }
    return next;
}

void EngineEventDispatcher::drainWakeUp()
{
    eventfd_t value = 0;
    (void)::eventfd_read(m_wakeFd, &value);
    // After the read: a wakeUp() from now on writes again. One that came between the read and
    // this store was for an event already posted, which the next turn sends before it waits.
    m_wakeUpPending.store(false, std::memory_order_release);
}

void EngineEventDispatcher::registerSocketNotifier(QSocketNotifier *notifier)
{
    if (std::find(m_notifiers.cbegin(), m_notifiers.cend(), notifier) == m_notifiers.cend()) {
        m_notifiers.push_back(notifier);
        m_pollListStale = true;
    }
}

void EngineEventDispatcher::unregisterSocketNotifier(QSocketNotifier *notifier)
{
    const auto it = std::find(m_notifiers.begin(), m_notifiers.end(), notifier);
    if (it != m_notifiers.end()) {
        m_notifiers.erase(it);
        m_pollListStale = true;
    }
}

void EngineEventDispatcher::registerTimer(int timerId, qint64 interval, Qt::TimerType timerType, QObject *object)
{
    Timer t;
    t.id = timerId;
    t.intervalMs = qMax<qint64>(0, interval);
    t.type = timerType;
    t.object = object;
    t.dueNs = monotonicNowNs() + t.intervalMs * kNsPerMs;
    m_timers.push_back(t);
}

bool EngineEventDispatcher::unregisterTimer(int timerId)
{
    const auto it = std::find_if(m_timers.begin(), m_timers.end(), [timerId](const Timer &t) { return t.id == timerId; });
    if (it == m_timers.end())
        return false;
    m_timers.erase(it);
    return true;
}

bool EngineEventDispatcher::unregisterTimers(QObject *object)
{
    const auto before = m_timers.size();
    m_timers.erase(std::remove_if(m_timers.begin(), m_timers.end(), [object](const Timer &t) { return t.object == object; }),
                   m_timers.end());
    return m_timers.size() != before;
}

QList<QAbstractEventDispatcher::TimerInfo> EngineEventDispatcher::registeredTimers(QObject *object) const
{
    QList<TimerInfo> timers;
    for (const Timer &t : m_timers) {
        if (t.object == object)
            timers.append(TimerInfo(t.id, int(t.intervalMs), t.type));
    }
    return timers;
}

int EngineEventDispatcher::remainingTime(int timerId)
{
    const Timer *t = findTimer(timerId);
    if (!t)
        return -1;
    const qint64 ns = t->dueNs - monotonicNowNs();
    return ns <= 0 ? 0 : int((ns + kNsPerMs - 1) / kNsPerMs);
}

EngineEventDispatcher::Timer *EngineEventDispatcher::findTimer(int timerId)
{
    for (Timer &t : m_timers) {
        if (t.id == timerId)
            return &t;
    }
    return nullptr;
}

void EngineEventDispatcher::connectNotify(const QMetaMethod &signal)
{
    if (signal == QMetaMethod::fromSignal(&QAbstractEventDispatcher::awake)
        || signal == QMetaMethod::fromSignal(&QAbstractEventDispatcher::aboutToBlock))
        m_turnObservers.fetch_add(1, std::memory_order_relaxed);
}

void EngineEventDispatcher::disconnectNotify(const QMetaMethod &signal)
{
    // An invalid method (everything disconnected at once) does not say which: the count stays,
    // and the signals go on being emitted, which is only slower.
    if (signal == QMetaMethod::fromSignal(&QAbstractEventDispatcher::awake)
        || signal == QMetaMethod::fromSignal(&QAbstractEventDispatcher::aboutToBlock))
        m_turnObservers.fetch_sub(1, std::memory_order_relaxed);
}

void EngineEventDispatcher::wakeUp()
{
    // Any thread. One write until the dispatcher has read it.
    bool expected = false;
    if (m_wakeUpPending.compare_exchange_strong(expected, true, std::memory_order_acq_rel))
        (void)::eventfd_write(m_wakeFd, 1);
}

void EngineEventDispatcher::interrupt()
{
    m_interrupted.store(true, std::memory_order_relaxed);
    wakeUp();
}

} // namespace mbscope

#include "moc_engineeventdispatcher.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
