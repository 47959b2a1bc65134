#pragma once

// Hex both ways, in one place. Numbers are written the way the MODBUS Application Protocol
// Specification V1.1b3 writes them (upper case, zero-padded to the field's width: 0x00FF), so
// every message of the core reads the same; hexDigitValue is the one decoder of a hex digit, for
// typed hex text and ASCII frames (MODBUS over Serial Line V1.02, 2.5.2.1) alike.

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

// The value of a hex digit of either case, or -1 for any other character.
[[nodiscard]] constexpr int hexDigitValue(char16_t c)
{
    if (c >= u'0' && c <= u'9')
        return c - u'0';
    if (c >= u'A' && c <= u'F')
        return c - u'A' + 10;
    if (c >= u'a' && c <= u'f')
        return c - u'a' + 10;
    return -1;
}

[[nodiscard]] constexpr int hexDigitValue(char c)
{
    return hexDigitValue(char16_t(quint8(c)));
}

[[nodiscard]] constexpr int hexDigitValue(QChar c)
{
    return hexDigitValue(c.unicode());
}

} // namespace mbscope
