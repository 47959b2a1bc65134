#pragma once

#include "delayspec.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// One fault injection rule (see docs/profiles.md, "Fault injection"). A rule matches a request
// by unit, function code, the address range it meets, and exactly by start address, quantity and
// written values (each optional: absent matches everything), then fires with its probability. The effects of all the rules that fire on one answer combine
// (FaultInjector::plan says in which order).
struct FaultRule {
    enum class Kind : quint8 {
        Delay,              // the answer after a drawn delay instead of the unit's response time
        Drop,               // no answer at all
        WrongChecksum,      // RTU CRC or ASCII LRC altered (every bit inverted)
        WrongTransactionId, // MBAP transaction id + delta
        WrongUnit,          // unit id + delta, checksum recomputed
        Exception,          // exception response with exceptionCode instead of the answer
        FewerRegisters,     // a read answer short of `fewer` registers (bytes of bits for 01/02)
        Chunks,             // the answer in pieces of chunkBytes with gapMs between them
        Trickle,            // one byte every gapMs
        Junk,               // bytes before and/or after the answer
        Duplicate,          // the answer, then `copies` more after gapMs each
        Close,              // connection closed before, midway through, or after the answer
    };
    enum class CloseWhen : quint8 { Before, Midway, After };

    Kind kind = Kind::Drop;
    QString name;                 // optional label for logs
    QList<quint8> units;          // empty: every unit
    QList<quint8> functions;      // empty: every function code
    // "meets": the request's addresses overlap [firstAddress, lastAddress]; -1: any request.
    int firstAddress = -1;
    int lastAddress = -1;
    QList<int> starts;            // "start": the request's start address is one of these; empty: any
    QList<int> quantities;        // "quantity": its quantity is one of these; empty: any
    QList<quint16> values;        // "values": the values it writes, exactly (when hasValues)
    bool hasValues = false;
    double probability = 1;

    DelaySpec delay;              // Delay
    quint8 exceptionCode = 4;     // Exception (04: server device failure)
    int fewer = 1;                // FewerRegisters
    int delta = 1;                // WrongTransactionId, WrongUnit (modulo 2^16, 2^8)
    int chunkBytes = 1;           // Chunks
    double gapMs = 0;             // Chunks, Trickle, Duplicate
    QByteArray junkBefore;        // Junk: these bytes, or
    QByteArray junkAfter;
    int junkBeforeCount = 0;      // ... this many random bytes
    int junkAfterCount = 0;
    int copies = 1;               // Duplicate
    CloseWhen closeWhen = CloseWhen::After; // Close

    [[nodiscard]] bool hasAddressRange() const { return firstAddress >= 0; }
    [[nodiscard]] static QString kindName(Kind kind); // "wrongChecksum"
    [[nodiscard]] static std::optional<Kind> kindFromName(QStringView name);
    [[nodiscard]] static QString kindNames(); // "delay, drop, ..." for messages

    friend bool operator==(const FaultRule &, const FaultRule &) = default;
};

// The rules of a profile or of a faults file, with the seed their random draws start from.
struct FaultRuleSet {
    quint64 seed = 1;
    QList<FaultRule> rules;

    friend bool operator==(const FaultRuleSet &, const FaultRuleSet &) = default;
};

} // namespace mbscope
