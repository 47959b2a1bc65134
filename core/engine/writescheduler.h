#pragma once

#include "inflightrequest.h"

#include <QtCore/QList>
#include <QtCore/QVarLengthArray>

namespace mbscope {

// The engine's requests between submit() and their end: the queue, the requests in flight, and
// the writes the link has not yet said are done. It decides what goes out and when each request
// is due; the engine drives the link and records the outcomes.
//
// Requests staged in one turn of a pipelined stream link go out in one write (one system call,
// one segment); bytesWritten() comes once per write, in order, and times every request of it.
class WriteScheduler
{
public:
    struct WriteMark {
        quint64 id = 0;
        int attempt = 0;
        bool endsWrite = true; // the last request of its write (a pipelined write carries several)
    };
    using WriteMarks = QVarLengthArray<WriteMark, 16>;

    void enqueue(OutgoingRequest request) { m_queue.append(std::move(request)); }
    // Another attempt goes before everything queued.
    void retry(OutgoingRequest request) { m_queue.prepend(std::move(request)); }
    [[nodiscard]] bool hasQueued() const { return !m_queue.isEmpty(); }
    [[nodiscard]] OutgoingRequest takeHead() { return m_queue.takeFirst(); }

    [[nodiscard]] const QList<InFlightRequest> &inFlight() const { return m_inFlight; }
    [[nodiscard]] InFlightRequest &inFlightAt(qsizetype index) { return m_inFlight[index]; }
    [[nodiscard]] qsizetype indexOfId(quint64 id) const;
    [[nodiscard]] InFlightRequest takeInFlight(qsizetype index) { return m_inFlight.takeAt(index); }

    // Whether the head of the queue may go out now, with at most depth requests in flight.
    // A broadcast occupies the line alone until its turnaround has passed.
    [[nodiscard]] bool mayStage(int depth) const;
    // Takes the head of the queue in flight and adds its bytes to the next write. An MBAP request
    // numbered by the engine (RequestItem::engineNumbered), or any pipelined one (depth > 1),
    // gets the connection's next transaction id, one no request in flight has; one sent as given
    // keeps its id and the connection's ids go on after it.
    // Its deadline counts from the start of its write until the link says when it ended.
    InFlightRequest &stage(int depth, qint64 nowNs, qint64 broadcastWaitNs);
    [[nodiscard]] bool hasStaged() const { return m_stagedCount > 0; }
    // What stage() gathered, as one write; marks: the requests it carries.
    [[nodiscard]] QByteArray takeStaged(WriteMarks *marks);
    // The link did not take a write: its requests wait for no bytesWritten().
    void forgetWrite(const WriteMarks &marks);
    void forgetWrites() { m_writeOrder.clear(); }

    // The link wrote the next write's last byte at lastByteNs: timeouts (and a broadcast's
    // turnaround) run from then.
    void written(qint64 lastByteNs, qint64 broadcastWaitNs);
    // How long a request may take from its end: its timeout, or for a broadcast the wait after
    // it (the link's RS485 turnaround or the engine's: Serial Line V1.02, 2.4.1).
    [[nodiscard]] static qint64 waitNs(const RequestItem &item, qint64 broadcastWaitNs)
    {
        return item.broadcast ? broadcastWaitNs : qint64(item.timeoutMs) * 1000000;
    }
    // The earliest deadline in flight; 0 when nothing is.
    [[nodiscard]] qint64 earliestDeadline() const;

    // Drops a tag's queued requests and those in flight; how many were in flight.
    qsizetype cancel(quint64 tag);
    // Drops a tag's queued requests only (never written: nothing to abandon).
    void dropQueued(quint64 tag);
    [[nodiscard]] bool isQueued(quint64 id) const;
    [[nodiscard]] int outstanding(quint64 tag) const;

private:
    QList<OutgoingRequest> m_queue;
    QList<InFlightRequest> m_inFlight;
    QList<WriteMark> m_writeOrder; // requests whose write's bytesWritten() has not come yet, in order
    QByteArray m_staged;           // requests staged for the next write
    qsizetype m_stagedCount = 0;
    // The connection's transaction ids (one allocator for every producer that sends on it).
    quint16 m_nextTransactionId = 1;
};

} // namespace mbscope
