#pragma once

#include "mapexportinput.h"

#include <QtCore/QString>

namespace mbscope {

// CSV, one value a row (RFC 4180): unit, table, function, address, registers, name, label, type, order, scale, offset, unit, kind, min, max, writable, length, padding, not_implemented, enum, bits, description.
class CsvMapWriter
{
public:
    [[nodiscard]] static QString write(const MapExportInput &input);
};

} // namespace mbscope
