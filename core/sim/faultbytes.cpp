#include "sim/faultbytes.h"
#include "protocol/framingtraits.h"

#include "sim/simrandom.h"

#include "protocol/adubuilder.h"

#include <algorithm>

namespace mbscope {

namespace {

char hexDigit(int value)
{
    return "0123456789ABCDEF"[value & 0x0F];
}

} // namespace

QByteArray FaultBytes::rewrap(QByteArrayView adu, Framing framing, QByteArrayView pdu, quint8 unit)
{
    const AduParts parts = AduBuilder::parse(adu, framing);
    return AduBuilder::complete(pdu, AduOptions{framing, unit, parts.transactionId, parts.protocolId});
}

QByteArray FaultBytes::wrongChecksum(QByteArrayView adu, Framing framing)
{
    if (!isSerialLine(framing))
        return {};
    QByteArray out = adu.toByteArray();
    if (framing == Framing::Rtu) {
        if (out.size() < 4)
            return {};
        out[out.size() - 2] = char(~quint8(out.at(out.size() - 2)));
        out[out.size() - 1] = char(~quint8(out.at(out.size() - 1)));
        return out;
    }
    // ':' unit+PDU digits, two LRC digits, CR LF (Serial Line V1.02, 2.5.2.1).
    if (out.size() < 7)
        return {};
    const qsizetype at = out.size() - 4;
    const int high = AduBuilder::hexDigitValue(out.at(at));
    const int low = AduBuilder::hexDigitValue(out.at(at + 1));
    if (high < 0 || low < 0)
        return {};
    const quint8 lrc = quint8(~quint8(high << 4 | low));
    out[at] = hexDigit(lrc >> 4);
    out[at + 1] = hexDigit(lrc);
    return out;
}

QByteArray FaultBytes::wrongTransactionId(QByteArrayView adu, Framing framing, int delta)
{
    if (!framingTraits(framing).mbap || adu.size() < 7)
        return {};
    QByteArray out = adu.toByteArray();
    const quint16 tid = quint16((quint8(out.at(0)) << 8 | quint8(out.at(1))) + delta);
    out[0] = char(tid >> 8);
    out[1] = char(tid & 0xFF);
    return out;
}

QByteArray FaultBytes::wrongUnit(QByteArrayView adu, Framing framing, int delta)
{
    const AduParts parts = AduBuilder::parse(adu, framing);
    if (!parts.complete || framing == Framing::Pdu || framing == Framing::Auto)
        return {};
    return rewrap(adu, framing, parts.pdu, quint8(parts.unitId + delta));
}

QByteArray FaultBytes::exception(QByteArrayView adu, Framing framing, quint8 function, quint8 code)
{
    const AduParts parts = AduBuilder::parse(adu, framing);
    if (!parts.complete)
        return {};
    QByteArray pdu;
    pdu.append(char((function & 0x7F) | 0x80));
    pdu.append(char(code));
    return rewrap(adu, framing, pdu, parts.unitId);
}

QByteArray FaultBytes::fewerRegistersPdu(QByteArrayView pdu, int fewer)
{
    if (pdu.size() < 2 || fewer < 1)
        return {};
    const quint8 function = quint8(pdu.at(0));
    QByteArray out = pdu.toByteArray();
    switch (function) {
    case 0x01:
    case 0x02: // byte count, then the bits packed in bytes (V1.1b3 6.1, 6.2)
    case 0x03:
    case 0x04:
    case 0x17: { // byte count, then 2 bytes per register (6.3, 6.4, 6.17)
        const int unitBytes = function <= 0x02 ? 1 : 2;
        const int count = quint8(out.at(1));
        if (count == 0 || out.size() != 2 + count)
            return {};
        const int remove = std::min(count, fewer * unitBytes);
        out.chop(remove);
        out[1] = char(count - remove);
        return out;
    }
    case 0x18: { // byte count (2), FIFO count (2), then the registers (6.18)
        if (out.size() < 5)
            return {};
        const int fifoCount = quint8(out.at(3)) << 8 | quint8(out.at(4));
        if (fifoCount == 0 || out.size() != 5 + 2 * fifoCount)
            return {};
        const int left = std::max(0, fifoCount - fewer);
        out.truncate(5 + 2 * left);
        const int byteCount = 2 + 2 * left;
        out[1] = char(byteCount >> 8);
        out[2] = char(byteCount & 0xFF);
        out[3] = char(left >> 8);
        out[4] = char(left & 0xFF);
        return out;
    }
    default:
        return {};
    }
}

QByteArray FaultBytes::fewerRegisters(QByteArrayView adu, Framing framing, int fewer)
{
    const AduParts parts = AduBuilder::parse(adu, framing);
    if (!parts.complete)
        return {};
    const QByteArray pdu = fewerRegistersPdu(parts.pdu, fewer);
    if (pdu.isEmpty())
        return {};
    return rewrap(adu, framing, pdu, parts.unitId);
}

QByteArray FaultBytes::flipBits(QByteArrayView bytes, double bitErrorRate, SimRandom &random)
{
    QByteArray out = bytes.toByteArray();
    if (bitErrorRate <= 0)
        return out;
    for (qsizetype i = 0; i < out.size(); ++i) {
        for (int bit = 0; bit < 8; ++bit) {
            if (random.chance(bitErrorRate))
                out[i] = char(quint8(out.at(i)) ^ (1u << bit));
        }
    }
    return out;
}

} // namespace mbscope
