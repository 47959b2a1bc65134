#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope decode [--framing F] [--direction D] [--request HEX] [--json] [HEX...]
// Exit 0 for a valid frame, 1 for a frame with errors, 2 for unusable input.
int runDecode(const QStringList &arguments);

} // namespace mbscope::app
