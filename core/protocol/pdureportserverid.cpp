// Function 11 (17) Report Server ID (MODBUS Application Protocol Specification V1.1b3, 6.13),
// serial line only. The request carries no data; the response carries a byte count, the server
// ID, the run indicator status and device-specific additional data.
//
// The spec leaves the server ID's length device specific. mbscope shows it as one byte, the
// layout of libmodbus, FreeModbus and Wireshark, unless byte 3 is no run indicator status and the
// last byte is one: then the server ID runs up to the last byte (pymodbus' layout). Otherwise a
// run indicator that is neither 0x00 nor 0xFF gets a warning that says both readings.
//
// Keys: modbus.byte_count (Decimal), modbus.server_id (Bytes), modbus.run_indicator (Hex, ON/OFF),
// modbus.additional_data (Bytes).
#include "pduchecks.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

void dissectReportServerId(const PduContext &ctx)
{
    if (!serialLineResponse(
            ctx, QStringLiteral("serial line only: V1.1b3 6.13 defines Report Server ID for serial line devices")))
        return;
    static const Slot layout[] = {
        {"modbus.byte_count", QT_TRANSLATE_NOOP("mbscope::Field", "Byte count"), 1, ValueFormat::Decimal, "byte count, server ID and run indicator status"},
        {"modbus.server_id", QT_TRANSLATE_NOOP("mbscope::Field", "Server ID"), 1, ValueFormat::Bytes, "server ID and run indicator status"},
        {"modbus.run_indicator", QT_TRANSLATE_NOOP("mbscope::Field", "Run indicator status"), 1, ValueFormat::Hex, "run indicator status"},
    };
    int f[3] = {-1, -1, -1};
    const int end = countedFields(ctx, layout, 3, f, "the server ID and the run indicator take at least 2 bytes");
    if (end < 0)
        return;
    const int r = f[2];
    const int present = qMin(end, ctx.length);
    const quint8 run = ctx.byte(3);
    // Devices with a longer server ID (pymodbus sends its identity text) put the run indicator
    // last: when byte 3 is no status but the last byte is, read the frame that way and say so.
    const quint8 last = present > 4 ? ctx.byte(present - 1) : run;
    int additionalFrom = 4;
    if (run != 0x00 && run != 0xFF && present > 4 && (last == 0x00 || last == 0xFF)) {
        ctx.tree.setSpan(f[1], ctx.offset + 2, present - 3);
        ctx.tree.setSpan(r, ctx.offset + present - 1, 1);
        ctx.tree.setValue(r, last);
        ctx.tree.flag(f[1], Severity::Info,
                      QStringLiteral("a %1-byte server ID: the run indicator status is read from the last byte "
                                     "(V1.1b3 6.13 leaves the server ID's length to the device)").arg(present - 3));
        ctx.tree.setMeaning(r, last == 0xFF ? QT_TRANSLATE_NOOP("mbscope::Field", "ON") : QT_TRANSLATE_NOOP("mbscope::Field", "OFF"));
        additionalFrom = present;
    } else if (run == 0x00) {
        ctx.tree.setMeaning(r, QT_TRANSLATE_NOOP("mbscope::Field", "OFF"));
    } else if (run == 0xFF) {
        ctx.tree.setMeaning(r, QT_TRANSLATE_NOOP("mbscope::Field", "ON"));
    } else {
        ctx.tree.flag(r, Severity::Warning,
                      QStringLiteral("%1 is not a run indicator status (0x00 OFF, 0xFF ON); if this device's server ID "
                                     "is longer than one byte, this byte is part of it").arg(hexByte(run)));
    }
    if (present > additionalFrom)
        ctx.add("modbus.additional_data", QT_TRANSLATE_NOOP("mbscope::Field", "Additional data"), additionalFrom, present - additionalFrom, 0, ValueFormat::Bytes);
    countedEnd(ctx, end);
}

} // namespace mbscope::pdu
