#include "inflightrequest.h"

#include <algorithm>

namespace mbscope {

InFlightRequest InFlightRequest::unsent(const OutgoingRequest &out)
{
    InFlightRequest p;
    p.out = out;
    p.sent = out.item.bytes;
    return p;
}

bool InFlightRequest::outranLine(qint64 firstNs, qint64 lastNs, qsizetype responseBytes) const
{
    const qint64 linkNs = sentNs != 0 ? sentNs : predictedSentNs;
    if (linkNs == 0 || firstNs == 0)
        return false;
    if (firstNs < linkNs)
        return true;
    // Serial Line V1.02, 2.5.1.1: the answer's characters follow one another on the line, each
    // characterNs long, so its last byte comes at least their time after the request's end. The
    // computed end can only be early (the line cannot start before the write), which makes the
    // time longer, never shorter; the only slack is for the two ends' baud clocks, a UART's
    // being allowed to run a few percent fast (3 % here).
    const qint64 answerNs = qint64(responseBytes) * characterNs;
    return characterNs > 0 && lastNs > 0 && lastNs - linkNs < answerNs - answerNs * 3 / 100;
}

qint64 InFlightRequest::sentTime(qint64 firstNs, qint64 lastNs, qsizetype responseBytes) const
{
    // A serial link's drain time is computed, and a pseudo terminal drains at once: an answer
    // cannot begin before its request left, nor end sooner than its characters take, so the
    // latency would be shorter than the line allows (issue 19: 2 of 40 latencies under 1 ms over
    // a pty at 9600 baud from a responder that waits 3 ms). The moment the write began is then
    // the latest time known to be before the answer.
    const qint64 linkNs = sentNs != 0 ? sentNs : predictedSentNs;
    if (linkNs != 0 && !outranLine(firstNs, lastNs, responseBytes))
        return linkNs;
    return writeStartNs;
}

Transaction InFlightRequest::toTransaction(TransactionStatus status, const QString &problem, const QByteArray &response,
                                           qint64 firstNs, qint64 lastNs, quint8 exceptionCode) const
{
    Transaction t;
    t.id = out.id;
    t.item = out.itemIndex;
    t.attempt = out.attempt;
    t.request = sent;
    t.response = response;
    t.status = status;
    t.exceptionCode = exceptionCode;
    t.problem = out.history + problem;
    // Never written: no time of its own.
    t.sentNs = writeStartNs == 0 && sentNs == 0 && predictedSentNs == 0 ? 0 : sentTime(firstNs, lastNs, response.size());
    t.writeNs = writeStartNs;
    const qint64 linkNs = sentNs != 0 ? sentNs : predictedSentNs;
    t.transmitNs = characterNs > 0 ? qint64(sent.size()) * characterNs : 0;
    t.lineQueuedNs = characterNs > 0 && linkNs > writeStartNs ? std::max<qint64>(0, linkNs - writeStartNs - t.transmitNs) : 0;
    t.outranLine = outranLine(firstNs, lastNs, response.size());
    t.firstByteNs = firstNs;
    t.doneNs = lastNs;
    t.transactionIdRewritten = rewritten;
    return t;
}

} // namespace mbscope
