#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

// The most items one request may name, by function code (MODBUS Application Protocol
// Specification V1.1b3, the request tables of 6.1-6.4, 6.11, 6.12, 6.17 and 6.18). The one
// place these numbers are written: the function table (functionspec.h) and through it the
// builders, the dissector's checks and the conformance battery read them here.
namespace QuantityLimits {

inline constexpr int kReadBits = 2000;           // 0x07D0: 01, 02 (6.1, 6.2)
inline constexpr int kReadRegisters = 125;       // 0x007D: 03, 04, and 17's read (6.3, 6.4, 6.17)
inline constexpr int kWriteCoils = 1968;         // 0x07B0: 0F (6.11)
inline constexpr int kWriteRegisters = 123;      // 0x007B: 10 (6.12)
inline constexpr int kReadWriteWrite = 121;      // 0x0079: 17's write (6.17)
inline constexpr int kFifoValues = 31;           // 18: a queue holds at most 31 registers (6.18)

// Which function each limit belongs to: FunctionSpec (functionspec.h), with
// QuantityLimits::maxQuantity and clause.

} // namespace QuantityLimits

} // namespace mbscope
