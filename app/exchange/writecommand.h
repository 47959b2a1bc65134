#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope write --target URL [--unit 1] (--coils 1,0,0 | --registers 205,172,73 [--format F])
//               --address A [--single] [--timeout 1000ms] [--json]
// Exit 0 every write ok, 1 some failed, 2 usage or link error.
int runWrite(const QStringList &arguments);

} // namespace mbscope::app
