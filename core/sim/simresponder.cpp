#include "sim/simresponder.h"

#include "transport/monotonicclock.h"

#include <algorithm>
#include <limits>

namespace mbscope {

SimResponder::SimResponder(bool ordered, QObject *parent)
    : QObject(parent)
    , m_ordered(ordered)
    , m_timer(this)
{
    connect(&m_timer, &DueTimer::timeout, this, &SimResponder::run);
}

SimResponder::~SimResponder() = default;

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
    m_timer.stop();
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
    QString reason;
    qint64 now = monotonicNowNs();
    if (const qint64 due = nextDueNs(); due > now && due - now <= DueTimer::kEarlyWakeNs)
        now = DueTimer::spinUntil(due);
    for (int i = 0; i < m_pending.size() && !closing;) {
        if (advance(i, now, &closing)) {
            if (closing)
                reason = m_pending.at(i).plan.closeReason;
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
        Q_EMIT closeRequested(reason);
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
    // Answers with nothing to wait for leave inside enqueue(): a timer never armed, or disarmed
    // already, costs no system call (one timerfd_settime per request was a sixth of the
    // simulator's system calls under 50 clients, issue 15).
    if (m_pending.isEmpty())
        m_timer.stop();
    else
        m_timer.start(nextDueNs());
}

} // namespace mbscope

#include "moc_simresponder.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
