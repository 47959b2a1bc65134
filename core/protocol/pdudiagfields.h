#pragma once

// Small helpers shared by the dissectors of the diagnostic and "other" function codes
// (07, 08, 0B, 0C, 11, 2B). They add fixed-size fields, report truncation and trailing bytes in
// one wording, and format hex for messages. Messages are built only when something is flagged,
// so the no-problem path allocates nothing.

#include "hexformat.h"
#include "pducontext.h"

#include <QtCore/QString>

namespace mbscope::pdu::diag {

[[nodiscard]] inline QString byteCount(int n)
{
    return n == 1 ? QStringLiteral("1 byte") : QString::number(n) + QStringLiteral(" bytes");
}

[[nodiscard]] inline bool isResponse(const PduContext &ctx)
{
    return ctx.direction == Direction::Response;
}

// The function code field: the dispatch (pdu::dissect) adds it just before calling a family's
// dissector.
[[nodiscard]] inline int functionField(const PduContext &ctx)
{
    return ctx.tree.size() - 1;
}

// Adds a big-endian field of 1 to 8 bytes at pduOffset. When the PDU ends early the field covers
// the bytes that are present, shows them raw, and is flagged with how many bytes were expected.
// Callers continue only when ctx.has(pduOffset, bytes).
inline int addFixed(const PduContext &ctx, int pduOffset, int bytes, const char *key, const char *name,
                    ValueFormat format, const char *meaning = nullptr)
{
    if (ctx.has(pduOffset, bytes)) {
        quint64 value = 0;
        for (int i = 0; i < bytes; ++i)
            value = (value << 8) | ctx.byte(pduOffset + i);
        return ctx.add(key, name, pduOffset, bytes, value, format, meaning);
    }
    const int present = qBound(0, ctx.length - pduOffset, bytes);
    const int f = ctx.add(key, name, pduOffset, present, 0, present > 0 ? ValueFormat::Bytes : ValueFormat::None);
    if (present == 0) {
        ctx.tree.flag(f, Severity::Error,
                      QStringLiteral("missing: %1 expected at PDU offset %2, the PDU ends there")
                          .arg(byteCount(bytes)).arg(pduOffset));
    } else {
        ctx.tree.flag(f, Severity::Error,
                      QStringLiteral("truncated: %1 expected at PDU offset %2, only %3 present")
                          .arg(byteCount(bytes)).arg(pduOffset).arg(present));
    }
    return f;
}

// Flags everything from pduOffset to the end of the PDU as trailing: pduOffset is the size the
// PDU should have had, function code included.
inline void addTrailing(const PduContext &ctx, int pduOffset)
{
    if (ctx.length <= pduOffset)
        return;
    const int extra = ctx.length - pduOffset;
    const int t = ctx.add("modbus.trailing", "Unexpected bytes", pduOffset, extra, 0, ValueFormat::Bytes);
    ctx.tree.flag(t, Severity::Error,
                  QStringLiteral("%1 after the end of the PDU: it should be %2 long, %3 are present")
                      .arg(byteCount(extra), byteCount(pduOffset)).arg(ctx.length));
}

} // namespace mbscope::pdu::diag
