#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope sweep --target URL (--hex HEX... | read options | write options) --intervals 100,200,300
//               (--count 300 | --duration 60s) [--pipeline N] [--stats] [--histogram latency.png] [--json]
// The same poll at each interval in turn: a table of interval against error rate and latency.
// Exit 0 every transaction ok, 1 some failed, 2 usage or link error.
int runSweep(const QStringList &arguments);

} // namespace mbscope::app
