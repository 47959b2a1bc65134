#include "adubuilder.h"

#include "checksum.h"
#include "hexformat.h"

#include <cstring>

namespace mbscope {

namespace {

constexpr int kMbapHeaderSize = 7; // transaction id, protocol id, length, unit id (TCP/IP V1.0b, 3.1.3)
constexpr char kHexDigits[] = "0123456789ABCDEF";

quint16 bigEndian16(QByteArrayView bytes, qsizetype at)
{
    return quint16(quint8(bytes[at]) << 8 | quint8(bytes[at + 1]));
}

// The serial framings' payload: unit id then PDU, with room for the check bytes after it.
QByteArray unitAndPdu(QByteArrayView pdu, quint8 unitId, qsizetype room)
{
    QByteArray out;
    out.reserve(1 + pdu.size() + room);
    out.append(char(unitId));
    out.append(pdu.data(), pdu.size());
    return out;
}

void appendHexByte(QByteArray &out, quint8 value)
{
    out.append(kHexDigits[value >> 4]);
    out.append(kHexDigits[value & 0x0F]);
}

} // namespace

int AduBuilder::hexDigitValue(char c)
{
    return mbscope::hexDigitValue(c);
}

QByteArray AduBuilder::mbap(QByteArrayView pdu, quint8 unitId, quint16 transactionId, quint16 protocolId)
{
    // Written in place (one allocation, no append per byte): the simulator frames every answer here.
    QByteArray out(kMbapHeaderSize + pdu.size(), Qt::Uninitialized);
    char *p = out.data();
    // The length field counts the unit id and the PDU (TCP/IP V1.0b, 3.1.3).
    const quint16 length = quint16(qMin<qsizetype>(pdu.size() + 1, 0xFFFF));
    for (const quint16 field : {transactionId, protocolId, length}) {
        *p++ = char(field >> 8);
        *p++ = char(field & 0xFF);
    }
    *p++ = char(unitId);
    if (!pdu.isEmpty())
        std::memcpy(p, pdu.data(), size_t(pdu.size()));
    return out;
}

QByteArray AduBuilder::rtu(QByteArrayView pdu, quint8 unitId)
{
    QByteArray out = unitAndPdu(pdu, unitId, 2);
    // Serial Line V1.02, 6.2.2: the CRC is sent low-order byte first.
    const quint16 crc = checksum::crc16Modbus(out);
    out.append(char(crc & 0xFF));
    out.append(char(crc >> 8));
    return out;
}

QByteArray AduBuilder::ascii(QByteArrayView pdu, quint8 unitId)
{
    const QByteArray binary = unitAndPdu(pdu, unitId, 0);
    // Serial Line V1.02, 2.5.2.1: the LRC is computed over the binary bytes, then sent as two digits.
    const quint8 lrc = checksum::lrc(binary);
    QByteArray out;
    out.reserve(2 * binary.size() + 5);
    out.append(':');
    for (char c : binary)
        appendHexByte(out, quint8(c));
    appendHexByte(out, lrc);
    out.append("\r\n", 2);
    return out;
}

QByteArray AduBuilder::complete(QByteArrayView pdu, const AduOptions &options)
{
    switch (options.framing) {
    case Framing::Tcp:
    case Framing::Udp:
        return mbap(pdu, options.unitId, options.transactionId, options.protocolId);
    case Framing::Rtu:
        return rtu(pdu, options.unitId);
    case Framing::Ascii:
        return ascii(pdu, options.unitId);
    case Framing::Pdu:
    case Framing::Auto:
        break;
    }
    return pdu.toByteArray();
}

QByteArray AduBuilder::outgoing(QByteArrayView bytes, Completion completion, const AduOptions &options)
{
    if (completion == Completion::AsGiven)
        return bytes.toByteArray();
    return complete(bytes, options);
}

AduParts AduBuilder::parseMbap(QByteArrayView adu)
{
    AduParts parts;
    parts.framing = Framing::Tcp;
    const qsizetype size = adu.size();
    if (size >= 2)
        parts.transactionId = bigEndian16(adu, 0);
    if (size >= 4)
        parts.protocolId = bigEndian16(adu, 2);
    if (size >= 6)
        parts.length = bigEndian16(adu, 4);
    if (size >= 7)
        parts.unitId = quint8(adu[6]);
    if (size > kMbapHeaderSize)
        parts.pdu = adu.sliced(kMbapHeaderSize).toByteArray();
    parts.lengthMatches = size >= 6 && parts.length == size - 6;
    parts.complete = size > kMbapHeaderSize;
    if (!parts.complete) {
        parts.error = QStringLiteral("an MBAP frame needs its 7-byte header and a function code (8 bytes), "
                                     "only %1 present").arg(size);
    } else if (!parts.lengthMatches) {
        parts.error = QStringLiteral("length field %1 counts %1 bytes after it but %2 are present")
                          .arg(parts.length).arg(size - 6);
    }
    return parts;
}

AduParts AduBuilder::parseRtu(QByteArrayView adu)
{
    AduParts parts;
    parts.framing = Framing::Rtu;
    const qsizetype size = adu.size();
    if (size >= 1)
        parts.unitId = quint8(adu[0]);
    // Serial Line V1.02, 2.5.1: unit id, function code, data, CRC: at least 4 bytes.
    parts.complete = size >= 4;
    if (!parts.complete) {
        if (size > 1)
            parts.pdu = adu.sliced(1).toByteArray();
        parts.error = QStringLiteral("an RTU frame needs a unit id, a function code and a 2-byte CRC "
                                     "(4 bytes), only %1 present").arg(size);
        return parts;
    }
    parts.pdu = adu.sliced(1, size - 3).toByteArray();
    parts.checksumPresent = true;
    parts.checksum = quint16(quint8(adu[size - 2]) | quint8(adu[size - 1]) << 8);
    parts.expectedChecksum = checksum::crc16Modbus(adu.first(size - 2));
    return parts;
}

AduParts AduBuilder::parseAscii(QByteArrayView adu)
{
    AduParts parts;
    parts.framing = Framing::Ascii;
    const qsizetype size = adu.size();
    if (size == 0 || adu[0] != ':') {
        parts.error = QStringLiteral("an ASCII frame starts with ':'");
        return parts;
    }
    const bool hasEnd = size >= 3 && adu[size - 2] == '\r' && adu[size - 1] == '\n';
    const qsizetype digitsEnd = hasEnd ? size - 2 : size;
    QByteArray binary;
    binary.reserve((digitsEnd - 1) / 2);
    QString digitError;
    qsizetype at = 1;
    for (; at + 1 < digitsEnd; at += 2) {
        const int high = hexDigitValue(adu[at]);
        const int low = hexDigitValue(adu[at + 1]);
        if (high < 0 || low < 0) {
            const qsizetype bad = high < 0 ? at : at + 1;
            digitError = QStringLiteral("character %1 (%2) is not a hex digit")
                             .arg(bad)
                             .arg(hexByte(quint8(adu[bad])));
            break;
        }
        binary.append(char(high << 4 | low));
    }
    if (digitError.isEmpty() && at < digitsEnd) {
        digitError = hexDigitValue(adu[at]) < 0
            ? QStringLiteral("character %1 (%2) is not a hex digit").arg(at).arg(hexByte(quint8(adu[at])))
            : QStringLiteral("odd number of hex digits (%1)").arg(digitsEnd - 1);
    }

    if (!binary.isEmpty())
        parts.unitId = quint8(binary[0]);
    const bool wellFormed = digitError.isEmpty();
    if (wellFormed && binary.size() >= 2) {
        // The last byte is the LRC over everything before it (Serial Line V1.02, 2.5.2.1).
        parts.pdu = binary.sliced(1, binary.size() - 2);
        parts.checksumPresent = true;
        parts.checksum = quint8(binary.back());
        parts.expectedChecksum = checksum::lrc(QByteArrayView(binary).first(binary.size() - 1));
    } else if (binary.size() > 1) {
        parts.pdu = binary.sliced(1);
    }
    parts.complete = wellFormed && hasEnd && binary.size() >= 3;
    if (!wellFormed)
        parts.error = digitError;
    else if (!hasEnd)
        parts.error = QStringLiteral("an ASCII frame ends with CR LF");
    else if (binary.size() < 3)
        parts.error = QStringLiteral("an ASCII frame needs a unit id, a function code and an LRC "
                                     "(6 hex digits), only %1 present").arg(digitsEnd - 1);
    return parts;
}

AduParts AduBuilder::parse(QByteArrayView adu, Framing framing)
{
    switch (framing) {
    case Framing::Tcp:
    case Framing::Udp: {
        AduParts parts = parseMbap(adu);
        parts.framing = framing;
        return parts;
    }
    case Framing::Rtu:
        return parseRtu(adu);
    case Framing::Ascii:
        return parseAscii(adu);
    case Framing::Pdu:
    case Framing::Auto:
        break;
    }
    AduParts parts;
    parts.framing = Framing::Pdu;
    parts.pdu = adu.toByteArray();
    parts.complete = !adu.isEmpty();
    if (!parts.complete)
        parts.error = QStringLiteral("a PDU needs at least a function code");
    return parts;
}

} // namespace mbscope
