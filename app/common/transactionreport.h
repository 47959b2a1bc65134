#pragma once

#include "exchange/transaction.h"
#include "transport/linkurl.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope::app {

// One transaction of send, read or write as people and scripts read it: the request and the
// response decoded field by field (DissectionFormat), the status and the latency. Frames of a
// delimited link carry no Modbus fields: they are shown as hex and text.
class TransactionReport
{
public:
    // REQUEST / RESPONSE headings, each frame's table, the TIMING line, then the outcome line.
    [[nodiscard]] static QString text(const Transaction &t, const LinkUrl &url);
    // The outcome line alone: "ok: answered in 1.234 ms" or "timeout: no answer within 1000 ms".
    [[nodiscard]] static QString outcome(const Transaction &t);
    // What the latency is measured from ("latency from the request's write to the link", on a
    // serial link the computed end of its transmission), or the warning that the answer outran
    // the serial line; empty when there is no latency.
    [[nodiscard]] static QString timingNote(const Transaction &t);
    // {"status", "problem", "exception_code", "latency_us", "first_byte_us", "latency_from"
    //  ("write", "line_end" or null), "transmit_us" (serial), "outran_line", "attempts",
    //  "request": {"hex", "length", "dissection"}, "response": {...} or null}
    [[nodiscard]] static QJsonObject json(const Transaction &t, const LinkUrl &url);

    // 0 for ok (and a broadcast, which wants no answer), 2 for a link error (nothing reached the
    // device), 1 for every other failure, and 1 as well for a request mbscope judges malformed
    // (its own dissection has errors) whatever came back.
    [[nodiscard]] static int exitStatus(const Transaction &t, const LinkUrl &url);
    // "the request itself is malformed: 1 error(s), 0 warning(s) (rtu.crc: ...)", or empty when the
    // request is well formed or the link is delimited (no Modbus fields to judge).
    [[nodiscard]] static QString requestProblem(const Transaction &t, const LinkUrl &url);
};

// "1.234 ms", "734.5 µs", "2.100 s".
[[nodiscard]] QString latencyText(qint64 ns);

} // namespace mbscope::app
