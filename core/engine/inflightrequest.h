#pragma once

#include "exchange/requestitem.h"
#include "exchange/transaction.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// A request waiting in the engine's queue: what was asked, for which poll item and run (tag),
// and, after a retry, what went wrong with the earlier attempts.
struct OutgoingRequest {
    RequestItem item;
    quint64 id = 0;
    int itemIndex = -1;
    int attempt = 0;
    quint64 tag = 0;
    QString history; // what went wrong with earlier attempts
};

// A request written (or being written) to the link, until its answer, its timeout or a link
// error ends it; after a timeout it may wait a while longer for a late answer.
struct InFlightRequest {
    OutgoingRequest out;
    QByteArray sent;            // the bytes written
    bool rewritten = false;     // transaction id given by the engine (pipelining)
    qint64 writeStartNs = 0;
    qint64 sentNs = 0;          // 0 until the link reports the write
    qint64 predictedSentNs = 0; // serial: when the link computes the last byte will have left
    qint64 characterNs = 0;     // serial: one character on the line at the URL's settings; 0 otherwise
    qint64 deadlineNs = 0;
    qint64 timedOutNs = 0;      // for late answers

    // One that never reached the link (it failed before it could be written).
    [[nodiscard]] static InFlightRequest unsent(const OutgoingRequest &out);

    // When the request left: the link's time for the last request byte, unless the answer came
    // faster than the line allows after it (see outranLine); then the time of the write.
    // firstNs, lastNs: the answer's first and last byte (0 when there is no answer).
    [[nodiscard]] qint64 sentTime(qint64 firstNs, qint64 lastNs = 0, qsizetype responseBytes = 0) const;
    // Serial: whether an answer arrived before the line could have carried the request and the
    // answer at its baud rate (it began before the computed end of the request, or ended sooner
    // than its own characters take, allowing 3 % for the baud clocks). The computed end is then
    // not what happened: a pseudo terminal ignores the baud rate, a USB adapter may report
    // bytes written while it still holds them.
    [[nodiscard]] bool outranLine(qint64 firstNs, qint64 lastNs, qsizetype responseBytes) const;

    // The one place a record of this request is made, whatever ended it.
    [[nodiscard]] Transaction toTransaction(TransactionStatus status, const QString &problem,
                                            const QByteArray &response = {}, qint64 firstNs = 0, qint64 lastNs = 0,
                                            quint8 exceptionCode = 0) const;
};

} // namespace mbscope
