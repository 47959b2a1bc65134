#pragma once

#include "engineprogress.h"
#include "exchange/statisticsset.h"

#include <QtCore/QList>
#include <QtCore/QMetaType>

namespace mbscope {

// The result of one poll at one interval.
struct PollRun {
    qint64 intervalNs = 0;
    StatisticsSet statistics;   // overall and per request item
    EngineCounters counters;    // what the engine counted during the run (unsolicited, skipped, ...)
    quint64 cycles = 0;
    quint64 overruns = 0;
    qint64 elapsedNs = 0;       // first cycle's start to the last answer
    bool stopped = false;       // ended by stop() before its count or duration
};

// What a poll (one run) or a sweep (one run per interval) delivers when it ends.
struct PollReport {
    bool sweep = false;
    bool stopped = false;
    QList<PollRun> runs;
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::PollReport)
