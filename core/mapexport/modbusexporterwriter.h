#pragma once

#include "mapexportinput.h"

#include <QtCore/QString>

namespace mbscope {

// A module of the prometheus-community modbus_exporter (modbus.yml): a metric per value, its address the read function code followed by the five-digit register address, dataType, endianness (big ABCD, little DCBA, mixed BADC, yolo CDAB), factor, metricType. It has no strings and no offset: those points get a comment.
class ModbusExporterWriter
{
public:
    [[nodiscard]] static QString write(const MapExportInput &input);
};

} // namespace mbscope
