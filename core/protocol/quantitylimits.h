#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

// The most items one request may name, by function code (MODBUS Application Protocol
// Specification V1.1b3, the request tables of 6.1-6.4, 6.11, 6.12, 6.17 and 6.18). The one
// place these numbers are written: the builders, the dissector's checks and the conformance
// battery read them here.
namespace QuantityLimits {

inline constexpr int kReadBits = 2000;           // 0x07D0: 01, 02 (6.1, 6.2)
inline constexpr int kReadRegisters = 125;       // 0x007D: 03, 04, and 17's read (6.3, 6.4, 6.17)
inline constexpr int kWriteCoils = 1968;         // 0x07B0: 0F (6.11)
inline constexpr int kWriteRegisters = 123;      // 0x007B: 10 (6.12)
inline constexpr int kReadWriteWrite = 121;      // 0x0079: 17's write (6.17)
inline constexpr int kFifoValues = 31;           // 18: a queue holds at most 31 registers (6.18)

// The most items a request of function may name (17: its read quantity); 0 for a function
// without a quantity.
[[nodiscard]] constexpr int maxQuantity(quint8 function)
{
    switch (function) {
    case 0x01:
    case 0x02:
        return kReadBits;
    case 0x03:
    case 0x04:
    case 0x17:
        return kReadRegisters;
    case 0x0F:
        return kWriteCoils;
    case 0x10:
        return kWriteRegisters;
    default:
        return 0;
    }
}

// The section of V1.1b3 that gives function's limit ("6.3"); empty for a function without one.
[[nodiscard]] constexpr const char *clause(quint8 function)
{
    switch (function) {
    case 0x01: return "6.1";
    case 0x02: return "6.2";
    case 0x03: return "6.3";
    case 0x04: return "6.4";
    case 0x0F: return "6.11";
    case 0x10: return "6.12";
    case 0x17: return "6.17";
    default: return "";
    }
}

} // namespace QuantityLimits

} // namespace mbscope
