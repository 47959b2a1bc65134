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
    return input;
}

} // namespace mbscope
