#pragma once

// Hex numbers for messages and displays, in one place. Numbers are written the way the MODBUS
// Application Protocol Specification V1.1b3 writes them (upper case, zero-padded to the field's
// width: 0x00FF), so every message of the core reads the same.

#include <QtCore/QString>

namespace mbscope {

// "00FF": value in upper-case hex, zero-padded to at least digits.
[[nodiscard]] inline QString hexDigits(quint64 value, int digits)
{
    return QString::number(value, 16).toUpper().rightJustified(digits, QLatin1Char('0'));
}

// "0x00FF".
[[nodiscard]] inline QString hex(quint64 value, int digits)
{
    return QStringLiteral("0x") + hexDigits(value, digits);
}

// "0x0A": the low byte of value.
[[nodiscard]] inline QString hexByte(quint64 value)
{
    return hex(value & 0xFFu, 2);
}

// "0x000A": the low 16 bits of value.
[[nodiscard]] inline QString hexWord(quint64 value)
{
    return hex(value & 0xFFFFu, 4);
}

} // namespace mbscope
