#include "sim/simresponder.h"

#include "transport/monotonicclock.h"

#include <limits>

namespace mbscope {

SimResponder::SimResponder(bool ordered, QObject *parent)
    : QObject(parent)
    , m_ordered(ordered)
    , m_timer(this)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimResponder::run);
}

void SimResponder::enqueue(const FaultPlan &plan, qint64 requestNs, Writer writer)
{
    if (plan.drop && !plan.closeBefore && !plan.closeAfter)
        return;
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
    const qint64 now = monotonicNowNs();
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

void SimResponder::arm()
{
    if (m_pending.isEmpty()) {
        m_timer.stop();
        return;
    }
    qint64 due = std::numeric_limits<qint64>::max();
    for (const Pending &p : std::as_const(m_pending)) {
        due = std::min(due, p.dueNs);
        if (m_ordered)
            break;
    }
    const qint64 waitNs = due - monotonicNowNs();
    // Round up: a timer that fires early would only be armed again.
    const int ms = waitNs <= 0 ? 0 : int(std::min<qint64>((waitNs + 999'999) / 1'000'000, std::numeric_limits<int>::max()));
    m_timer.start(ms);
}

} // namespace mbscope
