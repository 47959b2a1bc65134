#pragma once

#include "transaction.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QMetaType>
#include <QtCore/QAnyStringView>

namespace mbscope {

enum class TrafficDirection : quint8 {
    Out = 0, // written to the link
    In = 1,  // read from the link
};

// What became of a frame. The numbers are stored in journals (trafficjournal.h): never renumber.
// 0-8 are the transaction statuses, so a frame carries its transaction's verdict.
enum class TrafficVerdict : quint8 {
    Ok = 0,
    Exception = 1,
    Timeout = 2,
    CrcError = 3,
    Malformed = 4,
    Unexpected = 5,
    LinkError = 6,
    Broadcast = 7,
    Late = 8,         // an answer that came after its request had timed out
    Sent = 9,         // a request on its way: logged when written, its verdict comes with its answer
    Unsolicited = 10, // a frame that came when no request was waiting for it
    Garbage = 11,     // bytes the framer skipped: not a frame at all
};
inline constexpr int kTrafficVerdictCount = 12;

[[nodiscard]] TrafficVerdict trafficVerdict(TransactionStatus status);
// "ok", "exception", "timeout", "crc_error", "malformed", "unexpected", "link_error",
// "broadcast", "late" (as transactionStatusName), "sent", "unsolicited", "garbage".
[[nodiscard]] const char *trafficVerdictName(TrafficVerdict verdict);
// The verdict a name names (as above); Garbage for a name it does not know, with *known false.
[[nodiscard]] TrafficVerdict trafficVerdictFromName(QAnyStringView name, bool *known = nullptr);
[[nodiscard]] const char *trafficDirectionName(TrafficDirection direction); // "out", "in"

// One logged frame as a view into the log's storage (or a journal being read): valid until the
// log is next changed (append, eviction) or the reader returns. Copy into a TrafficFrame to keep.
struct TrafficEntry {
    quint64 sequence = 0;      // 0 for the first frame ever logged, then +1 each
    qint64 tNs = 0;            // monotonic ns (monotonicNowNs): written, or first byte read
    quint64 transactionId = 0; // Transaction::id, 0 when none (garbage, unsolicited)
    quint16 link = 0;          // TrafficLog::addLink id
    TrafficDirection direction = TrafficDirection::Out;
    TrafficVerdict verdict = TrafficVerdict::Sent;
    QByteArrayView bytes;
};

// The same, owning its bytes: for handing frames to another thread or keeping them.
struct TrafficFrame {
    quint64 sequence = 0;
    qint64 tNs = 0;
    quint64 transactionId = 0;
    quint16 link = 0;
    TrafficDirection direction = TrafficDirection::Out;
    TrafficVerdict verdict = TrafficVerdict::Sent;
    QByteArray bytes;

    [[nodiscard]] static TrafficFrame from(const TrafficEntry &entry);
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::TrafficFrame)
