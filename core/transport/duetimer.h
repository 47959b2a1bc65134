#pragma once

#include <QtCore/QObject>
#include <QtCore/QSocketNotifier>

#include <memory>

namespace mbscope {

// A one-shot timer for a moment on the monotonic clock (monotonicNowNs), to the microsecond: a
// timerfd armed at an absolute time on CLOCK_MONOTONIC, watched by a socket notifier. A QTimer
// counts whole milliseconds, so what it times leaves on millisecond ticks (issue 19: a 4 +/- 1.5 ms
// response time came out as a comb at 0.5 ms bins). It wakes the thread kEarlyWakeNs before the
// due time and spins the rest before timeout(), so the scheduler's wake-up latency does not make
// it late. Linux (timerfd).
//
// The timerfd and its notifier are made on the first start(): a timer never started adds no
// descriptor to the poll set, and stop() of a timer that is not armed costs no system call.
class DueTimer : public QObject
{
    Q_OBJECT
public:
    // How early the timer wakes the thread before the due time; the rest is spun on the clock. A
    // thread asleep until the due time itself starts running when the scheduler gets to it: tens of
    // microseconds later on an idle machine, a few hundred on a loaded one (measured: 134 us late
    // at the median with two compilers on both cores). Spinning costs at most this much CPU.
    static constexpr qint64 kEarlyWakeNs = 200'000;

    explicit DueTimer(QObject *parent = nullptr);
    ~DueTimer() override;

    // timeout() once monotonicNowNs() >= dueNs (at once, from the event loop, for a time passed).
    void start(qint64 dueNs);
    void stop();
    [[nodiscard]] bool isActive() const { return m_armed; }

    // Spins until the monotonic clock reaches dueNs; returns the time then.
    static qint64 spinUntil(qint64 dueNs);

Q_SIGNALS:
    void timeout();

private:
    void arm(qint64 wakeNs); // 0: disarm
    void onActivated();

    int m_fd = -1;
    std::unique_ptr<QSocketNotifier> m_notifier;
    qint64 m_dueNs = 0;
    bool m_armed = false;
};

} // namespace mbscope
