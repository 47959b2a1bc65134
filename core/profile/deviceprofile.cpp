#include "deviceprofile.h"

#include "protocol/registervalue.h"

namespace mbscope {

bool TableEntry::isNotImplemented(std::span<const quint16> words) const
{
    if (isBitTable(table) || isString() || int(words.size()) != width() || (!notImplemented && !notImplementedNaN))
        return false;
    const RegisterValueResult v = RegisterValue::fromRegisters(words, format);
    if (!v.ok)
        return false;
    if (notImplementedNaN && v.value.isNaN())
        return true;
    return notImplemented && v.value.bits() == *notImplemented;
}

QList<TableEntry> UnitProfile::entriesOf(SimTable table) const
{
    QList<TableEntry> out;
    for (const TableEntry &entry : entries) {
        if (entry.table == table)
            out.append(entry);
    }
    return out;
}

const TableEntry *UnitProfile::entryAt(SimTable table, int address) const
{
    for (const TableEntry &entry : entries) {
        if (entry.table == table && address >= entry.address && address < entry.end())
            return &entry;
    }
    return nullptr;
}

const UnitProfile *DeviceProfile::unit(quint8 id) const
{
    for (const UnitProfile &u : units) {
        if (u.id == id)
            return &u;
    }
    return nullptr;
}

} // namespace mbscope
