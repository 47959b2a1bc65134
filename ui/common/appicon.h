#pragma once

#include <QtGui/QIcon>

namespace mbscope {

// mbscope's icon (packaging/icons/mbscope.svg, compiled in as :/icons/mbscope.svg by
// resources/CMakeLists.txt) for the window and the application, rendered at the sizes desktops
// ask for. Rendered through Qt SVG when mbscope_ui has it, so it shows even where Qt's SVG icon
// engine plugin is not installed; null when the resource is missing from the executable.
[[nodiscard]] QIcon applicationIcon();

} // namespace mbscope
