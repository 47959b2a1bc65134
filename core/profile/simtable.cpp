#include "simtable.h"

#include <QtCore/QLatin1String>

namespace mbscope {

const char *simTableName(SimTable table)
{
    switch (table) {
    case SimTable::Coils: return "coils";
    case SimTable::DiscreteInputs: return "discrete inputs";
    case SimTable::InputRegisters: return "input registers";
    case SimTable::HoldingRegisters: return "holding registers";
    }
    return "?";
}

const char *simTableKey(SimTable table)
{
    switch (table) {
    case SimTable::Coils: return "coils";
    case SimTable::DiscreteInputs: return "discrete";
    case SimTable::InputRegisters: return "input";
    case SimTable::HoldingRegisters: return "holding";
    }
    return "holding";
}

std::optional<SimTable> simTableFromKey(QStringView key)
{
    for (int n = 0; n < SimTableCount; ++n) {
        if (key == QLatin1String(simTableKey(SimTable(n))))
            return SimTable(n);
    }
    return std::nullopt;
}

} // namespace mbscope
