#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope export SOURCE --csv FILE | --jsonl FILE | --pcap FILE (and plots): a capture or
// traffic journal written out one row per transaction, or as packets Wireshark decodes.
int runExport(const QStringList &arguments);

} // namespace mbscope::app
