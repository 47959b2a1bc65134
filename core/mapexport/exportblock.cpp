#include "exportblock.h"

#include <algorithm>

namespace mbscope {

namespace {

int protocolLimit(SimTable table)
{
    return isBitTable(table) ? 2000 : 125; // V1.1b3 6.1-6.4
}

} // namespace

int ExportBlock::maxQuantity(SimTable table, const DeviceLimits *limits)
{
    MapPoint p;
    p.table = table;
    const int limit = protocolLimit(table);
    const int declared = limits ? limits->maxQuantity.value(p.readFunction(), 0) : 0;
    return declared > 0 ? std::min(limit, declared) : limit;
}

QList<ExportBlock> ExportBlock::group(const QList<MapPoint> &points, const DeviceLimits *limits)
{
    QList<ExportBlock> blocks;
    for (qsizetype i = 0; i < points.size(); ++i) {
        const MapPoint &p = points.at(i);
        const int limit = maxQuantity(p.table, limits);
        if (!blocks.isEmpty()) {
            ExportBlock &b = blocks.last();
            if (b.unitId == p.unitId && b.table == p.table && b.start + b.quantity == p.address
                && b.quantity + p.registers <= limit) {
                b.quantity += p.registers;
                b.points.append(i);
                continue;
            }
        }
        ExportBlock b;
        b.unitId = p.unitId;
        b.table = p.table;
        b.start = p.address;
        b.quantity = p.registers;
        b.points.append(i);
        blocks.append(b);
    }
    return blocks;
}

} // namespace mbscope
