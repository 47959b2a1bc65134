#pragma once

#include "mapexportinput.h"

#include <QtCore/QString>

namespace mbscope {

// A Node-RED flow (JSON) with node-red-contrib-modbus nodes: a modbus-client for the endpoint, a modbus-read per block (function, unit, start, quantity, poll rate) and a function node after each that converts the registers into one message whose payload holds every value of the block by name (scaled, strings without padding, null for a "not implemented" sentinel, enumerations with their meaning in NAME_text, named bits in NAME_bits), ending in a debug node.
class NodeRedWriter
{
public:
    [[nodiscard]] static QString write(const MapExportInput &input);
};

} // namespace mbscope
