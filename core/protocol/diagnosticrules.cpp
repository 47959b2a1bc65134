#include "diagnosticrules.h"

#include "pdubuilder.h"

namespace mbscope::diagnosticrules {

namespace {

QString spaced(const QByteArray &data)
{
    return QString::fromLatin1(data.toHex(' ').toUpper());
}

bool isZeroWord(const QByteArray &data)
{
    return data.size() == 2 && data.at(0) == 0 && data.at(1) == 0;
}

bool fail(PduBuilder &b, int subFunction, const QByteArray &data, const char *expected)
{
    b.addError(QStringLiteral("data"), QStringLiteral("data %1 is not allowed: %2 (sub-function %3) takes %4")
                                           .arg(data.isEmpty() ? QStringLiteral("(none)") : spaced(data),
                                                QString::fromLatin1(subFunctionName(subFunction)),
                                                PduBuilder::hex(subFunction, 4), QString::fromLatin1(expected)));
    return false;
}

} // namespace

const char *subFunctionName(int subFunction)
{
    switch (subFunction) {
    case 0x00: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Query Data");
    case 0x01: return QT_TRANSLATE_NOOP("mbscope::Field", "Restart Communications Option");
    case 0x02: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Diagnostic Register");
    case 0x03: return QT_TRANSLATE_NOOP("mbscope::Field", "Change ASCII Input Delimiter");
    case 0x04: return QT_TRANSLATE_NOOP("mbscope::Field", "Force Listen Only Mode");
    case 0x0A: return QT_TRANSLATE_NOOP("mbscope::Field", "Clear Counters and Diagnostic Register");
    case 0x0B: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Message Count");
    case 0x0C: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Communication Error Count");
    case 0x0D: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Exception Error Count");
    case 0x0E: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Server Message Count");
    case 0x0F: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Server No Response Count");
    case 0x10: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Server NAK Count");
    case 0x11: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Server Busy Count");
    case 0x12: return QT_TRANSLATE_NOOP("mbscope::Field", "Return Bus Character Overrun Count");
    case 0x14: return QT_TRANSLATE_NOOP("mbscope::Field", "Clear Overrun Counter and Flag");
    default: return nullptr;
    }
}

bool checkSubFunction(PduBuilder &b, int subFunction)
{
    if (!b.checkRange(QStringLiteral("subFunction"), QStringLiteral("sub-function"), subFunction, 0, 0xFFFF,
                      QStringLiteral("Diagnostics sub-functions are 16-bit, 0-65535"))) {
        return false;
    }
    if (subFunctionName(subFunction))
        return true;
    b.addError(QStringLiteral("subFunction"),
               QStringLiteral("sub-function %1 (%2) is reserved: Diagnostics defines 0x00-0x04, 0x0A-0x12 and 0x14 "
                              "(V1.1b3, 6.8.1)")
                   .arg(subFunction)
                   .arg(PduBuilder::hex(subFunction, 4)));
    return false;
}

bool checkData(PduBuilder &b, int subFunction, const QByteArray &data, Direction direction)
{
    const bool response = direction == Direction::Response;
    switch (subFunction) {
    case 0x00:
        // Any data, in whole 16-bit words ("Data N x 2 Bytes"); the response echoes it.
        if (data.size() % 2 != 0) {
            b.addError(QStringLiteral("data"),
                       QStringLiteral("data of %1 bytes is not allowed: Return Query Data (sub-function 0x0000) "
                                      "takes whole 16-bit words (N x 2 bytes)")
                           .arg(data.size()));
            return false;
        }
        return b.checkFits(QStringLiteral("data"), QStringLiteral("data"), data.size(), 2);
    case 0x01:
        if (data == QByteArray::fromHex("0000") || data == QByteArray::fromHex("FF00"))
            return true;
        return fail(b, subFunction, data, "00 00 (keep the event log) or FF 00 (clear it)");
    case 0x02:
        if (response ? data.size() == 2 : isZeroWord(data))
            return true;
        return fail(b, subFunction, data, response ? "the 2-byte diagnostic register" : "00 00");
    case 0x03:
        if (data.size() == 2 && data.at(1) == 0)
            return true;
        return fail(b, subFunction, data, "the delimiter character followed by 00 (CHAR 00)");
    case 0x04:
        if (response) {
            b.addError(QStringLiteral("subFunction"),
                       QStringLiteral("Force Listen Only Mode (sub-function 0x0004) has no response: the device "
                                      "enters Listen Only Mode and returns nothing (V1.1b3, 6.8.1)"));
            return false;
        }
        return isZeroWord(data) || fail(b, subFunction, data, "00 00");
    case 0x0A:
    case 0x14:
        return isZeroWord(data) || fail(b, subFunction, data, "00 00");
    default:
        // 0B-12: the request takes 00 00, the response returns the 16-bit counter.
        if (response ? data.size() == 2 : isZeroWord(data))
            return true;
        return fail(b, subFunction, data, response ? "the 2-byte counter value" : "00 00");
    }
}

BuildResult build(int subFunction, const QByteArray &data, Direction direction)
{
    PduBuilder b(0x08);
    if (checkSubFunction(b, subFunction))
        checkData(b, subFunction, data, direction);
    if (b.hasErrors())
        return b.finish();
    b.appendU16(subFunction);
    b.appendBytes(data);
    return b.finish();
}

} // namespace mbscope::diagnosticrules
