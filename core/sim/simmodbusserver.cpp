#include "sim/simmodbusserver.h"

#include "sim/simunit.h"

#include <optional>

namespace mbscope {

namespace {

std::optional<SimTable> tableOf(QModbusDataUnit::RegisterType type)
{
    switch (type) {
    case QModbusDataUnit::Coils: return SimTable::Coils;
    case QModbusDataUnit::DiscreteInputs: return SimTable::DiscreteInputs;
    case QModbusDataUnit::InputRegisters: return SimTable::InputRegisters;
    case QModbusDataUnit::HoldingRegisters: return SimTable::HoldingRegisters;
    case QModbusDataUnit::Invalid: break;
    }
    return std::nullopt;
}

} // namespace

SimModbusServer::SimModbusServer(SimUnit *unit, QObject *parent)
    : QModbusServer(parent)
    , m_unit(unit)
{
    setServerAddress(unit->id());
}

bool SimModbusServer::open()
{
    return true;
}

void SimModbusServer::close()
{
}

bool SimModbusServer::setMap(const QModbusDataUnitMap &map)
{
    bool ok = true;
    for (auto it = map.cbegin(); it != map.cend(); ++it) {
        const auto table = tableOf(it.key());
        if (!table)
            continue;
        m_unit->clearRanges(*table);
        if (it->valueCount() == 0)
            continue;
        SimRange range;
        range.table = *table;
        range.start = quint16(it->startAddress());
        range.count = int(it->valueCount());
        range.values = it->values();
        ok = m_unit->addRange(range) && ok;
    }
    return ok;
}

bool SimModbusServer::readData(QModbusDataUnit *newData) const
{
    if (!newData)
        return false;
    const auto table = tableOf(newData->registerType());
    if (!table || newData->startAddress() < 0)
        return false;
    const QList<quint16> values = m_unit->values(*table, newData->startAddress(), int(newData->valueCount()));
    if (values.isEmpty())
        return false;
    newData->setValues(values);
    return true;
}

bool SimModbusServer::writeData(const QModbusDataUnit &unit)
{
    const auto table = tableOf(unit.registerType());
    if (!table || unit.startAddress() < 0)
        return false;
    if (!m_unit->clientWrite(*table, unit.startAddress(), unit.values()))
        return false;
    Q_EMIT dataWritten(unit.registerType(), unit.startAddress(), int(unit.valueCount()));
    return true;
}

} // namespace mbscope

#include "moc_simmodbusserver.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
