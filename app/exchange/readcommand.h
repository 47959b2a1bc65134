#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope read --target URL [--unit 1] [--function 3] [--address 0x79] [--quantity 22]
//              [--format u16,hex,...] [--timeout 1000ms] [--json]
// Exit 0 ok, 1 the transaction failed, 2 usage or link error.
int runRead(const QStringList &arguments);

} // namespace mbscope::app
