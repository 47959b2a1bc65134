#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope poll --target URL (--hex HEX... | read options | write options) [--interval 100ms]
//              [--count 100 | --duration 60s] [--pipeline N] [--stats] [--histogram latency.png] [--json]
// Exit 0 every transaction ok, 1 some failed, 2 usage or link error. Ctrl-C stops the poll and the
// statistics so far are printed.
int runPoll(const QStringList &arguments);
// Poll (sweep false) or sweep: they share options and the run, and differ in what they print.
int runPollOrSweep(const QStringList &arguments, bool sweep);

} // namespace mbscope::app
