#include "enginecore.h"

#include "traffic/trafficlog.h"

#include "transport/monotonicclock.h"

#include <utility>

namespace mbscope {

void EngineCore::setTrafficLog(TrafficLog *log)
{
    if (m_log && m_log != log)
        m_log->flush();
    m_log = log;
    attachLog();
}

void EngineCore::attachLog()
{
    if (!m_log) {
        m_journalTimer.stop();
        return;
    }
    m_logLink = m_log->addLink(m_url.toString());
    m_journalTimer.start();
}

void EngineCore::logOutgoing(const QByteArray &bytes, qint64 ns, quint64 id)
{
    if (m_log)
        m_log->append(ns, TrafficDirection::Out, m_logLink, TrafficVerdict::Sent, id, bytes);
}

void EngineCore::logIncoming(const QByteArray &bytes, qint64 firstNs, TrafficVerdict verdict, quint64 id)
{
    if (m_log)
        m_log->append(firstNs, TrafficDirection::In, m_logLink, verdict, id, bytes);
    // A frame that answers no request never reaches observers as a transaction: it goes in the
    // next batch on its own, so a traffic view shows garbage and unsolicited frames too.
    if (verdict == TrafficVerdict::Unsolicited || verdict == TrafficVerdict::Garbage) {
        TrafficFrame frame;
        frame.tNs = firstNs;
        frame.transactionId = id;
        frame.direction = TrafficDirection::In;
        frame.verdict = verdict;
        frame.bytes = bytes;
        m_unmatched.append(std::move(frame));
        scheduleBatch();
    }
}

void EngineCore::logTransaction(const Transaction &transaction)
{
    // A transaction whose answer was logged carries its verdict on that frame. One without an
    // answer (timeout, link error, broadcast) is logged as an empty frame in with its verdict,
    // so that the log holds every transaction's outcome.
    if (!m_log || !transaction.response.isEmpty())
        return;
    m_log->append(monotonicNowNs(), TrafficDirection::In, m_logLink, trafficVerdict(transaction.status), transaction.id, {});
}

} // namespace mbscope
