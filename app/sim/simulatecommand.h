#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope simulate --profile NAME|FILE [--listen URL ...] [--faults FILE] [--log FILE.jsonl]
//                  [--duration 60s] [--quiet] [--seed N] [--ready-file FILE]
// mbscope simulate --list-profiles
// Serves a device profile until SIGINT/SIGTERM or --duration, then prints a summary. --ready-file
// FILE appears once every endpoint listens (ReadyFile), for scripts that start it in the background.
// Exit 0 after a clean stop, 2 for unusable options (unknown profile, bad URL, port in use, bad
// faults file).
int runSimulate(const QStringList &arguments);

} // namespace mbscope::app
