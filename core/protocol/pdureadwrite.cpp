// 17 Read/Write Multiple Registers (MODBUS Application Protocol Specification V1.1b3, 6.17):
// the request carries a read block (start, quantity 1-125) and a write block (start, quantity
// 1-121, byte count, values); the response carries the registers read.
#include "pduchecks.h"
#include "quantitylimits.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

constexpr int kMaxRead = QuantityLimits::kReadRegisters;
constexpr int kMaxWrite = QuantityLimits::kReadWriteWrite;

const Slot kHeader[] = {
    {"modbus.read_start_address", QT_TRANSLATE_NOOP("mbscope::Field", "Read start address"), 2, ValueFormat::DecimalHex,
     "read start address, read quantity, write start address, write quantity, byte count and write values"},
    {"modbus.read_quantity", QT_TRANSLATE_NOOP("mbscope::Field", "Quantity to read"), 2, ValueFormat::Decimal,
     "read quantity, write start address, write quantity, byte count and write values"},
    {"modbus.write_start_address", QT_TRANSLATE_NOOP("mbscope::Field", "Write start address"), 2, ValueFormat::DecimalHex,
     "write start address, write quantity, byte count and write values"},
    {"modbus.write_quantity", QT_TRANSLATE_NOOP("mbscope::Field", "Quantity to write"), 2, ValueFormat::Decimal,
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
    checkBlock(ctx, f[1], readStart, readQuantity, kMaxRead, "read quantity");
    checkBlock(ctx, f[3], writeStart, writeQuantity, kMaxWrite, "write quantity");
    if (!ctx.has(9)) {
        missing(ctx, ctx.parent, 9, 10 + qMax(2 * writeQuantity, 2), writeQuantity < 1,
                "byte count and write register values");
        return;
    }
    const int byteCount = ctx.byte(9);
    const int bc = ctx.add("modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Write byte count"), 9, 1, quint64(byteCount), ValueFormat::Decimal);
    checkByteCount(ctx, bc, byteCount, 2 * writeQuantity, "write quantity", writeQuantity, false, "2 per register");
    checkEvenByteCount(ctx, bc, byteCount);
    registerBlock(ctx, ctx.parent, 10, 10, 10 + byteCount, "Register", writeStart);
    trailing(ctx, 10 + byteCount);
}

} // namespace

void dissectReadWriteRegisters(const PduContext &ctx)
{
    if (isResponse(ctx))
        registerReadResponse(ctx, "read quantity", "byte count and read register values");
    else
        request(ctx);
}

} // namespace mbscope::pdu
