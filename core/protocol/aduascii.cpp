#include "adudissectors.h"

#include "checksum.h"
#include "hexformat.h"
#include "pdudissector.h"

namespace mbscope::adu {

namespace {

QString charName(char c)
{
    const auto u = quint8(c);
    if (u >= 0x20 && u < 0x7F)
        return QStringLiteral("'%1'").arg(QLatin1Char(c));
    return hexByte(u);
}

} // namespace

// MODBUS over Serial Line v1.02, 2.5.2: ':' then each byte as two uppercase hex characters,
// the LRC likewise, then CR LF. Decoding stops at the first character that is not a hex digit.
bool decodeAsciiPayload(const QByteArray &frame, QByteArray &binary, QString *error, int *errorOffset)
{
    binary.clear();
    int begin = frame.startsWith(':') ? 1 : 0;
    int end = int(frame.size());
    if (frame.endsWith("\r\n"))
        end -= 2;
    for (int i = begin; i < end; i += 2) {
        const int hi = hexDigitValue(frame.at(i));
        if (hi < 0) {
            if (error)
                *error = QStringLiteral("character %1 (%2) is not a hex digit").arg(i + 1).arg(charName(frame.at(i)));
            if (errorOffset)
                *errorOffset = i;
            return false;
        }
        if (i + 1 >= end) {
            if (error)
                *error = QStringLiteral("odd number of hex digits: character %1 has no partner to make a byte").arg(i + 1);
            if (errorOffset)
                *errorOffset = i;
            return false;
        }
        const int lo = hexDigitValue(frame.at(i + 1));
        if (lo < 0) {
            if (error)
                *error = QStringLiteral("character %1 (%2) is not a hex digit").arg(i + 2).arg(charName(frame.at(i + 1)));
            if (errorOffset)
                *errorOffset = i + 1;
            return false;
        }
        binary.append(char((hi << 4) | lo));
    }
    return true;
}

void dissectAscii(Dissection &out, const RequestInfo &request)
{
    const QByteArray wire = out.fields.frame();
    QByteArray binary;
    QString decodeError;
    int errorOffset = -1;
    const bool decoded = decodeAsciiPayload(wire, binary, &decodeError, &errorOffset);
    out.note = QStringLiteral("ASCII frame: offsets count decoded bytes (unit id is byte 0); byte k is characters 2k+2 and 2k+3 of the frame");
    FieldTree &tree = out.fields;
    tree.reset(binary);

    if (!wire.startsWith(':')) {
        const int s = tree.add(-1, "ascii.start", QT_TRANSLATE_NOOP("mbscope::Field", "Start"), 0, 0);
        tree.flag(s, Severity::Error, QStringLiteral("an ASCII frame starts with ':' (0x3A); this one starts with %1")
                                          .arg(wire.isEmpty() ? QStringLiteral("nothing") : charName(wire.at(0))));
    }
    if (!decoded) {
        const int d = tree.add(-1, "ascii.text", QT_TRANSLATE_NOOP("mbscope::Field", "Frame text"), 0, 0);
        tree.flag(d, Severity::Error, decodeError + QStringLiteral("; the bytes before it are decoded below"));
    }
    const int m = int(binary.size());
    if (m == 0) {
        const int x = tree.add(-1, "frame.missing", QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes"), 0, 0);
        tree.flag(x, Severity::Error, QStringLiteral("no bytes: an ASCII frame holds at least unit id, function code and LRC as hex digits"));
    } else {
        const quint8 unit = quint8(binary.at(0));
        const int u = tree.add(-1, "ascii.unit_id", QT_TRANSLATE_NOOP("mbscope::Field", "Unit id"), 0, 1, unit, ValueFormat::Decimal,
                               unit == 0 ? QT_TRANSLATE_NOOP("mbscope::Field", "broadcast") : (unit >= 248 ? QT_TRANSLATE_NOOP("mbscope::Field", "reserved address") : nullptr));
        if (unit == 0 && out.direction == Direction::Response)
            tree.flag(u, Severity::Error, QStringLiteral("a response never comes from unit 0: it is the broadcast address"));
        else if (unit >= 248)
            tree.flag(u, Severity::Warning, QStringLiteral("unit %1 is in the reserved range 248-255; servers use 1-247").arg(unit));
        if (request.unit >= 0 && out.direction == Direction::Response && request.unit != unit)
            tree.flag(u, Severity::Error, QStringLiteral("does not match the request, which was sent to unit %1").arg(request.unit));
        if (m < 3) {
            pdu::dissect(PduContext{tree, -1, 1, m - 1, out.direction, request.pdu});
            const int x = tree.add(-1, "frame.missing", QT_TRANSLATE_NOOP("mbscope::Field", "Missing bytes"), m, 0);
            tree.flag(x, Severity::Error,
                      QStringLiteral("%1 bytes decoded; an ASCII frame needs at least 3 (unit id, function code, LRC)").arg(m));
        } else {
            pdu::dissect(PduContext{tree, -1, 1, m - 2, out.direction, request.pdu});
            const quint8 sent = quint8(binary.at(m - 1));
            const quint8 computed = checksum::lrc(QByteArrayView(binary).first(m - 1));
            const int l = tree.add(-1, "ascii.lrc", QT_TRANSLATE_NOOP("mbscope::Field", "LRC"), m - 1, 1, sent, ValueFormat::Hex, sent == computed ? QT_TRANSLATE_NOOP("mbscope::Field", "(valid)") : QT_TRANSLATE_NOOP("mbscope::Field", "(wrong)"));
            if (sent != computed)
                tree.flag(l, Severity::Error,
                          QStringLiteral("LRC %1 does not match the %2 computed over the decoded bytes 0-%3")
                              .arg(hexByte(sent), hexByte(computed))
                              .arg(m - 2));
        }
    }
    if (!wire.endsWith("\r\n")) {
        const int e = tree.add(-1, "ascii.end", QT_TRANSLATE_NOOP("mbscope::Field", "End"), m, 0);
        tree.flag(e, Severity::Error, QStringLiteral("an ASCII frame ends with CR LF (0x0D 0x0A); this one does not"));
    }
    bool lower = false;
    for (char c : wire)
        lower = lower || (c >= 'a' && c <= 'f');
    if (lower && m > 0) {
        const int first = 0;
        tree.flag(first, Severity::Warning, QStringLiteral("the frame uses lower-case hex digits; Serial Line v1.02, 2.5.2.1 specifies upper case"));
    }
}

} // namespace mbscope::adu
