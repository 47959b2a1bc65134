#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// `mbscope watch SESSION`: runs a session's watches headless until stopped (Ctrl-C, SIGTERM,
// --duration, --count), a line per poll, CSV logs with --csv or the session's watchLog; as a
// service (WatchService) Prometheus metrics (--metrics) and MQTT (--mqtt); SIGHUP reloads.
int runWatch(const QStringList &arguments);

} // namespace mbscope::app
