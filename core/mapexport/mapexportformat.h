#pragma once

#include "mapexportinput.h"

#include "profile/deviceprofile.h"

#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>

namespace mbscope {

// The tools a verified register map is exported for (mbscope export-map --to FORMAT).
enum class MapExportFormat : quint8 {
    NodeRed,        // a Node-RED flow with node-red-contrib-modbus nodes
    Telegraf,       // Telegraf [[inputs.modbus]], "request" configuration style
    HomeAssistant,  // Home Assistant modbus: YAML
    ModbusExporter, // prometheus-community modbus_exporter module YAML
    Csv,            // one value a row
};

// Writes the map in one format; each writer is a class of its own (noderedwriter.h ...).
class MapExporter
{
public:
    // "nodered", "telegraf", "homeassistant", "modbus_exporter", "csv".
    [[nodiscard]] static QString formatName(MapExportFormat format);
    [[nodiscard]] static std::optional<MapExportFormat> formatFromName(QStringView name);
    [[nodiscard]] static QString formatNames(); // "nodered, telegraf, ... or csv"
    // What the format cannot say about the endpoint (a serial line for modbus_exporter); empty when it can.
    [[nodiscard]] static QString unsupportedEndpoint(MapExportFormat format, const LinkUrl &endpoint);
    [[nodiscard]] static QString write(MapExportFormat format, const MapExportInput &input);
    // Where the tool reaches the device when nobody says: the profile's first endpoint the format
    // takes, else tcp://127.0.0.1:502 (export-map without --endpoint, the window's Export map).
    [[nodiscard]] static LinkUrl defaultEndpoint(const DeviceProfile &profile, MapExportFormat format);
};

} // namespace mbscope
