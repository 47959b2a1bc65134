#pragma once

#include "exchange/requestitem.h"

#include <QtCore/QList>
#include <QtCore/QMetaType>

namespace mbscope {

// A poll: the items sent in order, one cycle after another. The interval runs start to start,
// from the actual start of one cycle (its first request handed to the link: the first cycle
// waits for the link to open) to the next; a cycle that takes longer than the interval
// delays the next, which then starts as soon as it can and counts as an overrun. interval 0 runs
// the cycles back to back. The poll ends after count cycles or once duration has passed (no
// cycle starts after it; the one running ends), whichever comes first; with neither it runs until
// stopped. With pipelining the next cycle starts as soon as the pipeline has room, so that
// several cycles can be in flight.
struct PollSettings {
    QList<RequestItem> items;
    qint64 intervalNs = 0;
    quint64 count = 0;     // cycles; 0: no count limit
    qint64 durationNs = 0; // 0: no duration limit
    // The poll's latencies past this many are binned (LatencySamples::setExactLimit); 0: all kept.
    std::size_t exactLatencyLimit = 0;
};

// The same poll run once per interval, in order (interval of the poll ignored).
struct SweepSettings {
    PollSettings poll;
    QList<qint64> intervalsNs;
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::PollSettings)
Q_DECLARE_METATYPE(mbscope::SweepSettings)
