#pragma once

#include "mapexportinput.h"

#include <QtCore/QString>

namespace mbscope {

// Telegraf's Modbus input ([[inputs.modbus]], configuration_type "request"; plugins/inputs/modbus/sample_request.conf): one request per unit, table and byte order, a field per value with its type, scale and register address. Telegraf has no offset: a point with one gets a comment.
class TelegrafWriter
{
public:
    [[nodiscard]] static QString write(const MapExportInput &input);
};

} // namespace mbscope
