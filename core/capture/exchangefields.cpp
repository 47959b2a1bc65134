#include "exchangefields.h"
#include "protocol/framingtraits.h"

#include "protocol/adubuilder.h"

#include "protocol/hexnumber.h"

#include <QtCore/QStringList>

namespace mbscope {

namespace {

quint16 word(const QByteArray &pdu, qsizetype at)
{
    return quint16(quint8(pdu[at]) << 8 | quint8(pdu[at + 1]));
}

QString registers(const QByteArray &pdu, qsizetype at, qsizetype count)
{
    QString text;
    for (qsizetype i = 0; i < count && at + 2 * i + 1 < pdu.size(); ++i) {
        if (i > 0)
            text += QLatin1Char(' ');
        text += QString::number(word(pdu, at + 2 * i));
    }
    return text;
}

// Bits packed low bit first, eight to a byte (V1.1b3, 6.1).
QString bits(const QByteArray &pdu, qsizetype at, qsizetype count)
{
    QString text;
    for (qsizetype i = 0; i < count && at + i / 8 < pdu.size(); ++i) {
        if (i > 0)
            text += QLatin1Char(' ');
        text += (quint8(pdu[at + i / 8]) >> (i % 8)) & 1 ? QLatin1Char('1') : QLatin1Char('0');
    }
    return text;
}

} // namespace

QByteArray ExchangeFields::pduOf(const QByteArray &adu, Framing framing, quint8 *unit)
{
    if (framing == Framing::Auto)
        return {};
    // AduBuilder::parse reads every framing; a frame whose check is wrong still has its PDU.
    const AduParts parts = AduBuilder::parse(adu, framing);
    const bool whole = isSerialLine(framing) ? parts.checksumPresent : parts.complete;
    if (!whole || parts.pdu.isEmpty())
        return {};
    *unit = framing == Framing::Pdu ? 0 : parts.unitId;
    return parts.pdu;
}

ExchangeFields ExchangeFields::of(const Transaction &t, Framing framing)
{
    ExchangeFields f;
    quint8 unit = 0;
    const QByteArray request = pduOf(t.request, framing, &unit);
    quint8 answerUnit = 0;
    const QByteArray answer = pduOf(t.response, framing, &answerUnit);
    if (request.isEmpty()) {
        if (answer.isEmpty())
            return f;
        f.valid = true;
        f.unit = answerUnit;
        f.function = quint8(answer[0]) & 0x7f;
        f.exception = quint8(answer[0]) & 0x80;
        return f;
    }
    f.valid = true;
    f.unit = unit;
    f.function = quint8(request[0]);
    f.exception = !answer.isEmpty() && (quint8(answer[0]) & 0x80);
    const bool answered = !answer.isEmpty() && !f.exception && quint8(answer[0]) == f.function;
    const qsizetype n = request.size();
    switch (f.function) {
    case 0x01: case 0x02: case 0x03: case 0x04:
        if (n < 5)
            return f;
        f.hasAddress = true;
        f.address = word(request, 1);
        f.quantity = word(request, 3);
        if (answered && answer.size() >= 2) {
            const int count = quint8(answer[1]);
            if (f.function <= 0x02)
                f.values = bits(answer, 2, std::min<qsizetype>(f.quantity, count * 8));
            else
                f.values = registers(answer, 2, std::min<qsizetype>(f.quantity, count / 2));
        }
        return f;
    case 0x05:
        if (n < 5)
            return f;
        f.hasAddress = true;
        f.address = word(request, 1);
        f.quantity = 1;
        f.values = word(request, 3) == 0xff00 ? QStringLiteral("1") : word(request, 3) == 0 ? QStringLiteral("0")
                                                                     : QString::number(word(request, 3));
        return f;
    case 0x06:
        if (n < 5)
            return f;
        f.hasAddress = true;
        f.address = word(request, 1);
        f.quantity = 1;
        f.values = QString::number(word(request, 3));
        return f;
    case 0x0f:
    case 0x10:
        if (n < 6)
            return f;
        f.hasAddress = true;
        f.address = word(request, 1);
        f.quantity = word(request, 3);
        f.values = f.function == 0x0f ? bits(request, 6, f.quantity) : registers(request, 6, f.quantity);
        return f;
    case 0x16:
        if (n < 7)
            return f;
        f.hasAddress = true;
        f.address = word(request, 1);
        f.quantity = 1;
        f.values = QStringLiteral("and=0x%1 or=0x%2").arg(hexNumber(word(request, 3), 4)).arg(hexNumber(word(request, 5), 4));
        return f;
    case 0x17:
        if (n < 9)
            return f;
        f.hasAddress = true;
        f.address = word(request, 1);
        f.quantity = word(request, 3);
        if (answered && answer.size() >= 2)
            f.values = registers(answer, 2, std::min<qsizetype>(f.quantity, quint8(answer[1]) / 2));
        return f;
    default:
        return f;
    }
}

} // namespace mbscope
