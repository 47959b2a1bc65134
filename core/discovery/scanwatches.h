#pragma once

#include "unitprobe.h"

#include "watch/watchdefinition.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>

namespace mbscope {

struct UnitScanSettings;
struct RegisterMap;

// Found units turned into watches for the window's workspace and the watch command: a unit
// scan's find becomes one watch of the read that found it; a register map becomes one watch per
// block of addresses that exist (at most 125 registers or 2000 bits each, as one read can carry).
class ScanWatches
{
public:
    [[nodiscard]] static QList<WatchDefinition> fromProbe(const UnitScanSettings &settings, const UnitProbe &probe);
    [[nodiscard]] static QList<WatchDefinition> fromMap(const QString &target, const RegisterMap &map);
    // The watches as a JSON array of objects with the fields of WatchDefinition ("name", "target",
    // "unit", "function", "address", "quantity", "intervalMs", "profileBlock"), for the clipboard.
    [[nodiscard]] static QByteArray toJson(const QList<WatchDefinition> &watches);
};

} // namespace mbscope
