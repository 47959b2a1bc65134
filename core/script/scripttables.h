#pragma once

#include <QtCore/QList>

#include <optional>

namespace mbscope {

// The four tables of a unit as a script names them ("coils", "discrete", "input", "holding"),
// in the order of the Modbus data model (V1.1b3, 4.3).
enum class ScriptTable : quint8 {
    Coils,
    DiscreteInputs,
    InputRegisters,
    HoldingRegisters,
};

// A unit's data as a script reads and writes it (the simulator's SimUnit behind it: SimScriptTables).
// Bits read and write as 0/1. Writes are local writes: no writable check, views see them change.
class ScriptTables
{
public:
    virtual ~ScriptTables() = default;
    [[nodiscard]] virtual int unitId() const = 0;
    [[nodiscard]] virtual std::optional<quint16> value(ScriptTable table, int address) const = 0;
    // All or nothing: false (no change) when any address is not in the unit.
    virtual bool setValues(ScriptTable table, int address, const QList<quint16> &values) = 0;
};

} // namespace mbscope
