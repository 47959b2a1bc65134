#pragma once

#include "quantitylimits.h"

#include <QtCore/QtGlobal>

namespace mbscope {

// What the request of a public function carries after its code (MODBUS Application Protocol
// Specification V1.1b3, the request tables of 6.1-6.21).
enum class RequestShape : quint8 {
    Bare,        // 07, 0B, 0C, 11: the function code alone
    Range,       // 01-04: start address, quantity
    Single,      // 05, 06: address, value
    RangeValues, // 0F, 10: start address, quantity, byte count, values
    Mask,        // 16: address, AND mask, OR mask
    ReadWrite,   // 17: read start and quantity, write start and quantity, byte count, values
    Pointer,     // 18: the FIFO pointer's address
    SubFunction, // 08: sub-function, data
    FileRecords, // 14, 15: byte count, sub-requests
    Mei,         // 2B: MEI type, then what that type carries
};

// One public function code: the one table the builders, the dissector, the simulator, the form,
// the fault injector, replay's write guard and the conformance battery read.
struct FunctionSpec {
    quint8 code;
    const char *name;   // "Read Holding Registers" (translated in the mbscope::Field context)
    const char *clause; // the section of V1.1b3 that defines it: "6.3"
    RequestShape shape;
    bool writes;        // changes the device's data (08 depends on its sub-function: see RecordedWrite)
    bool readsValues;   // its answer carries values of a table (01-04, 17)
    int maxQuantity;    // the most items one request may name (17: its read); 0 without a quantity
    const char *unit;   // what the quantity counts: "coils", "inputs", "registers" (mbscope::Field); nullptr without one
};

inline constexpr FunctionSpec kFunctionSpecs[] = {
    {0x01, QT_TRANSLATE_NOOP("mbscope::Field", "Read Coils"), "6.1", RequestShape::Range, false, true, QuantityLimits::kReadBits, QT_TRANSLATE_NOOP("mbscope::Field", "coils")},
    {0x02, QT_TRANSLATE_NOOP("mbscope::Field", "Read Discrete Inputs"), "6.2", RequestShape::Range, false, true, QuantityLimits::kReadBits, QT_TRANSLATE_NOOP("mbscope::Field", "inputs")},
    {0x03, QT_TRANSLATE_NOOP("mbscope::Field", "Read Holding Registers"), "6.3", RequestShape::Range, false, true, QuantityLimits::kReadRegisters, QT_TRANSLATE_NOOP("mbscope::Field", "registers")},
    {0x04, QT_TRANSLATE_NOOP("mbscope::Field", "Read Input Registers"), "6.4", RequestShape::Range, false, true, QuantityLimits::kReadRegisters, QT_TRANSLATE_NOOP("mbscope::Field", "registers")},
    {0x05, QT_TRANSLATE_NOOP("mbscope::Field", "Write Single Coil"), "6.5", RequestShape::Single, true, false, 0, nullptr},
    {0x06, QT_TRANSLATE_NOOP("mbscope::Field", "Write Single Register"), "6.6", RequestShape::Single, true, false, 0, nullptr},
    {0x07, QT_TRANSLATE_NOOP("mbscope::Field", "Read Exception Status"), "6.7", RequestShape::Bare, false, false, 0, nullptr},
    {0x08, QT_TRANSLATE_NOOP("mbscope::Field", "Diagnostics"), "6.8", RequestShape::SubFunction, false, false, 0, nullptr},
    {0x0B, QT_TRANSLATE_NOOP("mbscope::Field", "Get Comm Event Counter"), "6.9", RequestShape::Bare, false, false, 0, nullptr},
    {0x0C, QT_TRANSLATE_NOOP("mbscope::Field", "Get Comm Event Log"), "6.10", RequestShape::Bare, false, false, 0, nullptr},
    {0x0F, QT_TRANSLATE_NOOP("mbscope::Field", "Write Multiple Coils"), "6.11", RequestShape::RangeValues, true, false, QuantityLimits::kWriteCoils, QT_TRANSLATE_NOOP("mbscope::Field", "coils")},
    {0x10, QT_TRANSLATE_NOOP("mbscope::Field", "Write Multiple Registers"), "6.12", RequestShape::RangeValues, true, false, QuantityLimits::kWriteRegisters, QT_TRANSLATE_NOOP("mbscope::Field", "registers")},
    {0x11, QT_TRANSLATE_NOOP("mbscope::Field", "Report Server ID"), "6.13", RequestShape::Bare, false, false, 0, nullptr},
    {0x14, QT_TRANSLATE_NOOP("mbscope::Field", "Read File Record"), "6.14", RequestShape::FileRecords, false, false, 0, nullptr},
    {0x15, QT_TRANSLATE_NOOP("mbscope::Field", "Write File Record"), "6.15", RequestShape::FileRecords, true, false, 0, nullptr},
    {0x16, QT_TRANSLATE_NOOP("mbscope::Field", "Mask Write Register"), "6.16", RequestShape::Mask, true, false, 0, nullptr},
    {0x17, QT_TRANSLATE_NOOP("mbscope::Field", "Read/Write Multiple Registers"), "6.17", RequestShape::ReadWrite, true, true, QuantityLimits::kReadRegisters, QT_TRANSLATE_NOOP("mbscope::Field", "registers")},
    {0x18, QT_TRANSLATE_NOOP("mbscope::Field", "Read FIFO Queue"), "6.18", RequestShape::Pointer, false, false, 0, nullptr},
    {0x2B, QT_TRANSLATE_NOOP("mbscope::Field", "Encapsulated Interface Transport"), "6.19", RequestShape::Mei, false, false, 0, nullptr},
};

// The public function with this code; nullptr for any other code (user-defined, reserved,
// unassigned, an exception's code).
[[nodiscard]] constexpr const FunctionSpec *functionSpec(quint8 code)
{
    for (const FunctionSpec &spec : kFunctionSpecs) {
        if (spec.code == code)
            return &spec;
    }
    return nullptr;
}

// A public function that changes the device's data (05, 06, 0F, 10, 15, 16, 17).
[[nodiscard]] constexpr bool functionWrites(quint8 code)
{
    const FunctionSpec *spec = functionSpec(code);
    return spec && spec->writes;
}

// A public function whose answer carries a table's values (01-04, 17).
[[nodiscard]] constexpr bool functionReadsValues(quint8 code)
{
    const FunctionSpec *spec = functionSpec(code);
    return spec && spec->readsValues;
}

// A public function whose request has this shape (false for any other code).
[[nodiscard]] constexpr bool functionHasShape(quint8 code, RequestShape shape)
{
    const FunctionSpec *spec = functionSpec(code);
    return spec && spec->shape == shape;
}

// Its request starts with an address (V1.1b3: 01-06, 0F, 10, 16, 17, 18).
[[nodiscard]] constexpr bool functionStartsWithAddress(quint8 code)
{
    const FunctionSpec *spec = functionSpec(code);
    if (!spec)
        return false;
    switch (spec->shape) {
    case RequestShape::Range:
    case RequestShape::Single:
    case RequestShape::RangeValues:
    case RequestShape::Mask:
    case RequestShape::ReadWrite:
    case RequestShape::Pointer:
        return true;
    default:
        return false;
    }
}

namespace QuantityLimits {

// The most items a request of function may name (17: its read quantity); 0 for a function
// without a quantity.
[[nodiscard]] constexpr int maxQuantity(quint8 function)
{
    const FunctionSpec *spec = functionSpec(function);
    return spec ? spec->maxQuantity : 0;
}

// The section of V1.1b3 that gives function's limit ("6.3"); empty for a function without one.
[[nodiscard]] constexpr const char *clause(quint8 function)
{
    const FunctionSpec *spec = functionSpec(function);
    return spec && spec->maxQuantity > 0 ? spec->clause : "";
}

} // namespace QuantityLimits

} // namespace mbscope
