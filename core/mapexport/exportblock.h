#pragma once

#include "mappoint.h"

#include <QtCore/QList>

namespace mbscope {

// A run of points one read request fetches: same unit and table, no address between them
// left out, at most maxQuantity registers (bits), which the device profile's limits may lower.
struct ExportBlock {
    quint8 unitId = 1;
    SimTable table = SimTable::HoldingRegisters;
    quint16 start = 0;
    int quantity = 0;
    QList<qsizetype> points; // indexes into the list grouped

    // Groups points (in fromProfile's order) into blocks of at most maxQuantity() each.
    [[nodiscard]] static QList<ExportBlock> group(const QList<MapPoint> &points, const DeviceLimits *limits = nullptr);
    // The most a read of table may ask for: the protocol's limit (125 registers, 2000 bits),
    // lowered by the device's "limits.maxQuantity" for the function that reads it.
    [[nodiscard]] static int maxQuantity(SimTable table, const DeviceLimits *limits = nullptr);
};

} // namespace mbscope
