#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope scan --target URL [--units 1-247 | --all-ids] [--function 3 --address 0 --quantity 1]
//              [--timeout 200ms] [--gap 20ms] [--max-time 10min] [--all] [--json] [--watches FILE]
// mbscope scan --target URL --map UNIT [--addresses 0-999] [--tables 1,2,3,4] [--no-optional]
//              [--profile-out FILE] [--max-requests N]
// mbscope scan --target rtu:///dev/ttyUSB0 --line [--bauds LIST] [--parities LIST] [--stops LIST]
// mbscope scan --target URL --timing UNIT
// Finds what is on a link: which unit ids answer, a unit's register map (saved as a profile draft
// the simulator serves), a serial line's settings, and a device's timing limits. Only reads.
// Exit 0 when something was found, 1 when nothing was, 2 for usage or link errors.
int runScan(const QStringList &arguments);

} // namespace mbscope::app
