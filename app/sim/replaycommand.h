#pragma once

#include <QtCore/QStringList>

namespace mbscope::app {

// mbscope replay SOURCE: a recorded session, traffic journal or pcap/pcapng re-sent to a live
// target and each answer compared with the recorded one (--target), or served as a stand-in
// device that answers with the recorded answers (--serve).
int runReplay(const QStringList &arguments);

} // namespace mbscope::app
