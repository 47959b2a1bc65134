#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope monitor URL [--count N] [--duration D] [--timeout D] [--silence D] [--json] [--quiet]
//                     [--record FILE [--force]]
// Listens to a bus another master drives (rtu://, ascii://, rtu-tcp://, ascii-tcp://) without
// ever sending a byte, and prints every exchange and the statistics poll prints.
// Exit 0 every exchange ok, 1 some failed or damaged frames were seen, 2 usage or link error.
int runMonitor(const QStringList &arguments);

} // namespace mbscope::app
