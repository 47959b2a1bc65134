#pragma once

#include "protocol/registerformat.h"

#include <QtCore/QByteArray>
#include <QtCore/QJsonArray>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope::app {

// The data of a read or a write, one row per register or bit: its PDU address, its Modicon
// reference (V1.1b3, 4.4: register 40122 is PDU address 121) and its value in each format asked.
// A value of 2 or 4 registers (u32, f32, f64...) stands on the row of its first register,
// counted from the first register of the request.
struct ValueTable {
    quint8 functionCode = 0; // the table follows from it (ModiconReference::tableOf)
    int address = 0;
    QList<quint16> registers; // register functions
    QList<bool> bits;         // bit functions
    QList<RegisterFormat> formats;
    bool oneBased = false; // --one-based: each row leads with its number counted from 1

    [[nodiscard]] bool isEmpty() const { return registers.isEmpty() && bits.isEmpty(); }

    // The values of a read's answer: the PDU of a 01/02/03/04 response (function code first).
    // Empty for anything else (an exception, a short answer).
    [[nodiscard]] static ValueTable fromReadResponse(quint8 functionCode, int address, int quantity,
                                                     const QByteArray &responsePdu,
                                                     const QList<RegisterFormat> &formats);

    // The values one after the other, as poll --print values shows them: bits as 1/0; registers
    // in the format, one value per registerCount() registers from the first.
    [[nodiscard]] QStringList valueTexts(RegisterFormat format) const;
    [[nodiscard]] QStringList bitTexts() const;

    // Aligned columns with a heading line (a 1-BASED column first when oneBased).
    [[nodiscard]] QString text() const;
    // One value a line, as mbpoll prints them: "[REF]: \tVALUE", REF the PDU address (counted from
    // 1 when oneBased), a value of 2 or 4 registers at its first register (the first format's
    // width; further formats follow on the line, tab-separated).
    [[nodiscard]] QString terse() const;
    // [{"address", "reference", "value"} for bits; {"address", "reference", "raw", "<format>": value...}
    // for registers], with "one_based" (address + 1) when oneBased. Integers and finite floats are
    // JSON numbers (integers beyond 2^53 are text).
    [[nodiscard]] QJsonArray json() const;
};

} // namespace mbscope::app
