#pragma once

#include "exportblock.h"
#include "mappoint.h"

#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

struct DeviceProfile;

// What every map writer gets: the points, the blocks that read them, where the device is, how
// often to poll it and how gently (the profile's "limits": docs/profiles.md, "Device limits").
struct MapExportInput {
    QString name;            // the profile's name: the tool's device, hub or module name
    QString source;          // where the profile came from, for the header comment
    LinkUrl endpoint;        // tcp://, rtu-tcp:// (and rtu:// for the tools that take a serial line)
    int intervalMs = 1000;   // poll interval
    int timeoutMs = 1000;
    QList<MapPoint> points;
    QList<ExportBlock> blocks;  // ExportBlock::group(points, the device's limits)
    // The device's limits.minGapMs and limits.warmUpMs (0: none), whole milliseconds rounded up:
    // each tool that has a setting for them gets it (a pause between requests, a pause after a
    // connection opens), and a tool that has none says so in a comment.
    int minGapMs = 0;
    int warmUpMs = 0;

    // Name, source, the points of the profile (of one unit, or of all), their blocks within the
    // device's largest quantities, and its gap and warm-up; the endpoint, interval and timeout
    // are the caller's.
    [[nodiscard]] static MapExportInput fromProfile(const DeviceProfile &profile, std::optional<quint8> unit = std::nullopt);
};

} // namespace mbscope
