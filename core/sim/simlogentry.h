#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// What the simulator did with a request (or with bytes that were not one), for the CLI's one
// line per request, the GUI and tests (Simulator::logged).
struct SimLogEntry {
    enum class Verdict : quint8 {
        Answered,          // a normal response was sent (or handed to the fault plan)
        Exception,         // an exception response
        NoAnswer,          // processed without an answer: broadcast, listen-only, 08/04
        UnknownUnit,       // no such unit behind the endpoint: exception 0B or silence (options)
        ChecksumError,     // RTU CRC / ASCII LRC wrong: silence, a comm error counted
        Malformed,         // a frame that is no request: bad MBAP header, truncated frame...
        Garbage,           // bytes no frame could use (skipped by the framer)
        ConnectionOpened,
        ConnectionRefused, // over the endpoint's connection limit
        ConnectionClosed,  // by the peer, idle timeout, a fault plan or a malformed header
    };

    qint64 tNs = 0;        // monotonicNowNs() when it happened
    QString endpoint;      // the endpoint's URL as bound
    QString peer;          // "127.0.0.1:53122", the serial device, ...
    int unitId = -1;       // -1 when no unit id was read
    QByteArray request;    // the bytes received (whole ADU, or the garbage)
    QByteArray response;   // the answer as built (empty when none); faults may change what is sent
    Verdict verdict = Verdict::Answered;
    QString reason;        // why: the exception's cause, "bad CRC: 0x1234, expected 0x5678", ...
    QStringList faults;    // the fault rules that fired on the answer (FaultPlan::faults)

    // "answered", "exception", "no_answer", "unknown_unit", "checksum_error", "malformed",
    // "garbage", "connection_opened", "connection_refused", "connection_closed"
    [[nodiscard]] static const char *verdictName(Verdict verdict);
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::SimLogEntry)
