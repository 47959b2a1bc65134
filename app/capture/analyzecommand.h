#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope analyze CAPTURE: a pcap, pcapng or traffic journal read offline: requests paired with
// answers, every frame decoded, statistics and the latency histogram as poll prints them.
int runAnalyze(const QStringList &arguments);

} // namespace mbscope::app
