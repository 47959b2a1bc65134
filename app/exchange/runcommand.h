#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope run SESSION [--target URL] [--junit FILE] [--json]: runs a session's test plan.
int runRun(const QStringList &arguments);

} // namespace mbscope::app
