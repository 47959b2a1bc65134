#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope export-map PROFILE --to nodered|telegraf|homeassistant|modbus_exporter|csv [-o FILE]
// [--verify TARGET]: a device profile's register map written for the tool that will poll the
// device; with --verify, every value read once through the map first, and the export refused
// when one is not finite or outside its declared range.
int runExportMap(const QStringList &arguments);

} // namespace mbscope::app
