#include "adudissectors.h"

#include "pdudissector.h"

namespace mbscope::adu {

// MODBUS Messaging on TCP/IP v1.0b, 3.1.3: the MBAP header is transaction id (2), protocol id
// (2, 0 for Modbus), length (2: the bytes that follow, unit id included) and unit id (1).
// The PDU is at most 253 bytes, so length runs 2-254.
void dissectMbap(Dissection &out, const RequestInfo &request)
{
    FieldTree &tree = out.fields;
    const QByteArray &b = tree.frame();
    const int n = int(b.size());
    auto u16 = [&b](int at) { return quint16((quint8(b.at(at)) << 8) | quint8(b.at(at + 1))); };

    if (n < 8) {
        // Show what there is of the header, then say what is missing.
        if (n >= 2)
            tree.add(-1, "mbap.transaction_id", QT_TRANSLATE_NOOP("mbscope::Field", "Transaction id"), 0, 2, u16(0), ValueFormat::Decimal);
        if (n >= 4)
            tree.add(-1, "mbap.protocol_id", QT_TRANSLATE_NOOP("mbscope::Field", "Protocol id"), 2, 2, u16(2), ValueFormat::Decimal);
        if (n >= 6)
            tree.add(-1, "mbap.length", QT_TRANSLATE_NOOP("mbscope::Field", "Length"), 4, 2, u16(4), ValueFormat::Decimal);
        if (n >= 7)
            tree.add(-1, "mbap.unit_id", QT_TRANSLATE_NOOP("mbscope::Field", "Unit id"), 6, 1, quint8(b.at(6)), ValueFormat::Decimal);
        const int m = tree.add(-1, "frame.missing", QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes"), n, 0, quint64(8 - n), ValueFormat::Decimal);
        tree.flag(m, Severity::Error,
                  QStringLiteral("the frame is %1 bytes; a Modbus TCP frame needs at least 8 (7-byte MBAP header and a function code)").arg(n));
        return;
    }

    const int tid = tree.add(-1, "mbap.transaction_id", QT_TRANSLATE_NOOP("mbscope::Field", "Transaction id"), 0, 2, u16(0), ValueFormat::Decimal);
    if (request.transactionId >= 0 && out.direction == Direction::Response && request.transactionId != u16(0))
        tree.flag(tid, Severity::Error, QStringLiteral("does not match the request's transaction id %1").arg(request.transactionId));

    const int pid = tree.add(-1, "mbap.protocol_id", QT_TRANSLATE_NOOP("mbscope::Field", "Protocol id"), 2, 2, u16(2), ValueFormat::Decimal,
                             u16(2) == 0 ? QT_TRANSLATE_NOOP("mbscope::Field", "Modbus") : nullptr);
    if (u16(2) != 0)
        tree.flag(pid, Severity::Error, QStringLiteral("protocol id %1 is not Modbus: the MBAP header carries 0 for Modbus").arg(u16(2)));

    const int announced = u16(4);
    const int present = n - 6;
    const int len = tree.add(-1, "mbap.length", QT_TRANSLATE_NOOP("mbscope::Field", "Length"), 4, 2, quint64(announced), ValueFormat::Decimal);
    if (announced < 2 || announced > 254)
        tree.flag(len, Severity::Error,
                  QStringLiteral("length %1 is out of range: it counts the unit id and the PDU, 2-254 bytes").arg(announced));
    else if (announced != present)
        tree.flag(len, Severity::Error,
                  QStringLiteral("length %1 announces %1 bytes after it (unit id and PDU) but %2 are present").arg(announced).arg(present));

    const quint8 unit = quint8(b.at(6));
    const int u = tree.add(-1, "mbap.unit_id", QT_TRANSLATE_NOOP("mbscope::Field", "Unit id"), 6, 1, unit, ValueFormat::Decimal,
                           unit == 0xFF ? QT_TRANSLATE_NOOP("mbscope::Field", "no unit behind a gateway (0xFF is the usual value for a direct TCP server)")
                                        : (unit == 0 ? QT_TRANSLATE_NOOP("mbscope::Field", "direct or broadcast") : nullptr));
    if (request.unit >= 0 && out.direction == Direction::Response && request.unit != unit)
        tree.flag(u, Severity::Error, QStringLiteral("does not match the request, which was sent to unit %1").arg(request.unit));

    const int pduEnd = (announced >= 2 && announced <= 254) ? qMin(n, 6 + announced) : n;
    pdu::dissect(PduContext{tree, -1, 7, pduEnd - 7, out.direction, request.pdu});

    if (pduEnd < n) {
        const int t = tree.add(-1, "frame.trailing", QT_TRANSLATE_NOOP("mbscope::Field", "Trailing bytes"), pduEnd, n - pduEnd, 0, ValueFormat::Bytes);
        tree.flag(t, Severity::Error,
                  QStringLiteral("%1 bytes after the %2 the length field announces; on a stream they would start the next frame")
                      .arg(n - pduEnd).arg(announced));
    } else if (6 + announced > n && announced <= 254) {
        const int missing = 6 + announced - n;
        const int m = tree.add(-1, "frame.missing", QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes"), n, 0, quint64(missing), ValueFormat::Decimal);
        tree.flag(m, Severity::Error,
                  QStringLiteral("the length field announces a %1-byte frame but %2 bytes are present: %3 missing")
                      .arg(6 + announced).arg(n).arg(missing));
    }
}

void dissectBarePdu(Dissection &out, const RequestInfo &request)
{
    pdu::dissect(PduContext{out.fields, -1, 0, int(out.fields.frame().size()), out.direction, request.pdu});
}

} // namespace mbscope::adu
