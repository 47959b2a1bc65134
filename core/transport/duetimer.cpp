#include "duetimer.h"

#include "monotonicclock.h"

#include <algorithm>
#include <cerrno>

#include <sys/timerfd.h>
#include <unistd.h>

namespace mbscope {

DueTimer::DueTimer(QObject *parent)
    : QObject(parent)
{
}

DueTimer::~DueTimer()
{
    if (m_notifier)
        m_notifier->setEnabled(false);
    if (m_fd >= 0)
        ::close(m_fd);
}

qint64 DueTimer::spinUntil(qint64 dueNs)
{
    qint64 now = monotonicNowNs();
    while (now < dueNs)
        now = monotonicNowNs();
    return now;
}

void DueTimer::start(qint64 dueNs)
{
    m_dueNs = dueNs;
    arm(std::max<qint64>(1, dueNs - kEarlyWakeNs));
}

void DueTimer::stop()
{
    if (m_armed)
        arm(0);
}

void DueTimer::arm(qint64 wakeNs)
{
    if (m_fd < 0) {
        m_fd = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
        if (m_fd < 0)
            qFatal("mbscope: cannot make a timerfd (errno %d)", errno);
        m_notifier = std::make_unique<QSocketNotifier>(m_fd, QSocketNotifier::Read, this);
        connect(m_notifier.get(), &QSocketNotifier::activated, this, &DueTimer::onActivated);
    }
    m_armed = wakeNs != 0;
    // An absolute time: the wait does not grow by the time spent arming it. A time in the past is
    // 1 ns, which has passed: the timer fires at once. 0 disarms.
    itimerspec spec{};
    if (wakeNs != 0) {
        spec.it_value.tv_sec = time_t(wakeNs / 1'000'000'000);
        spec.it_value.tv_nsec = long(wakeNs % 1'000'000'000);
    }
    if (::timerfd_settime(m_fd, wakeNs != 0 ? TFD_TIMER_ABSTIME : 0, &spec, nullptr) != 0)
        qWarning("mbscope: timerfd_settime failed (errno %d)", errno);
}

void DueTimer::onActivated()
{
    quint64 expirations = 0;
    ssize_t n = 0;
    while ((n = ::read(m_fd, &expirations, sizeof expirations)) < 0 && errno == EINTR) {
    }
    if (n <= 0 || !m_armed)
        return; // disarmed or armed again meanwhile
    m_armed = false; // a one-shot timer that fired is disarmed until armed again
    spinUntil(m_dueNs);
    Q_EMIT timeout();
}

} // namespace mbscope

#include "moc_duetimer.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
