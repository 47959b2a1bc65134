#include "simtable.h"

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

} // namespace mbscope
