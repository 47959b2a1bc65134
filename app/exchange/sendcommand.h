#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope send --target URL --hex HEX [--complete] [--unit N] [--timeout 1000ms] [--json]
// Exit 0 ok, 1 the transaction failed (exception, timeout, bad answer), 2 usage or link error.
int runSend(const QStringList &arguments);

} // namespace mbscope::app
