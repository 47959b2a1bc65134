#pragma once

#include "exportblock.h"
#include "mappoint.h"

#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// What every map writer gets: the points, the blocks that read them, where the device is and
// how often to poll it.
struct MapExportInput {
    QString name;            // the profile's name: the tool's device, hub or module name
    QString source;          // where the profile came from, for the header comment
    LinkUrl endpoint;        // tcp://, rtu-tcp:// (and rtu:// for the tools that take a serial line)
    int intervalMs = 1000;   // poll interval
    int timeoutMs = 1000;
    QList<MapPoint> points;
    QList<ExportBlock> blocks;  // ExportBlock::group(points, the device's limits)
};

} // namespace mbscope
