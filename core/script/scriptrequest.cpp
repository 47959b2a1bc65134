#include "scriptrequest.h"

namespace mbscope {

namespace {

int word(const QByteArray &pdu, int at)
{
    if (at + 1 >= pdu.size())
        return -1;
    return quint8(pdu.at(at)) << 8 | quint8(pdu.at(at + 1));
}

// count bits from the packed bytes starting at at (V1.1b3 6.11: LSB of the first byte first).
QList<quint16> bits(const QByteArray &pdu, int at, int count)
{
    QList<quint16> out;
    for (int i = 0; i < count && at + i / 8 < pdu.size(); ++i)
        out.append((quint8(pdu.at(at + i / 8)) >> (i % 8)) & 1);
    return out;
}

QList<quint16> words(const QByteArray &pdu, int at, int count)
{
    QList<quint16> out;
    for (int i = 0; i < count && at + 2 * i + 1 < pdu.size(); ++i)
        out.append(quint16(word(pdu, at + 2 * i)));
    return out;
}

} // namespace

ScriptRequest ScriptRequest::fromPdu(const QByteArray &pdu)
{
    ScriptRequest r;
    r.pdu = pdu;
    if (pdu.isEmpty())
        return r;
    r.function = quint8(pdu.at(0));
    switch (r.function) {
    case 0x01: case 0x02: case 0x03: case 0x04:
        r.address = word(pdu, 1);
        r.quantity = word(pdu, 3);
        break;
    case 0x05: // FF00 is ON, 0000 OFF (V1.1b3 6.5)
        r.address = word(pdu, 1);
        r.quantity = 1;
        if (word(pdu, 3) >= 0)
            r.values.append(word(pdu, 3) == 0xFF00 ? 1 : 0);
        break;
    case 0x06:
        r.address = word(pdu, 1);
        r.quantity = 1;
        if (word(pdu, 3) >= 0)
            r.values.append(quint16(word(pdu, 3)));
        break;
    case 0x0F: // address, quantity, byte count, packed bits (V1.1b3 6.11)
        r.address = word(pdu, 1);
        r.quantity = word(pdu, 3);
        r.values = bits(pdu, 6, std::max(0, r.quantity));
        break;
    case 0x10: // address, quantity, byte count, registers (V1.1b3 6.12)
        r.address = word(pdu, 1);
        r.quantity = word(pdu, 3);
        r.values = words(pdu, 6, std::max(0, r.quantity));
        break;
    case 0x16: // address, AND mask, OR mask (V1.1b3 6.16)
        r.address = word(pdu, 1);
        r.quantity = 1;
        r.values = words(pdu, 3, 2);
        break;
    case 0x17: // read address, read quantity, write address, write quantity, byte count, registers (6.17)
        r.address = word(pdu, 1);
        r.quantity = word(pdu, 3);
        r.writeAddress = word(pdu, 5);
        r.values = words(pdu, 10, std::max(0, word(pdu, 7)));
        break;
    default:
        break;
    }
    return r;
}

} // namespace mbscope
