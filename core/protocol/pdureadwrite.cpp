// 17 Read/Write Multiple Registers (MODBUS Application Protocol Specification V1.1b3, 6.17):
// the request carries a read block (start, quantity 1-125) and a write block (start, quantity
// 1-121, byte count, values); the response carries the registers read.
#include "pduchecks.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

constexpr int kMaxRead = 125; // 0x007D
constexpr int kMaxWrite = 121; // 0x0079

const Slot kHeader[] = {
    {"modbus.read_start_address", "Read start address", 2, ValueFormat::DecimalHex,
     "read start address, read quantity, write start address, write quantity, byte count and write values"},
    {"modbus.read_quantity", "Quantity to read", 2, ValueFormat::Decimal,
     "read quantity, write start address, write quantity, byte count and write values"},
    {"modbus.write_start_address", "Write start address", 2, ValueFormat::DecimalHex,
     "write start address, write quantity, byte count and write values"},
    {"modbus.write_quantity", "Quantity to write", 2, ValueFormat::Decimal,
     "write quantity, byte count and write values"},
};

void request(const PduContext &ctx)
{
    int f[4];
    if (!addFixed(ctx, ctx.parent, 1, kHeader, 4, f, 12, true))
        return;
    const int readStart = ctx.u16(1);
    const int readQuantity = ctx.u16(3);
    const int writeStart = ctx.u16(5);
    const int writeQuantity = ctx.u16(7);
    checkQuantity(ctx, f[1], readQuantity, kMaxRead, "read quantity");
    checkRange(ctx, f[1], readStart, readQuantity, "read quantity");
    checkQuantity(ctx, f[3], writeQuantity, kMaxWrite, "write quantity");
    checkRange(ctx, f[3], writeStart, writeQuantity, "write quantity");
    if (!ctx.has(9)) {
        missing(ctx, ctx.parent, 9, 10 + qMax(2 * writeQuantity, 2), writeQuantity < 1,
                "byte count and write register values");
        return;
    }
    const int byteCount = ctx.byte(9);
    const int bc = ctx.add("modbus.byte_count", "Write byte count", 9, 1, quint64(byteCount), ValueFormat::Decimal);
    if (byteCount != 2 * writeQuantity) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 does not match write quantity %2, which needs %3 "
                                     "(2 per register)")
                          .arg(QString::number(byteCount), QString::number(writeQuantity),
                               amount(2 * writeQuantity, "byte", "bytes")));
    }
    if (byteCount % 2 != 0) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is odd: registers are 2 bytes each").arg(byteCount));
    }
    registerBlock(ctx, ctx.parent, 10, 10, 10 + byteCount, "Register", writeStart);
    trailing(ctx, 10 + byteCount);
}

void response(const PduContext &ctx)
{
    if (!ctx.has(1)) {
        missing(ctx, ctx.parent, 1, 4, true, "byte count and read register values");
        return;
    }
    const int byteCount = ctx.byte(1);
    const int bc = ctx.add("modbus.byte_count", "Byte count", 1, 1, quint64(byteCount), ValueFormat::Decimal);
    const bool known = requestUsable(ctx, 5);
    const int quantity = known ? ctx.requestU16(3) : -1;
    if (known && byteCount != 2 * quantity) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 does not match the request: read quantity %2 needs %3 "
                                     "(2 per register)")
                          .arg(QString::number(byteCount), QString::number(quantity),
                               amount(2 * quantity, "byte", "bytes")));
    } else if (byteCount == 0 || byteCount > 2 * kMaxRead) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is out of range: a Read/Write Multiple Registers response "
                                     "carries 1-125 registers (2-250 bytes)")
                          .arg(byteCount));
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

void dissectReadWriteRegisters(const PduContext &ctx)
{
    if (isResponse(ctx))
        response(ctx);
    else
        request(ctx);
}

} // namespace mbscope::pdu
