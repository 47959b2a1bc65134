#pragma once

#include "script/scripttables.h"

#include <QtCore/QPointer>

namespace mbscope {

class SimUnit;

// A SimUnit's tables as its script reads and writes them (local writes: views see them,
// clients read them; no writable check).
class SimScriptTables : public ScriptTables
{
public:
    explicit SimScriptTables(SimUnit *unit);
    [[nodiscard]] int unitId() const override;
    [[nodiscard]] std::optional<quint16> value(ScriptTable table, int address) const override;
    bool setValues(ScriptTable table, int address, const QList<quint16> &values) override;

private:
    QPointer<SimUnit> m_unit;
};

} // namespace mbscope
