#include "adudissectors.h"

#include "checksum.h"
#include "hexformat.h"
#include "pdudissector.h"
#include "pdusize.h"

namespace mbscope::adu {

namespace {

// MODBUS over Serial Line v1.02, 2.2: 0 is the broadcast address, 1-247 are server addresses
// and 248-255 are reserved.
void addUnit(FieldTree &tree, const char *key, int offset, int length, quint8 unit, Direction direction,
             const RequestInfo &request)
{
    const char *meaning = unit == 0 ? QT_TRANSLATE_NOOP("mbscope::Field", "broadcast") : (unit >= 248 ? QT_TRANSLATE_NOOP("mbscope::Field", "reserved address") : nullptr);
    const int u = tree.add(-1, key, QT_TRANSLATE_NOOP("mbscope::Field", "Unit id"), offset, length, unit, ValueFormat::Decimal, meaning);
    if (unit == 0 && direction == Direction::Response)
        tree.flag(u, Severity::Error, QStringLiteral("a response never comes from unit 0: it is the broadcast address and servers do not answer broadcasts"));
    else if (unit == 0)
        tree.flag(u, Severity::Info, QStringLiteral("broadcast: every server acts on it and none answers"));
    else if (unit >= 248)
        tree.flag(u, Severity::Warning, QStringLiteral("unit %1 is in the reserved range 248-255 (Serial Line v1.02, 2.2); servers use 1-247").arg(unit));
    if (request.unit >= 0 && direction == Direction::Response && request.unit != unit)
        tree.flag(u, Severity::Error, QStringLiteral("does not match the request, which was sent to unit %1").arg(request.unit));
}

} // namespace

void dissectRtu(Dissection &out, const RequestInfo &request, int frameCrc)
{
    FieldTree &tree = out.fields;
    const QByteArray &b = tree.frame();
    const int n = int(b.size());
    if (n == 0) {
        const int m = tree.add(-1, "frame.missing", QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes"), 0, 0);
        tree.flag(m, Severity::Error, QStringLiteral("the frame is empty: an RTU frame needs at least 4 bytes (unit id, function code, 2 CRC bytes)"));
        return;
    }
    addUnit(tree, "rtu.unit_id", 0, 1, quint8(b.at(0)), out.direction, request);
    if (n < 4) {
        pdu::dissect(PduContext{tree, -1, 1, n - 1, out.direction, request.pdu});
        const int m = tree.add(-1, "frame.missing", QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes"), n, 0);
        tree.flag(m, Severity::Error,
                  QStringLiteral("the frame is %1 bytes; an RTU frame needs at least 4 (unit id, function code, 2 CRC bytes)").arg(n));
        return;
    }

    // Where does the frame end? The last two bytes are taken as the CRC, unless the function's
    // length rule puts a valid CRC earlier, in which case what follows is trailing bytes.
    int frameEnd = n;
    const pdusize::Expected expected = pdusize::expectedPduSize(QByteArrayView(b).sliced(1), out.direction);
    const int predictedFrame = expected.status == pdusize::Status::Complete ? 1 + expected.size + 2 : -1;
    if (predictedFrame >= 4 && predictedFrame < n) {
        const quint16 atPredicted = quint16(quint8(b.at(predictedFrame - 2)) | (quint8(b.at(predictedFrame - 1)) << 8));
        if (checksum::crc16Modbus(QByteArrayView(b).first(predictedFrame - 2)) == atPredicted)
            frameEnd = predictedFrame;
    }
    const int crcAt = frameEnd - 2;
    pdu::dissect(PduContext{tree, -1, 1, crcAt - 1, out.direction, request.pdu});

    const quint16 sent = quint16(quint8(b.at(crcAt)) | (quint8(b.at(crcAt + 1)) << 8));
    const quint16 computed = crcAt == n - 2 && frameCrc >= 0 ? quint16(frameCrc)
                                                              : checksum::crc16Modbus(QByteArrayView(b).first(crcAt));
    const bool crcOk = sent == computed;
    const int c = tree.add(-1, "rtu.crc", QT_TRANSLATE_NOOP("mbscope::Field", "CRC"), crcAt, 2, sent, ValueFormat::Hex, crcOk ? QT_TRANSLATE_NOOP("mbscope::Field", "(valid)") : QT_TRANSLATE_NOOP("mbscope::Field", "(wrong)"));
    if (!crcOk) {
        tree.flag(c, Severity::Error,
                  QStringLiteral("CRC %1 does not match the %2 computed over bytes 0-%3; a correct frame ends %4 %5")
                      .arg(hexWord(sent), hexWord(computed)).arg(crcAt - 1)
                      .arg(hexDigits(computed & 0xFF, 2),
                           hexDigits(computed >> 8, 2)));
    }

    if (frameEnd < n) {
        const int t = tree.add(-1, "frame.trailing", QT_TRANSLATE_NOOP("mbscope::Field", "Trailing bytes"), frameEnd, n - frameEnd, 0, ValueFormat::Bytes);
        tree.flag(t, Severity::Error,
                  QStringLiteral("%1 bytes after the end of the frame: the function's length rule and a valid CRC end it at byte %2")
                      .arg(n - frameEnd).arg(frameEnd));
    } else if (predictedFrame > n) {
        const int missing = predictedFrame - n;
        const int m = tree.add(-1, "frame.missing", QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes"), n, 0, quint64(missing), ValueFormat::Decimal);
        QString message = QStringLiteral("the frame is %1 bytes but its own length fields announce %2: %3 bytes are missing")
                              .arg(n).arg(predictedFrame).arg(missing);
        const int bc = tree.indexOf("modbus.byte_count");
        if (bc >= 0 && tree.at(bc).length > 0) {
            const int follow = n - (tree.at(bc).offset + tree.at(bc).length);
            message += QStringLiteral("; the byte count announces %1 data bytes but only %2 bytes follow it (%3 data + the 2 read as the CRC)")
                           .arg(tree.at(bc).value).arg(follow).arg(qMax(0, follow - 2));
        } else {
            message += QStringLiteral(" (the last 2 bytes present were read as the CRC)");
        }
        tree.flag(m, Severity::Error, message);
    } else if (predictedFrame >= 4 && predictedFrame < n && !crcOk) {
        const int extra = n - predictedFrame;
        const int m = tree.add(-1, "frame.trailing", QT_TRANSLATE_NOOP("mbscope::Field", "Extra bytes"), predictedFrame, 0, quint64(extra), ValueFormat::Decimal);
        tree.flag(m, Severity::Error,
                  QStringLiteral("the frame is %1 bytes but its own length fields announce %2: %3 bytes too many, and no valid CRC at byte %4")
                      .arg(n).arg(predictedFrame).arg(extra).arg(predictedFrame - 2));
    }
}

} // namespace mbscope::adu
