#include "sim/simresponder.h"

#include "transport/monotonicclock.h"

#include <algorithm>
#include <cerrno>
#include <limits>

#include <sys/timerfd.h>
#include <unistd.h>

namespace mbscope {

namespace {

// How early the timer wakes the thread before an answer is due; the rest is spun on the clock. A
// thread asleep until the due time itself starts running when the scheduler gets to it: tens of
// microseconds later on an idle machine, a few hundred on a loaded one (measured: 134 us late at
// the median with two compilers on both cores). Spinning costs at most this much CPU per answer.
constexpr qint64 kEarlyWakeNs = 200'000;

// Spins until the monotonic clock reaches dueNs; returns the time then.
qint64 spinUntil(qint64 dueNs)
{
    qint64 now = monotonicNowNs();
    while (now < dueNs)
        now = monotonicNowNs();
    return now;
}

int makeTimerFd()
{
    const int fd = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (fd < 0)
        qFatal("mbscope: the simulator cannot make a timerfd (errno %d)", errno);
    return fd;
}

} // namespace

SimResponder::SimResponder(bool ordered, QObject *parent)
    : QObject(parent)
    , m_ordered(ordered)
{
}

SimResponder::~SimResponder()
{
    if (m_notifier)
        m_notifier->setEnabled(false);
    if (m_timerFd >= 0)
        ::close(m_timerFd);
}

void SimResponder::armAt(qint64 dueNs)
{
    // Answers with nothing to wait for leave inside enqueue(): a timer that was never armed, or is
    // disarmed already, costs no system call (one timerfd_settime per request was a sixth of the
    // simulator's system calls under 50 clients, issue 15); the timerfd and its notifier are made
    // on the first wait, so a connection that never waits adds no descriptor to the poll set.
    if (dueNs == 0 && !m_armed)
        return;
    if (m_timerFd < 0) {
        m_timerFd = makeTimerFd();
        m_notifier = std::make_unique<QSocketNotifier>(m_timerFd, QSocketNotifier::Read, this);
        connect(m_notifier.get(), &QSocketNotifier::activated, this, &SimResponder::onTimer);
    }
    m_armed = dueNs != 0;
    // An absolute time: the wait does not grow by the time spent arming it. A due time in the
    // past (or now) is 1 ns, which has passed: the timer fires at once. 0 disarms.
    itimerspec spec{};
    if (dueNs != 0) {
        const qint64 at = std::max<qint64>(dueNs, 1);
        spec.it_value.tv_sec = time_t(at / 1'000'000'000);
        spec.it_value.tv_nsec = long(at % 1'000'000'000);
    }
    if (::timerfd_settime(m_timerFd, dueNs != 0 ? TFD_TIMER_ABSTIME : 0, &spec, nullptr) != 0)
        qWarning("mbscope: the simulator's answer timer: timerfd_settime failed (errno %d)", errno);
}

void SimResponder::onTimer()
{
    quint64 expirations = 0;
    ssize_t n = 0;
    while ((n = ::read(m_timerFd, &expirations, sizeof expirations)) < 0 && errno == EINTR) {
    }
    if (n > 0)
        m_armed = false; // a one-shot timer that fired is disarmed until armed again
    run();
}

void SimResponder::enqueue(const FaultPlan &plan, qint64 requestNs, Writer writer)
{
    if (plan.drop && !plan.closeBefore && !plan.closeAfter)
        return;
    // The usual answer (one chunk, nothing before it, nothing to wait for) leaves at once, as run()
    // would send it, without a pending entry.
    if (!m_running && m_pending.isEmpty() && !plan.drop && !plan.closeBefore && !plan.closeAfter && plan.chunks.size() == 1
        && requestNs + plan.chunks.first().delayNs <= monotonicNowNs()) {
        m_running = true; // a writer that re-enters queues behind this answer
        writer(plan.chunks.first().bytes);
        m_running = false;
        arm();
        return;
    }
    Pending p;
    p.plan = plan;
    p.writer = std::move(writer);
    p.dueNs = requestNs + (plan.chunks.isEmpty() ? 0 : plan.chunks.first().delayNs);
    m_pending.append(std::move(p));
    run();
}

void SimResponder::clear()
{
    m_pending.clear();
    armAt(0);
}

bool SimResponder::advance(int index, qint64 nowNs, bool *closing)
{
    Pending &p = m_pending[index];
    if (p.dueNs > nowNs)
        return false;
    if (!p.started) {
        p.started = true;
        // In ordered mode the plan starts when the previous one ended: its chunk timing holds
        // from here, and its first chunk is late at worst.
        if (p.plan.closeBefore) {
            *closing = true;
            return true;
        }
        if (p.plan.drop) {
            *closing = p.plan.closeAfter;
            return true;
        }
    }
    while (p.next < p.plan.chunks.size()) {
        if (p.dueNs > nowNs)
            return false;
        p.writer(p.plan.chunks.at(p.next).bytes);
        ++p.next;
        if (p.next < p.plan.chunks.size())
            p.dueNs = nowNs + p.plan.chunks.at(p.next).delayNs;
    }
    if (p.plan.closeAfter)
        *closing = true;
    return true;
}

void SimResponder::run()
{
    if (m_running)
        return; // a writer re-entered (a socket signal): the outer call carries on
    m_running = true;
    bool closing = false;
    qint64 now = monotonicNowNs();
    if (const qint64 due = nextDueNs(); due > now && due - now <= kEarlyWakeNs)
        now = spinUntil(due);
    for (int i = 0; i < m_pending.size() && !closing;) {
        if (advance(i, now, &closing)) {
            m_pending.removeAt(i);
            continue;
        }
        if (m_ordered)
            break;
        ++i;
    }
    m_running = false;
    if (closing) {
        clear();
        Q_EMIT closeRequested();
        return;
    }
    arm();
}

qint64 SimResponder::nextDueNs() const
{
    qint64 due = std::numeric_limits<qint64>::max();
    for (const Pending &p : std::as_const(m_pending)) {
        due = std::min(due, p.dueNs);
        if (m_ordered)
            break;
    }
    return due;
}

void SimResponder::arm()
{
    if (m_pending.isEmpty()) {
        armAt(0);
        return;
    }
    armAt(std::max<qint64>(1, nextDueNs() - kEarlyWakeNs));
}

} // namespace mbscope
