// 03 Read Holding Registers and 04 Read Input Registers (MODBUS Application Protocol
// Specification V1.1b3, 6.3 and 6.4): request start address + quantity (1-125); response byte
// count (2 x quantity) + registers.
#include "pduchecks.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

constexpr int kMaxRegisters = 125; // 0x007D, V1.1b3 6.3/6.4

const Slot kRequest[] = {
    {"modbus.start_address", "Start address", 2, ValueFormat::DecimalHex, "start address and quantity"},
    {"modbus.quantity", "Quantity", 2, ValueFormat::Decimal, "quantity"},
};

void request(const PduContext &ctx)
{
    int f[2];
    if (!addFixed(ctx, ctx.parent, 1, kRequest, 2, f, 5, false))
        return;
    const int start = ctx.u16(1);
    const int quantity = ctx.u16(3);
    checkQuantity(ctx, f[1], quantity, kMaxRegisters, "quantity");
    checkRange(ctx, f[1], start, quantity, "quantity");
    trailing(ctx, 5);
}

void response(const PduContext &ctx)
{
    if (!ctx.has(1)) {
        missing(ctx, ctx.parent, 1, 4, true, "byte count and register values");
        return;
    }
    const int byteCount = ctx.byte(1);
    const int bc = ctx.add("modbus.byte_count", "Byte count", 1, 1, quint64(byteCount), ValueFormat::Decimal);
    const bool known = requestUsable(ctx, 5);
    const int quantity = known ? ctx.requestU16(3) : -1;
    if (known && byteCount != 2 * quantity) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 does not match the request: quantity %2 needs %3 "
                                     "(2 per register)")
                          .arg(QString::number(byteCount), QString::number(quantity),
                               amount(2 * quantity, "byte", "bytes")));
    } else if (byteCount == 0 || byteCount > 2 * kMaxRegisters) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is out of range: a %2 response carries 1-125 registers "
                                     "(2-250 bytes)")
                          .arg(QString::number(byteCount), functionLabel(ctx)));
    }
    if (byteCount % 2 != 0) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is odd: registers are 2 bytes each").arg(byteCount));
    }
    registerBlock(ctx, ctx.parent, 2, 2, 2 + byteCount, known ? "Register" : "Register index",
                  known ? int(ctx.requestU16(1)) : -1);
    trailing(ctx, 2 + byteCount);
}

} // namespace

void dissectReadRegisters(const PduContext &ctx)
{
    if (isResponse(ctx))
        response(ctx);
    else
        request(ctx);
}

} // namespace mbscope::pdu
