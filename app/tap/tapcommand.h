#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope tap --listen URL [--listen URL ...] (--target URL | --route UNITS[:UNIT]=URL ...)
//             [--timeout TIME] [--retries N] [--no-answer auto|exception|silence] [--read-only]
//             [--refuse exception|silence] [--pipeline N] [--faults FILE] [--seed N]
//             [--record FILE [--force]] [--duration TIME] [--quiet] [--ready-file FILE]
// The inline tap (issue 27): masters connect to the listening URLs, each request goes on to the
// device its unit's route names (TapForwarder, behind the simulator's endpoints), the answer
// back to the master that asked; one line per request, a summary at the end. Exit 0 after a
// clean stop, 2 for unusable options.
int runTap(const QStringList &arguments);

} // namespace mbscope::app
