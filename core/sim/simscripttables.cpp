#include "sim/simscripttables.h"

#include "sim/simunit.h"

namespace mbscope {

namespace {

// ScriptTable and SimTable list the four tables in the same order (V1.1b3, 4.3).
SimTable simTable(ScriptTable table)
{
    switch (table) {
    case ScriptTable::Coils: return SimTable::Coils;
    case ScriptTable::DiscreteInputs: return SimTable::DiscreteInputs;
    case ScriptTable::InputRegisters: return SimTable::InputRegisters;
    case ScriptTable::HoldingRegisters: break;
    }
    return SimTable::HoldingRegisters;
}

} // namespace

SimScriptTables::SimScriptTables(SimUnit *unit)
    : m_unit(unit)
{
}

int SimScriptTables::unitId() const
{
    return m_unit ? m_unit->id() : 0;
}

std::optional<quint16> SimScriptTables::value(ScriptTable table, int address) const
{
    if (!m_unit)
        return std::nullopt;
    return m_unit->value(simTable(table), address);
}

bool SimScriptTables::setValues(ScriptTable table, int address, const QList<quint16> &values)
{
    return m_unit && m_unit->setValues(simTable(table), address, values);
}

} // namespace mbscope
