#pragma once

#include "exportblock.h"
#include "mappoint.h"

#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <algorithm>
#include <chrono>

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
    // The waits a client keeps for them, with poll --profile's margins (DeviceLimits::clientGap),
    // and whether the device hangs up after each answer: what --verify keeps when it reads.
    std::chrono::milliseconds clientGap{0};
    std::chrono::milliseconds clientWarmUp{0};
    bool closesAfterAnswer = false;

    // url with at least the device's pace (gap=, warmup=, close=each): the reads of --verify
    // keep it, as the tool the map is exported to will.
    [[nodiscard]] LinkUrl paced(LinkUrl url) const
    {
        url.gap = std::max(url.gap, clientGap);
        url.warmUp = std::max(url.warmUp, clientWarmUp);
        url.closeAfterAnswer = url.closeAfterAnswer || (closesAfterAnswer && !url.isSerial() && !url.isDatagram());
        return url;
    }

    // Points one read cannot fetch whole within the device's largest quantity (a 5-register string
    // with maxQuantity 4): one line each ("unit 1 holding 20 (Serial number): 5 registers in one
    // read, more than maxQuantity 4 of function 0x03"). No tool can poll them: an export refuses.
    QStringList tooLarge;

    // Name, source, the points of the profile (of one unit, or of all), their blocks within the
    // device's largest quantities, and its gap and warm-up; the endpoint, interval and timeout
    // are the caller's.
    [[nodiscard]] static MapExportInput fromProfile(const DeviceProfile &profile, std::optional<quint8> unit = std::nullopt);
};

} // namespace mbscope
