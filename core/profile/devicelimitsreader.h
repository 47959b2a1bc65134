#pragma once

#include "devicelimits.h"

#include <QtCore/QJsonObject>

namespace mbscope {

class JsonReader;

// Reads a profile's "unknownUnit" and "limits" (docs/profiles.md, "Device limits") from the
// profile's top-level object, recording problems in the reader.
class DeviceLimitsReader
{
public:
    [[nodiscard]] static DeviceLimits read(JsonReader &reader, const QJsonObject &root);
    // The most a function code may ask for by the specification (V1.1b3, 6.1-6.17): 01/02 2000
    // bits, 03/04 125 registers, 0F 1968 bits, 10 123 registers, 17 125 read; 0 for others.
    [[nodiscard]] static int specMaxQuantity(quint8 function);
};

} // namespace mbscope
