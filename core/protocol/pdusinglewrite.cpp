// 05 Write Single Coil and 06 Write Single Register (MODBUS Application Protocol Specification
// V1.1b3, 6.5 and 6.6): address + value in the request, and the same four bytes echoed in the
// normal response.
#include "pduchecks.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

namespace {

const Slot kCoil[] = {
    {"modbus.address", QT_TRANSLATE_NOOP("mbscope::Field", "Output address"), 2, ValueFormat::DecimalHex, "output address and output value"},
    {"modbus.value", QT_TRANSLATE_NOOP("mbscope::Field", "Output value"), 2, ValueFormat::Hex, "output value"},
};

const Slot kRegister[] = {
    {"modbus.address", QT_TRANSLATE_NOOP("mbscope::Field", "Register address"), 2, ValueFormat::DecimalHex, "register address and register value"},
    {"modbus.value", QT_TRANSLATE_NOOP("mbscope::Field", "Register value"), 2, ValueFormat::Decimal, "register value"},
};

} // namespace

void dissectWriteSingleCoil(const PduContext &ctx)
{
    const int first = ctx.tree.size();
    int f[2];
    if (addFixed(ctx, ctx.parent, 1, kCoil, 2, f, 5, false)) {
        // V1.1b3, 6.5: 0xFF00 requests ON, 0x0000 OFF; every other value is illegal.
        const quint16 value = ctx.u16(3);
        if (value == 0xFF00) {
            ctx.tree.setMeaning(f[1], QT_TRANSLATE_NOOP("mbscope::Field", "ON"));
        } else if (value == 0x0000) {
            ctx.tree.setMeaning(f[1], QT_TRANSLATE_NOOP("mbscope::Field", "OFF"));
        } else {
            ctx.tree.setMeaning(f[1], QT_TRANSLATE_NOOP("mbscope::Field", "illegal (neither ON nor OFF)"));
            ctx.tree.flag(f[1], Severity::Error,
                          QStringLiteral("output value %1 is not allowed: Write Single Coil takes 0xFF00 (ON) "
                                         "or 0x0000 (OFF)")
                              .arg(hexWord(value)));
        }
        trailing(ctx, 5);
    }
    if (isResponse(ctx) && requestUsable(ctx, 5))
        checkEcho(ctx, first, false);
}

void dissectWriteSingleRegister(const PduContext &ctx)
{
    const int first = ctx.tree.size();
    int f[2];
    if (addFixed(ctx, ctx.parent, 1, kRegister, 2, f, 5, false))
        trailing(ctx, 5);
    if (isResponse(ctx) && requestUsable(ctx, 5))
        checkEcho(ctx, first, false);
}

} // namespace mbscope::pdu
