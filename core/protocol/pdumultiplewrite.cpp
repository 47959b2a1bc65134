// 0F Write Multiple Coils and 10 Write Multiple Registers (MODBUS Application Protocol
// Specification V1.1b3, 6.11 and 6.12): request start address, quantity, byte count and the
// values; the normal response echoes start address and quantity.
#include "pduchecks.h"
#include "quantitylimits.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

constexpr int kMaxCoils = QuantityLimits::kWriteCoils;         // V1.1b3 6.11
constexpr int kMaxRegisters = QuantityLimits::kWriteRegisters; // V1.1b3 6.12

const Slot kCoilsHeader[] = {
    {"modbus.start_address", QT_TRANSLATE_NOOP("mbscope::Field", "Start address"), 2, ValueFormat::DecimalHex,
     "start address, quantity, byte count and coil values"},
    {"modbus.quantity", QT_TRANSLATE_NOOP("mbscope::Field", "Quantity"), 2, ValueFormat::Decimal, "quantity, byte count and coil values"},
};

const Slot kRegistersHeader[] = {
    {"modbus.start_address", QT_TRANSLATE_NOOP("mbscope::Field", "Start address"), 2, ValueFormat::DecimalHex,
     "start address, quantity, byte count and register values"},
    {"modbus.quantity", QT_TRANSLATE_NOOP("mbscope::Field", "Quantity"), 2, ValueFormat::Decimal, "quantity, byte count and register values"},
};

// The normal response of both codes: start address and quantity, checked against the request.
void echoResponse(const PduContext &ctx, int maxQuantity)
{
    const int first = ctx.tree.size();
    startAndQuantity(ctx, maxQuantity);
    if (requestUsable(ctx, 5))
        checkEcho(ctx, first, false);
}

// Adds and checks start address, quantity and byte count of a request; false when the PDU
// ends first. dataBytes is the byte count the quantity calls for.
bool requestHeader(const PduContext &ctx, const Slot *header, int *f, int maxQuantity, int dataBytes,
                   const char *what)
{
    if (!addFixed(ctx, ctx.parent, 1, header, 2, f, 7, true))
        return false;
    checkBlock(ctx, f[1], ctx.u16(1), ctx.u16(3), maxQuantity, "quantity");
    if (!ctx.has(5)) {
        missing(ctx, ctx.parent, 5, 6 + qMax(dataBytes, 1), dataBytes < 1, what);
        return false;
    }
    f[2] = ctx.add("modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 5, 1, ctx.byte(5), ValueFormat::Decimal);
    return true;
}

} // namespace

void dissectWriteMultipleCoils(const PduContext &ctx)
{
    if (isResponse(ctx)) {
        echoResponse(ctx, kMaxCoils);
        return;
    }
    const int quantity = ctx.has(3, 2) ? ctx.u16(3) : 0;
    const int needed = (quantity + 7) / 8;
    int f[3];
    if (!requestHeader(ctx, kCoilsHeader, f, kMaxCoils, needed, "byte count and coil values"))
        return;
    const int start = ctx.u16(1);
    const int byteCount = ctx.byte(5);
    checkByteCount(ctx, f[2], byteCount, needed, "quantity", quantity, false, "quantity / 8, rounded up");
    bitBlock(ctx, ctx.parent, 6, byteCount, quantity, "modbus.coil_value", "Coil", start);
    trailing(ctx, 6 + byteCount);
}

void dissectWriteMultipleRegisters(const PduContext &ctx)
{
    if (isResponse(ctx)) {
        echoResponse(ctx, kMaxRegisters);
        return;
    }
    const int quantity = ctx.has(3, 2) ? ctx.u16(3) : 0;
    int f[3];
    if (!requestHeader(ctx, kRegistersHeader, f, kMaxRegisters, 2 * quantity, "byte count and register values"))
        return;
    const int start = ctx.u16(1);
    const int byteCount = ctx.byte(5);
    checkByteCount(ctx, f[2], byteCount, 2 * quantity, "quantity", quantity, false, "2 per register");
    checkEvenByteCount(ctx, f[2], byteCount);
    registerBlock(ctx, ctx.parent, 6, 6, 6 + byteCount, "Register", start);
    trailing(ctx, 6 + byteCount);
}

} // namespace mbscope::pdu
