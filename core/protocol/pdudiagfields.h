#pragma once

// Single fields for the exception dissector (pdudissector.cpp), on the shared mechanism of
// pduchecks.h: a PDU that ends early gets the modbus.missing field, bytes after its end the
// modbus.trailing field.

#include "pduchecks.h"

namespace mbscope::pdu::diag {

// Adds a big-endian field of 1 or 2 bytes at pduOffset, the last of the PDU; when the PDU ends
// first, the missing field instead, named after this one. Returns the field, or -1 when absent.
inline int addFixed(const PduContext &ctx, int pduOffset, int bytes, const char *key, const char *name,
                    ValueFormat format)
{
    const checks::Slot slot{key, name, bytes, format, name};
    int f = -1;
    checks::addFixed(ctx, ctx.parent, pduOffset, &slot, 1, &f, pduOffset + bytes, false);
    return f;
}

// Flags everything from pduOffset (the size the PDU should have) on as trailing.
inline void addTrailing(const PduContext &ctx, int pduOffset)
{
    checks::trailing(ctx, pduOffset);
}

} // namespace mbscope::pdu::diag
