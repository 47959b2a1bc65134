#include "watchblock.h"

#include "protocol/quantitylimits.h"

namespace mbscope {

namespace {

QString hexByte(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).rightJustified(2, QLatin1Char('0')).toUpper();
}

quint16 word(QByteArrayView pdu, qsizetype at)
{
    return quint16((quint8(pdu[at]) << 8) | quint8(pdu[at + 1]));
}

} // namespace

RegisterFormat WatchBlock::effectiveFormat(const WatchDefinition &watch, const WatchPoint &point)
{
    if (wordsPerAddress(watch) != 2 || point.format.registerCount() != 1)
        return point.format;
    const RegisterOrder order = point.format.isByteSwapped() ? RegisterOrder::BADC : RegisterOrder::ABCD;
    switch (point.format.type()) {
    case RegisterType::Int16:
        return RegisterFormat(RegisterType::Int32, order);
    default:
        return RegisterFormat(RegisterType::UInt32, order);
    }
}

int WatchBlock::maxQuantity(quint8 function, bool enron32)
{
    switch (function) {
    case 1: case 2:
        return QuantityLimits::kReadBits;
    case 3: case 4:
        return enron32 ? QuantityLimits::kReadRegisters / 2 : QuantityLimits::kReadRegisters;
    case 0x18:
        return QuantityLimits::kFifoValues;
    default:
        return 0;
    }
}

QByteArray WatchBlock::requestPdu(const WatchDefinition &watch)
{
    QByteArray pdu;
    pdu.append(char(watch.function));
    pdu.append(char(watch.address >> 8));
    pdu.append(char(watch.address & 0xFF));
    if (watch.function != 0x18) {
        pdu.append(char(watch.quantity >> 8));
        pdu.append(char(watch.quantity & 0xFF));
    }
    return pdu;
}

WatchAnswer WatchBlock::readAnswer(const WatchDefinition &watch, QByteArrayView pdu)
{
    WatchAnswer answer;
    if (pdu.isEmpty()) {
        answer.error = QStringLiteral("the answer holds no PDU");
        return answer;
    }
    const quint8 function = quint8(pdu[0]);
    if (function == (watch.function | 0x80)) {
        answer.exceptionCode = pdu.size() > 1 ? quint8(pdu[1]) : 0;
        answer.error = QStringLiteral("exception %1").arg(hexByte(answer.exceptionCode));
        return answer;
    }
    if (function != watch.function) {
        answer.error = QStringLiteral("the answer is to function %1, not %2").arg(hexByte(function), hexByte(watch.function));
        return answer;
    }
    if (watch.function == 0x18) {
        // V1.1b3, 6.18: byte count (2 bytes), FIFO count (2 bytes), then the values.
        if (pdu.size() < 5) {
            answer.error = QStringLiteral("the FIFO answer has %1 bytes, at least 5 expected").arg(pdu.size());
            return answer;
        }
        const int byteCount = word(pdu, 1);
        const int fifoCount = word(pdu, 3);
        if (byteCount != 2 + 2 * fifoCount || pdu.size() != 3 + byteCount) {
            answer.error = QStringLiteral("the FIFO answer's byte count %1 does not match its FIFO count %2 and %3 bytes")
                               .arg(byteCount).arg(fifoCount).arg(pdu.size() - 3);
            return answer;
        }
        if (fifoCount > watch.quantity) {
            answer.error = QStringLiteral("the FIFO holds %1 values, more than the %2 expected").arg(fifoCount).arg(watch.quantity);
            return answer;
        }
        for (int i = 0; i < fifoCount; ++i)
            answer.words.append(word(pdu, 5 + 2 * i));
        answer.ok = true;
        return answer;
    }
    if (pdu.size() < 2) {
        answer.error = QStringLiteral("the answer has no byte count");
        return answer;
    }
    const int byteCount = quint8(pdu[1]);
    if (pdu.size() != 2 + byteCount) {
        answer.error = QStringLiteral("the byte count says %1 bytes but %2 follow it").arg(byteCount).arg(pdu.size() - 2);
        return answer;
    }
    if (isBitFunction(watch.function)) {
        const int expected = (watch.quantity + 7) / 8;
        if (byteCount != expected) {
            answer.error = QStringLiteral("the byte count is %1, %2 expected for %3 bits").arg(byteCount).arg(expected).arg(watch.quantity);
            return answer;
        }
        answer.bits.reserve(watch.quantity);
        for (int i = 0; i < watch.quantity; ++i)
            answer.bits.append((quint8(pdu[2 + i / 8]) >> (i % 8)) & 1);
        answer.ok = true;
        return answer;
    }
    const int words = watch.quantity * wordsPerAddress(watch);
    if (byteCount != 2 * words) {
        answer.error = watch.enron32
            ? QStringLiteral("the byte count is %1, %2 expected for %3 32-bit registers").arg(byteCount).arg(2 * words).arg(watch.quantity)
            : QStringLiteral("the byte count is %1, %2 expected for %3 registers").arg(byteCount).arg(2 * words).arg(watch.quantity);
        return answer;
    }
    answer.words.reserve(words);
    for (int i = 0; i < words; ++i)
        answer.words.append(word(pdu, 2 + 2 * i));
    answer.ok = true;
    return answer;
}

QByteArray WatchBlock::writePdu(const WatchDefinition &watch, quint16 address, const QList<quint16> &words,
                                QString *error)
{
    const auto refuse = [error](const QString &message) {
        if (error)
            *error = message;
        return QByteArray();
    };
    const WatchPoint *point = nullptr;
    for (const WatchPoint &p : watch.points) {
        if (p.address == address)
            point = &p;
    }
    const QString where = QStringLiteral("%1 address %2").arg(watch.name).arg(address);
    if (!point || !point->writable)
        return refuse(QStringLiteral("%1: no writable point there (mark the point \"writable\": true)").arg(where));
    if (watch.function != 1 && watch.function != 3)
        return refuse(QStringLiteral("%1: only holding registers (03) and coils (01) can be written, this watch reads function %2")
                          .arg(where).arg(watch.function));
    if (words.isEmpty())
        return refuse(QStringLiteral("%1: nothing to write").arg(where));
    QByteArray pdu;
    const auto put16 = [&pdu](int v) {
        pdu.append(char((v >> 8) & 0xFF));
        pdu.append(char(v & 0xFF));
    };
    if (watch.function == 1) {
        if (words.size() != 1)
            return refuse(QStringLiteral("%1: a coil point holds one bit, %2 values given").arg(where).arg(words.size()));
        if (words.first() > 1)
            return refuse(QStringLiteral("%1: a coil is 0 or 1, not %2").arg(where).arg(words.first()));
        pdu.append(char(0x05));
        put16(address);
        put16(words.first() ? 0xFF00 : 0x0000);
        return pdu;
    }
    const int perAddress = wordsPerAddress(watch);
    const int expected = qMax(perAddress, effectiveFormat(watch, *point).registerCount());
    if (words.size() != expected)
        return refuse(QStringLiteral("%1: the point holds %2 registers, %3 given").arg(where).arg(expected).arg(words.size()));
    if (expected == 1) {
        pdu.append(char(0x06));
        put16(address);
        put16(words.first());
        return pdu;
    }
    pdu.append(char(0x10));
    put16(address);
    put16(expected / perAddress);
    pdu.append(char(2 * expected));
    for (quint16 w : words)
        put16(w);
    return pdu;
}

} // namespace mbscope
