// Function 11 (17) Report Server ID (MODBUS Application Protocol Specification V1.1b3, 6.13),
// serial line only. The request carries no data; the response carries a byte count, the server
// ID, the run indicator status and device-specific additional data.
//
// The spec leaves the server ID's length device specific. mbscope shows it as one byte, the
// layout of libmodbus, FreeModbus and Wireshark; a run indicator that is neither 0x00 nor 0xFF
// then says either a bad status or a longer server ID, and the message says both.
//
// Keys: modbus.byte_count (Decimal), modbus.server_id (Bytes), modbus.run_indicator (Hex, ON/OFF),
// modbus.additional_data (Bytes).
#include "pdudissector.h"

#include "pdudiagfields.h"

namespace mbscope::pdu {

using namespace diag;

void dissectReportServerId(const PduContext &ctx)
{
    ctx.tree.flag(functionField(ctx), Severity::Info,
                  QStringLiteral("serial line only: V1.1b3 6.13 defines Report Server ID for serial line devices"));
    if (!isResponse(ctx)) {
        addTrailing(ctx, 1);
        return;
    }
    const int bc = addFixed(ctx, 1, 1, "modbus.byte_count", "Byte count", ValueFormat::Decimal);
    if (!ctx.has(1))
        return;
    const int count = ctx.byte(1);
    const int present = ctx.length - 2;
    if (count < 2) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 is too small: the server ID and the run indicator take at least 2 bytes")
                          .arg(count));
    }
    if (count > present) {
        ctx.tree.flag(bc, Severity::Error,
                      QStringLiteral("byte count %1 announces %1 data bytes but only %2 are present").arg(count).arg(present));
    }
    addFixed(ctx, 2, 1, "modbus.server_id", "Server ID", ValueFormat::Bytes);
    if (!ctx.has(2))
        return;
    const int r = addFixed(ctx, 3, 1, "modbus.run_indicator", "Run indicator status", ValueFormat::Hex);
    if (!ctx.has(3))
        return;
    const quint8 run = ctx.byte(3);
    if (run == 0x00) {
        ctx.tree.setMeaning(r, "OFF");
    } else if (run == 0xFF) {
        ctx.tree.setMeaning(r, "ON");
    } else {
        ctx.tree.flag(r, Severity::Error,
                      QStringLiteral("%1 is not a run indicator status (0x00 OFF, 0xFF ON); if this device's server ID "
                                     "is longer than one byte, this byte is part of it").arg(hexByte(run)));
    }
    const int end = qMin(2 + qMax(count, 2), ctx.length);
    if (end > 4)
        ctx.add("modbus.additional_data", "Additional data", 4, end - 4, 0, ValueFormat::Bytes);
    addTrailing(ctx, 2 + qMax(count, 2));
}

} // namespace mbscope::pdu
