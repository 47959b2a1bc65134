#pragma once

#include "devicelimits.h"

#include <QtCore/QJsonObject>

namespace mbscope {

class JsonReader;

// Reads a profile's "unknownUnit", "answersBroadcasts" and "limits" (docs/profiles.md, "Device limits") from the
// profile's top-level object, recording problems in the reader.
class DeviceLimitsReader
{
public:
    [[nodiscard]] static DeviceLimits read(JsonReader &reader, const QJsonObject &root);
};

} // namespace mbscope
