#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope conform --target URL [--unit N] [--timeout D] [--profile NAME|FILE] [--readable T:A]
//                 [--missing T:A] [--writable T:A[-B]] [--only PREFIX,...] [--samples N]
//                 [--json] [--junit FILE] [--record FILE] [--force] [--list]
// The conformance scorecard of a Modbus slave: a battery of checks, each citing its clause, judged
// from the raw answer bytes (core/conformance). Reads only, unless --writable names addresses.
// Exit 0 every mandatory check passed, 1 one failed (or Ctrl-C), 2 usage or link error (the target
// refused, or answered nothing at all).
int runConform(const QStringList &arguments);

} // namespace mbscope::app
