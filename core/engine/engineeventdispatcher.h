#pragma once

#include <QtCore/QAbstractEventDispatcher>
#include <QtCore/QList>

#include <atomic>
#include <vector>

#include <poll.h>

namespace mbscope {

class DirectSocketNotifier;

// The event dispatcher of the engine's thread (TransactionEngine sets it before the thread
// starts): one ppoll() over the enabled socket notifiers and a wake-up eventfd, timers kept in a
// short list, posted events sent at each turn. The engine's thread holds a link's notifiers, a few
// timers and the calls posted to it, and turns once per transaction; Qt's general dispatchers
// (GLib's main context, or Qt's own on Unix) spent about 2,500 instructions per turn on sources,
// locks and pollfd lists rebuilt each time, more than a quarter of the engine's work per
// transaction (issue 3). This one keeps its pollfd list until a notifier changes, and calls a
// DirectSocketNotifier's activate() itself instead of sending it an event.
//
// Timers fire at their due time rounded to the millisecond or better (every timer is treated as
// precise); a timer does not fire again while its own timer event is still running (a nested
// event loop). Linux (eventfd, ppoll).
class EngineEventDispatcher final : public QAbstractEventDispatcher
{
    Q_OBJECT
public:
    explicit EngineEventDispatcher(QObject *parent = nullptr);
    ~EngineEventDispatcher() override;

    bool processEvents(QEventLoop::ProcessEventsFlags flags) override;
    void registerSocketNotifier(QSocketNotifier *notifier) override;
    void unregisterSocketNotifier(QSocketNotifier *notifier) override;
    void registerTimer(int timerId, qint64 interval, Qt::TimerType timerType, QObject *object) override;
    bool unregisterTimer(int timerId) override;
    bool unregisterTimers(QObject *object) override;
    [[nodiscard]] QList<TimerInfo> registeredTimers(QObject *object) const override;
    int remainingTime(int timerId) override;
    void wakeUp() override;
    void interrupt() override;

protected:
    // awake() and aboutToBlock() are emitted only while something is connected to them (nothing
    // in the engine's thread is; an emission with no receiver still cost ~70 instructions a turn).
    void connectNotify(const QMetaMethod &signal) override;
    void disconnectNotify(const QMetaMethod &signal) override;

private:
    struct Timer {
        int id = 0;
        qint64 intervalMs = 0;
        Qt::TimerType type = Qt::CoarseTimer;
        QObject *object = nullptr;
        qint64 dueNs = 0;
        bool firing = false; // its timer event is running
    };

    [[nodiscard]] Timer *findTimer(int timerId);
    // Nanoseconds until the next timer is due (0: one is due now), -1 when none is armed.
    [[nodiscard]] qint64 nextTimerNs(qint64 nowNs) const;
    int activateTimers();
    int activateNotifiers();
    void rebuildPollList();
    void drainWakeUp();

    int m_wakeFd = -1;
    std::atomic<bool> m_wakeUpPending{false};
    std::atomic<bool> m_interrupted{false};
    std::atomic<int> m_turnObservers{0}; // connections to awake() and aboutToBlock()
    std::vector<Timer> m_timers;
    std::vector<QSocketNotifier *> m_notifiers;
    std::vector<pollfd> m_pollList; // the wake-up descriptor first, then one per notifier
    struct Polled {
        QSocketNotifier *notifier = nullptr;
        DirectSocketNotifier *direct = nullptr; // the same notifier when it handles activation itself
    };
    std::vector<Polled> m_polled; // the notifiers of m_pollList, in its order
    bool m_pollListStale = true;
};

} // namespace mbscope
