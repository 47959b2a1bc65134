#include "inflightrequest.h"

namespace mbscope {

InFlightRequest InFlightRequest::unsent(const OutgoingRequest &out)
{
    InFlightRequest p;
    p.out = out;
    p.sent = out.item.bytes;
    return p;
}

qint64 InFlightRequest::sentTime(qint64 firstNs) const
{
    // A serial link's drain time is computed, and a pseudo terminal drains at once: an answer
    // cannot begin before its request left, so its first byte bounds the send time, and the
    // moment the write began is the latest time known to be before it.
    const qint64 linkNs = sentNs != 0 ? sentNs : predictedSentNs;
    if (linkNs != 0 && (firstNs == 0 || linkNs <= firstNs))
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
    t.sentNs = writeStartNs == 0 && sentNs == 0 && predictedSentNs == 0 ? 0 : sentTime(firstNs);
    t.firstByteNs = firstNs;
    t.doneNs = lastNs;
    t.transactionIdRewritten = rewritten;
    return t;
}

} // namespace mbscope
