#pragma once

#include "mapexportinput.h"

#include <QtCore/QString>

namespace mbscope {

// Home Assistant's modbus: YAML: one hub, a sensor per register value (data_type, swap, scale, offset, precision, unit_of_measurement, state_class, min_value/max_value, nan_value) and a binary sensor per coil and discrete input.
class HomeAssistantWriter
{
public:
    [[nodiscard]] static QString write(const MapExportInput &input);
};

} // namespace mbscope
