// 16 Mask Write Register and 18 Read FIFO Queue (MODBUS Application Protocol Specification
// V1.1b3, 6.16 and 6.18).
#include "pduchecks.h"
#include "quantitylimits.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

constexpr int kMaxFifo = QuantityLimits::kFifoValues; // V1.1b3 6.18

const Slot kMask[] = {
    {"modbus.address", QT_TRANSLATE_NOOP("mbscope::Field", "Reference address"), 2, ValueFormat::DecimalHex, "reference address, AND mask and OR mask"},
    {"modbus.and_mask", QT_TRANSLATE_NOOP("mbscope::Field", "AND mask"), 2, ValueFormat::Hex, "AND mask and OR mask"},
    {"modbus.or_mask", QT_TRANSLATE_NOOP("mbscope::Field", "OR mask"), 2, ValueFormat::Hex, "OR mask"},
};

const Slot kFifoRequest[] = {
    {"modbus.fifo_address", QT_TRANSLATE_NOOP("mbscope::Field", "FIFO pointer address"), 2, ValueFormat::DecimalHex, "FIFO pointer address"},
};

} // namespace

void dissectMaskWriteRegister(const PduContext &ctx)
{
    const int first = ctx.tree.size();
    int f[3];
    if (addFixed(ctx, ctx.parent, 1, kMask, 3, f, 7, false)) {
        // V1.1b3, 6.16: Result = (Current Contents AND And_Mask) OR (Or_Mask AND (NOT And_Mask)).
        ctx.tree.setMeaning(f[1], QT_TRANSLATE_NOOP("mbscope::Field", "bits kept from the current contents (1 = keep)"));
        ctx.tree.setMeaning(f[2], QT_TRANSLATE_NOOP("mbscope::Field",
                                                    "bits set where the AND mask is 0: result = (current AND and_mask) OR "
                                                    "(or_mask AND NOT and_mask)"));
        if (ctx.u16(3) == 0xFFFF) {
            ctx.tree.flag(f[1], Severity::Info,
                          QStringLiteral("AND mask 0xFFFF keeps every bit: the register is left unchanged "
                                         "whatever the OR mask"));
        }
        trailing(ctx, 7);
    }
    if (isResponse(ctx) && requestUsable(ctx, 7))
        checkEcho(ctx, first, false);
}

void dissectReadFifoQueue(const PduContext &ctx)
{
    if (!isResponse(ctx)) {
        int f[1];
        if (addFixed(ctx, ctx.parent, 1, kFifoRequest, 1, f, 3, false))
            trailing(ctx, 3);
        return;
    }
    if (!ctx.has(1, 2)) {
        missing(ctx, ctx.parent, 1, 5, true, "byte count, FIFO count and FIFO values");
        return;
    }
    // The byte count is 2 bytes here and counts the FIFO count field plus the values.
    const int byteCount = ctx.u16(1);
    const int bc = ctx.add("modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 1, 2, quint64(byteCount), ValueFormat::Decimal);
    if (!ctx.has(3, 2)) {
        missing(ctx, ctx.parent, 3, byteCount >= 2 ? 3 + byteCount : 5, byteCount < 2, "FIFO count and FIFO values");
        return;
    }
    const int count = ctx.u16(3);
    const int fc = ctx.add("modbus.fifo_count", QT_TRANSLATE_NOOP("mbscope::Field", "FIFO count"), 3, 2, quint64(count), ValueFormat::Decimal);
    if (count > kMaxFifo) {
        ctx.tree.flag(fc, Severity::Error,
                      QStringLiteral("FIFO count %1 is out of range: a FIFO queue returns 0-31 values").arg(count));
    }
    if (byteCount != 2 + 2 * count) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 does not match FIFO count %2, which needs a byte count of %3 "
                                     "(2 for the FIFO count + 2 per value)")
                          .arg(QString::number(byteCount), QString::number(count), QString::number(2 + 2 * count)));
    }
    registerBlock(ctx, ctx.parent, 5, 3, 3 + byteCount, QT_TRANSLATE_NOOP("mbscope::Field", "FIFO entry"), -1);
    trailing(ctx, qMax(5, 3 + byteCount));
}

} // namespace mbscope::pdu
