#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

// The verdict of one request/response exchange.
enum class TransactionStatus : quint8 {
    Ok,          // a matching, well-formed answer
    Exception,   // a matching exception response (exceptionCode says which)
    Timeout,     // no matching answer within the timeout (after every retry)
    CrcError,    // an answer whose CRC/LRC is wrong
    Malformed,   // an answer that is not a well-formed frame for the request (byte count, length...)
    Unexpected,  // an answer that does not match (transaction id, unit or function code)
    LinkError,   // the link failed (closed, refused, I/O error) before an answer came
    Broadcast,   // a broadcast: sent, turnaround waited, no answer expected
    Late,        // an answer that came after its request was recorded as Timeout: a record of its
                 // own about a request already counted (statistics count it as late, not in count)
};

[[nodiscard]] QString transactionStatusName(TransactionStatus status); // "ok", "timeout", "crc_error"...

// One exchange as the engine saw it. Timestamps are monotonic nanoseconds (monotonicNowNs):
// sentNs when the last request byte left, firstByteNs and doneNs when the first and the last
// byte of the answer arrived (0 when there was no answer). The latency runs from sentNs to doneNs.
//
// What sentNs is: on network links, the moment the socket took the request (the write). On
// serial links, the end of the request's transmission as computed from the write and the line's
// settings (writeNs + the time queued behind earlier bytes + transmitNs), since the host cannot
// see the last stop bit leave; unless the answer came faster than that line allows
// (outranLine: a pseudo terminal or a buffering USB adapter), when it is the write (writeNs).
struct Transaction {
    quint64 id = 0;          // engine-wide sequence number
    int item = -1;           // index of the request item in a poll, -1 for a single send
    int attempt = 0;         // 0 for the first try, then retries
    QByteArray request;      // exactly the bytes sent
    QByteArray response;     // exactly the bytes of the matched answer (empty on timeout)
    TransactionStatus status = TransactionStatus::Timeout;
    quint8 exceptionCode = 0;
    QString problem;         // what was wrong, for statuses other than Ok and Broadcast
    qint64 sentNs = 0;
    qint64 firstByteNs = 0;
    qint64 doneNs = 0;
    qint64 writeNs = 0;      // when the request was handed to the link (0: never written)
    qint64 transmitNs = 0;   // serial: the request's computed time on the line at its baud rate; 0 otherwise
    qint64 lineQueuedNs = 0; // serial: computed wait behind bytes written before it
    // Serial: the answer arrived before the line could have carried the request and the answer
    // (the link does not honour its baud rate); the latency is then measured from the write.
    bool outranLine = false;
    // The engine gave the request the connection's next transaction id in place of the one in the
    // bytes it was given (RequestItem::engineNumbered, or pipelining); request holds the bytes
    // actually sent.
    bool transactionIdRewritten = false;

    // -1 without an answer, or for a request never written (sentNs 0: a link error before the
    // write, whose doneNs only places it in time).
    [[nodiscard]] qint64 latencyNs() const { return doneNs > 0 && sentNs > 0 ? doneNs - sentNs : -1; }
    [[nodiscard]] bool isOk() const { return status == TransactionStatus::Ok; }
    // Whether the latency runs from the computed end of transmission (serial links that honour
    // their line) rather than from the write.
    [[nodiscard]] bool measuredFromLineEnd() const { return transmitNs > 0 && !outranLine; }
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::Transaction)
