// SimProcessor: Read/Write Multiple Registers (17) and Read FIFO Queue (18), V1.1b3 6.17-6.18.
// QModbusServer has both, but its 17 limits the read quantity to 123 (the spec allows 125) and
// writes before checking the read addresses, and its 18 keeps the queue in holding registers.
#include "sim/simbytes.h"
#include "sim/simprocessor.h"
#include "sim/simunit.h"

namespace mbscope {

using simbytes::appendWord;
using simbytes::hexDec;
using simbytes::word;

SimReply SimProcessor::readWriteRegisters(QByteArrayView pdu)
{
    auto bad = [](const QString &why) { return SimReply::exception(0x17, 0x03, why); };
    if (pdu.size() < 10)
        return bad(QStringLiteral("17 needs 9 header bytes, %1 given").arg(pdu.size() - 1));
    const int readStart = word(pdu, 1);
    const int readQuantity = word(pdu, 3);
    const int writeStart = word(pdu, 5);
    const int writeQuantity = word(pdu, 7);
    const int byteCount = quint8(pdu[9]);
    // 6.17 state diagram: quantities and byte count (03), then both address ranges (02).
    if (readQuantity < 1 || readQuantity > 0x7D)
        return bad(QStringLiteral("quantity to read %1 is outside 1-125").arg(readQuantity));
    if (writeQuantity < 1 || writeQuantity > 0x79)
        return bad(QStringLiteral("quantity to write %1 is outside 1-121").arg(writeQuantity));
    if (byteCount != 2 * writeQuantity)
        return bad(QStringLiteral("write byte count %1, expected 2 x %2 = %3").arg(byteCount).arg(writeQuantity).arg(2 * writeQuantity));
    if (pdu.size() != 10 + byteCount)
        return bad(QStringLiteral("write byte count %1 announces %1 bytes but %2 follow").arg(byteCount).arg(pdu.size() - 10));
    const SimTable table = SimTable::HoldingRegisters;
    if (!m_unit->contains(table, readStart, readQuantity))
        return SimReply::exception(0x17, 0x02, QStringLiteral("read range %1 + %2 is outside the holding registers").arg(hexDec(readStart)).arg(readQuantity));
    if (!m_unit->contains(table, writeStart, writeQuantity))
        return SimReply::exception(0x17, 0x02, QStringLiteral("write range %1 + %2 is outside the holding registers").arg(hexDec(writeStart)).arg(writeQuantity));
    if (!m_unit->isWritable(table, writeStart, writeQuantity))
        return SimReply::exception(0x17, 0x02, QStringLiteral("write range %1 + %2 is read-only").arg(hexDec(writeStart)).arg(writeQuantity));
    QList<quint16> values;
    values.reserve(writeQuantity);
    for (int i = 0; i < writeQuantity; ++i)
        values.append(word(pdu, 10 + 2 * i));
    // 6.17: the write is performed before the read.
    if (!m_unit->clientWrite(table, writeStart, values))
        return SimReply::exception(0x17, 0x04, QStringLiteral("the write failed"));
    const QList<quint16> read = m_unit->values(table, readStart, readQuantity);
    QByteArray bytes(1, char(0x17));
    bytes.append(char(2 * readQuantity));
    for (quint16 v : read)
        appendWord(bytes, v);
    return SimReply::normal(bytes);
}

SimReply SimProcessor::readFifo(QByteArrayView pdu)
{
    if (pdu.size() != 3)
        return SimReply::exception(0x18, 0x03, QStringLiteral("18 takes a 2-byte FIFO pointer address, %1 data bytes given").arg(pdu.size() - 1));
    const quint16 pointer = word(pdu, 1);
    // 6.18 state diagram: the FIFO pointer address (02), then the FIFO count <= 31 (03).
    if (!m_unit->hasFifo(pointer))
        return SimReply::exception(0x18, 0x02, QStringLiteral("no FIFO queue at %1").arg(hexDec(pointer)));
    const QList<quint16> queue = m_unit->fifo(pointer);
    if (queue.size() > 31)
        return SimReply::exception(0x18, 0x03, QStringLiteral("the FIFO at %1 holds %2 registers, more than 31").arg(hexDec(pointer)).arg(queue.size()));
    QByteArray bytes(1, char(0x18));
    appendWord(bytes, quint16(2 + 2 * queue.size())); // byte count: FIFO count + values
    appendWord(bytes, quint16(queue.size()));
    for (quint16 v : queue)
        appendWord(bytes, v);
    return SimReply::normal(bytes);
}

} // namespace mbscope
