#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// `mbscope watch SESSION`: runs the session's watches headless until stopped, as a service:
// CSV logs (--csv), Prometheus metrics (--metrics), MQTT (--mqtt), SIGHUP reloads the session.
int runWatch(const QStringList &arguments);

} // namespace mbscope::app
