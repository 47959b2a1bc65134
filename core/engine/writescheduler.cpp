#include "writescheduler.h"

#include <algorithm>
#include <utility>

namespace mbscope {

qsizetype WriteScheduler::indexOfId(quint64 id) const
{
    for (qsizetype i = 0; i < m_inFlight.size(); ++i) {
        if (m_inFlight.at(i).out.id == id)
            return i;
    }
    return -1;
}

bool WriteScheduler::mayStage(int depth) const
{
    if (m_queue.isEmpty())
        return false;
    if (m_inFlight.isEmpty())
        return true;
    return m_inFlight.size() < depth && !m_inFlight.constFirst().out.item.broadcast && !m_queue.constFirst().item.broadcast;
}

InFlightRequest &WriteScheduler::stage(int depth, qint64 nowNs, qint64 broadcastWaitNs)
{
    InFlightRequest p;
    p.out = m_queue.takeFirst();
    p.sent = p.out.item.bytes;
    if (p.out.item.rule == MatchRule::Mbap && p.sent.size() >= 2) {
        if (depth > 1 || p.out.item.engineNumbered) {
            // A transaction id of the connection's own, distinct from every request in flight
            // (Messaging on TCP/IP V1.0b, 3.1.3: the id pairs a response with its request).
            quint16 tid = m_nextTransactionId++;
            for (int guard = 0; guard < 65536; ++guard) {
                bool used = false;
                for (const InFlightRequest &q : m_inFlight)
                    used = used || q.out.item.transactionId == tid;
                if (!used)
                    break;
                tid = m_nextTransactionId++;
            }
            p.sent[0] = char(tid >> 8);
            p.sent[1] = char(tid & 0xFF);
            p.rewritten = tid != p.out.item.transactionId;
            p.out.item.transactionId = tid;
        } else {
            m_nextTransactionId = quint16(p.out.item.transactionId + 1); // as given: the ids go on after it
        }
    }
    p.writeStartNs = nowNs;
    p.deadlineNs = nowNs + waitNs(p.out.item, broadcastWaitNs);
    m_writeOrder.append(WriteMark{p.out.id, p.out.attempt, false});
    if (m_stagedCount++ == 0)
        m_staged = p.sent; // shared, not copied: a single request is written as it is
    else
        m_staged.append(p.sent);
    m_inFlight.append(std::move(p));
    return m_inFlight.last();
}

QByteArray WriteScheduler::takeStaged(WriteMarks *marks)
{
    // The staged requests are the last entries of the write order (nothing ran since staging).
    marks->clear();
    for (qsizetype i = m_writeOrder.size() - m_stagedCount; i < m_writeOrder.size(); ++i)
        marks->append(m_writeOrder.at(i));
    m_writeOrder.last().endsWrite = true;
    m_stagedCount = 0;
    return std::exchange(m_staged, {});
}

void WriteScheduler::forgetWrite(const WriteMarks &marks)
{
    m_writeOrder.removeIf([&marks](const WriteMark &m) {
        return std::any_of(marks.cbegin(), marks.cend(), [&m](const WriteMark &s) { return s.id == m.id && s.attempt == m.attempt; });
    });
}

void WriteScheduler::written(qint64 lastByteNs, qint64 broadcastWaitNs)
{
    while (!m_writeOrder.isEmpty()) {
        const WriteMark mark = m_writeOrder.takeFirst();
        const qsizetype i = indexOfId(mark.id);
        // The request may have ended already (an answer that came before the link said the bytes
        // had left: the answer's time then bounds the send time, see InFlightRequest::sentTime).
        if (i >= 0 && m_inFlight.at(i).out.attempt == mark.attempt && m_inFlight.at(i).sentNs == 0) {
            InFlightRequest &p = m_inFlight[i];
            p.sentNs = lastByteNs;
            p.deadlineNs = lastByteNs + waitNs(p.out.item, broadcastWaitNs);
        }
        if (mark.endsWrite)
            break;
    }
}

qint64 WriteScheduler::earliestDeadline() const
{
    if (m_inFlight.isEmpty())
        return 0;
    qint64 earliest = m_inFlight.constFirst().deadlineNs;
    for (const InFlightRequest &p : m_inFlight)
        earliest = qMin(earliest, p.deadlineNs);
    return earliest;
}

qsizetype WriteScheduler::cancel(quint64 tag)
{
    m_queue.removeIf([tag](const OutgoingRequest &o) { return o.tag == tag; });
    const qsizetype before = m_inFlight.size();
    m_inFlight.removeIf([tag](const InFlightRequest &p) { return p.out.tag == tag; });
    return before - m_inFlight.size();
}

void WriteScheduler::dropQueued(quint64 tag)
{
    m_queue.removeIf([tag](const OutgoingRequest &o) { return o.tag == tag; });
}

bool WriteScheduler::isQueued(quint64 id) const
{
    return std::any_of(m_queue.cbegin(), m_queue.cend(), [id](const OutgoingRequest &o) { return o.id == id; });
}

int WriteScheduler::outstanding(quint64 tag) const
{
    int n = 0;
    for (const OutgoingRequest &o : m_queue)
        n += o.tag == tag ? 1 : 0;
    for (const InFlightRequest &p : m_inFlight)
        n += p.out.tag == tag ? 1 : 0;
    return n;
}

} // namespace mbscope
