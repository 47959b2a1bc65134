#pragma once

#include <QtCore/QStringView>
#include <QtCore/QtGlobal>

#include <optional>

namespace mbscope {

// The four primary tables of the Modbus data model (V1.1b3, 4.3). Coils and discrete inputs hold
// single bits (stored as 0 or 1 in a quint16), the register tables 16-bit words.
enum class SimTable : quint8 {
    Coils,
    DiscreteInputs,
    InputRegisters,
    HoldingRegisters,
};

inline constexpr int SimTableCount = 4;

// The table a read function reads: 01 coils, 02 discrete inputs, 04 input registers, else
// (03, 17, 18) holding registers.
[[nodiscard]] constexpr SimTable readTable(quint8 function)
{
    switch (function) {
    case 0x01: return SimTable::Coils;
    case 0x02: return SimTable::DiscreteInputs;
    case 0x04: return SimTable::InputRegisters;
    default: return SimTable::HoldingRegisters;
    }
}

[[nodiscard]] constexpr bool isBitTable(SimTable table)
{
    return table == SimTable::Coils || table == SimTable::DiscreteInputs;
}

// "coils", "discrete inputs", "input registers", "holding registers" (for messages).
[[nodiscard]] const char *simTableName(SimTable table);
// A table's key in a device profile's "tables" (docs/profiles.md): "coils", "discrete", "input",
// "holding"; and back (nullopt for any other text).
[[nodiscard]] const char *simTableKey(SimTable table);
[[nodiscard]] std::optional<SimTable> simTableFromKey(QStringView key);

} // namespace mbscope
