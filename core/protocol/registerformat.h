#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringView>

namespace mbscope {

// What the bits in one or more 16-bit registers stand for. Modbus defines only 16-bit registers,
// each sent high byte first (MODBUS Application Protocol Specification V1.1b3, 4.2: "big-Endian
// representation"); wider values are a device convention, which is why the order must be chosen.
enum class RegisterType : quint8 {
    UInt16,   // u16:   0 .. 65535
    Int16,    // i16:   -32768 .. 32767 (two's complement)
    Hex16,    // hex:   0x0000 .. 0xFFFF
    Binary16, // bin:   0b0000_0000_0000_0000 .. 0b1111_1111_1111_1111
    Ascii,    // ascii: two 8-bit characters per register
    UInt32,   // u32
    Int32,    // i32
    UInt64,   // u64
    Int64,    // i64
    Float32,  // f32: IEEE 754 binary32
    Float64,  // f64: IEEE 754 binary64
};

// Where the bytes of a value travel. Name the bytes of the value from the most significant (A) to
// the least significant (B, C, ... H); the order spells them in the order they are on the wire,
// i.e. register by register, each register's high byte first.
//
//   order   16-bit  32-bit  64-bit     registers                     bytes in each register
//   ABCD    AB      ABCD    ABCDEFGH   most significant first        high byte first (big endian)
//   CDAB    AB      CDAB    GHEFCDAB   least significant first       high byte first ("word swap")
//   BADC    BA      BADC    BADCFEHG   most significant first        low byte first  ("byte swap")
//   DCBA    BA      DCBA    HGFEDCBA   least significant first       low byte first  (little endian)
//
// So float 123.456 (0x42F6E979) is 42F6 E979 in ABCD, E979 42F6 in CDAB, F642 79E9 in BADC and
// 79E9 F642 in DCBA. A one-register value has no word order: ABCD and CDAB are the same (AB), as
// are BADC and DCBA (BA, the bytes of the register swapped); RegisterFormat keeps ABCD or BADC.
enum class RegisterOrder : quint8 {
    ABCD,
    CDAB,
    BADC,
    DCBA,
};

struct RegisterFormatResult;

// A register type with its order: a small value type, parsed from and printed as names such as
// "u16", "i16-ba", "hex", "bin", "ascii", "ascii-ba", "u32-abcd", "f32-cdab", "f64-ghefcdab".
//
// Name grammar (case-insensitive, surrounding spaces ignored): TYPE or TYPE-ORDER.
//   TYPE:  u16 | i16 | hex | bin | ascii | u32 | i32 | u64 | i64 | f32 | f64, or the long forms
//          uint16 int16 hex16 binary uint32 int32 uint64 int64 float32 float float64 double.
//   ORDER: 16-bit types ab | ba; 32-bit abcd | cdab | badc | dcba; 64-bit the eight-letter names
//          abcdefgh | ghefcdab | badcfehg | hgfedcba or the four-letter family names above.
//   Without an order a format is big endian (ABCD), the Modbus byte order.
// name() gives the canonical name: 16-bit types carry "-ba" only when byte swapped, 32- and
// 64-bit types always carry their order (four and eight letters), since that is where devices
// and tools differ.
class RegisterFormat
{
public:
    constexpr RegisterFormat() = default;
    constexpr RegisterFormat(RegisterType type, RegisterOrder order = RegisterOrder::ABCD)
        : m_type(type), m_order(normalized(type, order))
    {
    }

    [[nodiscard]] constexpr RegisterType type() const { return m_type; }
    [[nodiscard]] constexpr RegisterOrder order() const { return m_order; }
    // Registers one value occupies: 1, 2 or 4.
    [[nodiscard]] constexpr int registerCount() const { return registerCount(m_type); }
    [[nodiscard]] constexpr int byteCount() const { return 2 * registerCount(); }
    [[nodiscard]] constexpr bool isSigned() const
    {
        return m_type == RegisterType::Int16 || m_type == RegisterType::Int32 || m_type == RegisterType::Int64;
    }
    [[nodiscard]] constexpr bool isFloat() const
    {
        return m_type == RegisterType::Float32 || m_type == RegisterType::Float64;
    }
    // The registers of a value come least significant first (CDAB, DCBA).
    [[nodiscard]] constexpr bool isWordSwapped() const
    {
        return m_order == RegisterOrder::CDAB || m_order == RegisterOrder::DCBA;
    }
    // Each register carries its low byte first (BADC, DCBA).
    [[nodiscard]] constexpr bool isByteSwapped() const
    {
        return m_order == RegisterOrder::BADC || m_order == RegisterOrder::DCBA;
    }

    [[nodiscard]] QString name() const;        // "f32-cdab"
    [[nodiscard]] QString typeName() const;    // "f32"
    [[nodiscard]] QString orderName() const;   // "CDAB"; "AB"/"BA" for 16-bit; eight letters for 64-bit
    [[nodiscard]] QString description() const; // "float32 (IEEE 754 single), word swap (CDAB)"
    // description()'s two parts as static strings the window translates (QT_TRANSLATE_NOOP
    // "mbscope::Field"): "float32 (IEEE 754 single)" and "word swap" (one register: "high byte first").
    [[nodiscard]] const char *typeDescription() const;
    [[nodiscard]] const char *orderWords() const;

    [[nodiscard]] static RegisterFormatResult parse(QStringView name);
    // Every distinct format (34), 16-bit types first: for choosers and for tests.
    [[nodiscard]] static QList<RegisterFormat> all();

    [[nodiscard]] static constexpr int registerCount(RegisterType type)
    {
        switch (type) {
        case RegisterType::UInt32: case RegisterType::Int32: case RegisterType::Float32:
            return 2;
        case RegisterType::UInt64: case RegisterType::Int64: case RegisterType::Float64:
            return 4;
        default:
            return 1;
        }
    }

    friend constexpr bool operator==(const RegisterFormat &, const RegisterFormat &) = default;

private:
    static constexpr RegisterOrder normalized(RegisterType type, RegisterOrder order)
    {
        if (registerCount(type) > 1)
            return order;
        return (order == RegisterOrder::BADC || order == RegisterOrder::DCBA) ? RegisterOrder::BADC
                                                                              : RegisterOrder::ABCD;
    }

    RegisterType m_type = RegisterType::UInt16;
    RegisterOrder m_order = RegisterOrder::ABCD;
};

struct RegisterFormatResult {
    RegisterFormat format;
    QString error; // "'f33' is not a register format: expected ..."; empty when ok
    bool ok = false;
};

} // namespace mbscope
