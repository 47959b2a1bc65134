#pragma once

#include "registerformat.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringView>

#include <span>

namespace mbscope {

struct RegisterValueResult;
struct RegisterListResult;

// One value held in 1, 2 or 4 registers, read with a RegisterFormat: decode (registers -> value)
// for display, encode (text or number -> registers) for the request builder and the simulator.
// A value type that stores the format and the raw bits, right aligned in natural significance
// (the order already undone), so nothing is lost: a NaN keeps its payload, -0.0 its sign.
//
// Text (toText, fromText), per type:
//   u16 u32 u64     decimal: "65535"; fromText also takes 0x... and 0b... as the raw bit pattern
//   i16 i32 i64     decimal: "-1"; fromText also takes 0x... and 0b... as the raw bit pattern
//                   ("0xFFFF" as i16 is -1)
//   hex             "0x002A" (four upper-case digits); fromText takes 0x2A, 2A, 002a
//   bin             "0b0000_0000_0010_1010" (16 digits in groups of four); fromText takes it with
//                   or without 0b and '_'
//   ascii           two characters, high byte first (low byte first for ascii-ba); bytes outside
//                   0x20-0x7E as \xNN and a backslash as \\, so "A\x00" is 0x4100
//   f32 f64         the shortest text that reads back to the same value ("123.456", "1e+40",
//                   "-0"), "NaN", "Inf", "-Inf"; fromText takes decimal and scientific notation
//                   and nan/inf/infinity in any case, and refuses a value the type cannot hold
//                   rather than turning it into infinity or zero
class RegisterValue
{
public:
    RegisterValue() = default;

    // Decoding: reads the first format.registerCount() registers (in wire order). Fails only when
    // fewer registers are given; further registers are ignored.
    [[nodiscard]] static RegisterValueResult fromRegisters(std::span<const quint16> registers,
                                                           RegisterFormat format);
    // Raw bits in natural significance; bits above the format's width are dropped.
    [[nodiscard]] static RegisterValue fromBits(quint64 bits, RegisterFormat format);

    // Encoding. Each fails with a message when the format cannot hold the value exactly as an
    // integer (out of range, a fraction for an integer type) or, for f32, when a finite value is
    // beyond float range; floats otherwise round to nearest as IEEE 754 does.
    [[nodiscard]] static RegisterValueResult fromText(QStringView text, RegisterFormat format);
    [[nodiscard]] static RegisterValueResult fromSigned(qint64 value, RegisterFormat format);
    [[nodiscard]] static RegisterValueResult fromUnsigned(quint64 value, RegisterFormat format);
    [[nodiscard]] static RegisterValueResult fromDouble(double value, RegisterFormat format);

    [[nodiscard]] RegisterFormat format() const { return m_format; }
    // The value's bits with the order undone: 0x42F6E979 for float 123.456 in any order.
    [[nodiscard]] quint64 bits() const { return m_bits; }
    // Signed types sign-extended; every other type its bits as they are (u64 above 2^63 wraps).
    [[nodiscard]] qint64 toInt64() const;
    // The number the value stands for (integers converted, exact up to 2^53).
    [[nodiscard]] double toDouble() const;
    [[nodiscard]] bool isNaN() const;
    [[nodiscard]] QString toText() const;

    // The registers in wire order, ready for a request or a simulator's table.
    [[nodiscard]] QList<quint16> registers() const;
    // Writes at most out.size() of the format.registerCount() registers; never beyond out.
    void writeRegisters(std::span<quint16> out) const;

    // The order alone, for callers that move raw bits: joins up to four registers given in wire
    // order into the value's bits, and splits bits back into out.size() (at most four) registers.
    [[nodiscard]] static quint64 joinRegisters(std::span<const quint16> registers, RegisterOrder order);
    static void splitRegisters(quint64 bits, RegisterOrder order, std::span<quint16> out);

    // A text spread over many registers, two characters per register, high byte first (low byte
    // first when byteSwapped). asciiText shows every byte (NUL padding as \x00, escapes as above);
    // asciiRegisters reads the same escapes, refuses characters outside ASCII, and pads an odd
    // count with one NUL byte.
    [[nodiscard]] static QString asciiText(std::span<const quint16> registers, bool byteSwapped);
    [[nodiscard]] static RegisterListResult asciiRegisters(QStringView text, bool byteSwapped);

    friend bool operator==(const RegisterValue &, const RegisterValue &) = default;

private:
    RegisterValue(quint64 bits, RegisterFormat format);

    quint64 m_bits = 0;
    RegisterFormat m_format;
};

struct RegisterValueResult {
    RegisterValue value;
    QString error; // "'70000' is out of range for u16 (0 to 65535)"; empty when ok
    bool ok = false;
};

struct RegisterListResult {
    QList<quint16> registers;
    QString error;
    bool ok = false;
};

} // namespace mbscope
