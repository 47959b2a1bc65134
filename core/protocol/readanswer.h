#pragma once

#include "modiconreference.h"
#include "registervalue.h"

#include <QtCore/QByteArrayView>
#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

struct ReadAnswerResult;

// The data of one read: which table, from which PDU address, and the registers or bits the
// answer holds. It pairs a read request (01, 02, 03, 04 or 17) with its answer, so the values
// can be named by address: the answer alone carries no address (V1.1b3, 6.1-6.4, 6.17).
// Shared by the CLI's value table and the window's register table.
struct ReadAnswer {
    ModbusTable table = ModbusTable::HoldingRegisters;
    quint8 functionCode = 0;
    int address = 0;          // PDU address of the first value
    int quantity = 0;         // values the request asked for
    QList<quint16> registers; // register functions: exactly quantity words
    QList<bool> bits;         // bit functions: exactly quantity bits (the padding bits dropped)

    [[nodiscard]] bool isBits() const { return table == ModbusTable::Coils || table == ModbusTable::DiscreteInputs; }
    [[nodiscard]] int count() const { return int(isBits() ? bits.size() : registers.size()); }
    [[nodiscard]] ModiconReference reference(int index) const
    {
        return ModiconReference(table, quint16(address + index));
    }
    // The value of format starting at register index, counted from the first register of the
    // answer: only at multiples of the format's width, and only when all its registers are there.
    [[nodiscard]] std::optional<RegisterValue> valueAt(int index, RegisterFormat format) const;

    // From the request and response PDUs (function code first). Refused, with what is wrong and
    // where: a request that is not a read of a table, an exception answer, an answer to another
    // function, a byte count that disagrees with the bytes that follow or with the quantity asked.
    [[nodiscard]] static ReadAnswerResult fromPdus(QByteArrayView requestPdu, QByteArrayView responsePdu);
    // From the parameters of the request and the response PDU.
    [[nodiscard]] static ReadAnswerResult fromResponse(quint8 functionCode, int address, int quantity,
                                                       QByteArrayView responsePdu);
    // "40122" when the five-digit form reaches the address, else "400122".
    [[nodiscard]] static QString referenceText(const ModiconReference &reference);
    // "121 (0x0079)": a PDU address in decimal and hex.
    [[nodiscard]] static QString addressText(int address);
};

struct ReadAnswerResult {
    ReadAnswer answer;
    QString error; // "the byte count says 44 bytes but 40 follow it (offset 2 of the response PDU)"
    bool ok = false;
};

} // namespace mbscope
