// 01 Read Coils and 02 Read Discrete Inputs (MODBUS Application Protocol Specification V1.1b3,
// 6.1 and 6.2): request start address + quantity (1-2000); response byte count + packed bits.
#include "pduchecks.h"
#include "quantitylimits.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

constexpr int kMaxBits = QuantityLimits::kReadBits; // V1.1b3 6.1/6.2
constexpr int kMaxBytes = (kMaxBits + 7) / 8;

void response(const PduContext &ctx)
{
    const bool coils = ctx.function() == 0x01;
    if (!ctx.has(1)) {
        missing(ctx, ctx.parent, 1, 3, true, coils ? "byte count and coil status" : "byte count and input status");
        return;
    }
    const int byteCount = ctx.byte(1);
    const int bc = ctx.add("modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 1, 1, quint64(byteCount), ValueFormat::Decimal);
    const bool known = requestUsable(ctx, 5);
    const int quantity = known ? ctx.requestU16(3) : -1;
    const int start = known ? ctx.requestU16(1) : -1;
    const bool mismatched = known
        && checkByteCount(ctx, bc, byteCount, (quantity + 7) / 8, "quantity", quantity, true, "quantity / 8, rounded up");
    if (!mismatched && byteCount == 0) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count 0: a %1 response carries 1-%2 data bytes (1-2000 bits)")
                          .arg(functionLabel(ctx), QString::number(kMaxBytes)));
    } else if (!mismatched && byteCount > kMaxBytes) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is too large: a %2 response carries at most %3 data bytes "
                                     "(2000 bits)")
                          .arg(QString::number(byteCount), functionLabel(ctx), QString::number(kMaxBytes)));
    }
    const char *key = coils ? "modbus.coil_value" : "modbus.discrete_input_value";
    const char *name = known ? (coils ? QT_TRANSLATE_NOOP("mbscope::Field", "Coil") : QT_TRANSLATE_NOOP("mbscope::Field", "Discrete input")) : (coils ? QT_TRANSLATE_NOOP("mbscope::Field", "Coil index") : QT_TRANSLATE_NOOP("mbscope::Field", "Input index"));
    bitBlock(ctx, ctx.parent, 2, byteCount, quantity, key, name, start);
    trailing(ctx, 2 + byteCount);
}

} // namespace

void dissectReadBits(const PduContext &ctx)
{
    if (isResponse(ctx))
        response(ctx);
    else
        startAndQuantity(ctx, kMaxBits);
}

} // namespace mbscope::pdu
