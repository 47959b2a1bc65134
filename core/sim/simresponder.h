#pragma once

#include "sim/faultplan.h"
#include "transport/duetimer.h"

#include <QtCore/QList>
#include <QtCore/QObject>

#include <functional>

namespace mbscope {

// Executes FaultPlans on one output (a connection, a serial port, a datagram socket) with timers,
// never blocking the event loop: each chunk is written delayNs after the previous one (the first
// after the request arrived); closeBefore and closeAfter ask the owner to close the output.
//
// The timer is a DueTimer (core/transport): a timerfd armed at the due time on CLOCK_MONOTONIC (the
// clock of monotonicNowNs), not a QTimer's whole milliseconds (issue 19); it wakes 200 us early
// and spins the rest, so the scheduler's wake-up latency does not make the answer late.
//
// Ordered (streams, serial lines): plans run one after the other in arrival order, as a device
// that answers one request at a time; a plan's first delay runs from its request's arrival but
// its first byte never leaves before the previous plan's last. Unordered (datagrams): each plan
// runs on its own clock.
//
// A plan with nothing to wait for is written at once, inside enqueue().
class SimResponder : public QObject
{
    Q_OBJECT
public:
    using Writer = std::function<void(const QByteArray &bytes)>;

    explicit SimResponder(bool ordered, QObject *parent = nullptr);
    ~SimResponder() override;

    // requestNs: monotonicNowNs() when the request's last byte arrived.
    void enqueue(const FaultPlan &plan, qint64 requestNs, Writer writer);
    // Forget every pending plan (the output is gone).
    void clear();
    [[nodiscard]] bool isIdle() const { return m_pending.isEmpty(); }
    [[nodiscard]] int pendingCount() const { return int(m_pending.size()); }

Q_SIGNALS:
    // A plan said to close; the owner closes the output (the responder forgets what is pending).
    void closeRequested(const QString &reason);

private:
    struct Pending {
        FaultPlan plan;
        Writer writer;
        int next = 0;     // next chunk to write
        qint64 dueNs = 0; // when it is due
        bool started = false;
    };
    void run();
    void arm();
    // The earliest due time of what is pending (ordered: of the first plan); max when none.
    [[nodiscard]] qint64 nextDueNs() const;
    // Writes what is due of m_pending[index]; returns true when the plan is finished.
    bool advance(int index, qint64 nowNs, bool *closing);

    bool m_ordered;
    QList<Pending> m_pending;
    DueTimer m_timer;
    bool m_running = false;
};

} // namespace mbscope
