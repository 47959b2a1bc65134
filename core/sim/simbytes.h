#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QString>

namespace mbscope::simbytes {

// Big-endian words, as every Modbus field is (V1.1b3, 4.2). Callers check the size first.
[[nodiscard]] inline quint16 word(QByteArrayView bytes, qsizetype at)
{
    return quint16((quint8(bytes[at]) << 8) | quint8(bytes[at + 1]));
}

inline void appendWord(QByteArray &bytes, quint16 value)
{
    bytes.append(char(value >> 8));
    bytes.append(char(value & 0xFF));
}

// "0x007B (123)" for messages.
[[nodiscard]] inline QString hexDec(int value)
{
    return QStringLiteral("0x%1 (%2)").arg(value, 4, 16, QLatin1Char('0')).arg(value);
}

} // namespace mbscope::simbytes
