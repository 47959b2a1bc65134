#include "mapexportinput.h"

#include "profile/deviceprofile.h"

#include <cmath>

namespace mbscope {

MapExportInput MapExportInput::fromProfile(const DeviceProfile &profile, std::optional<quint8> unit)
{
    MapExportInput input;
    input.name = profile.name;
    input.source = profile.source;
    input.points = MapPoint::fromProfile(profile, unit);
    input.blocks = ExportBlock::group(input.points, &profile.limits); // as many a request as the device takes
    input.minGapMs = int(std::ceil(profile.limits.minGapMs));
    input.warmUpMs = int(std::ceil(profile.limits.warmUpMs));
    input.clientGap = profile.limits.clientGap();
    input.clientWarmUp = profile.limits.clientWarmUp();
    input.closesAfterAnswer = profile.limits.closesAfterAnswer;
    for (const MapPoint &p : std::as_const(input.points)) {
        const int limit = ExportBlock::maxQuantity(p.table, &profile.limits);
        if (p.registers > limit)
            input.tooLarge.append(QStringLiteral("unit %1 %2 %3 (%4): %5 %6 in one read, more than maxQuantity %7 of function %8")
                                      .arg(p.unitId)
                                      .arg(p.tableKey())
                                      .arg(p.address)
                                      .arg(p.label)
                                      .arg(p.registers)
                                      .arg(p.registers == 1 ? QStringLiteral("register") : QStringLiteral("registers"))
                                      .arg(limit)
                                      .arg(DeviceLimits::functionKey(p.readFunction())));
    }
    return input;
}

} // namespace mbscope
