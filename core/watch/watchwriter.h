#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QJsonObject>

namespace mbscope {

// Writes watches as WatchReader reads them: what was read is written back the same, values at
// their defaults are left out, addresses are written in hex ("0x0079").
class WatchWriter
{
public:
    // Adds "watches", "watchLinks" and "watchLog" to root (each only when there is something).
    static void write(const SessionWatches &watches, QJsonObject *root);
    [[nodiscard]] static QJsonObject watchToJson(const WatchDefinition &watch);
};

} // namespace mbscope
