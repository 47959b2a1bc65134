#pragma once

#include <QtCore/QMetaType>
#include <QtCore/QtGlobal>

namespace mbscope {

// What the engine has seen beyond the transactions it records. Nothing that arrives is dropped
// without being counted here (and logged to the traffic log when one is attached).
struct EngineCounters {
    quint64 requestsSent = 0;     // writes, retries included
    quint64 transactions = 0;     // records made (late records included)
    quint64 retries = 0;          // attempts after the first
    quint64 late = 0;             // answers that came after their request timed out
    quint64 unsolicitedFrames = 0; // whole frames no pending or timed-out request explains
    quint64 duplicateFrames = 0;  // of which: a second answer to a request already answered
    quint64 skippedRuns = 0;      // runs of bytes the framer could not use (garbage, partial frames)
    quint64 skippedBytes = 0;
    quint64 bytesIn = 0;
    quint64 bytesOut = 0;
    quint64 connects = 0;         // link openings, the first included
    quint64 linkErrors = 0;       // errors and closings reported by the link
    quint64 abandoned = 0;        // requests in flight when a poll was stopped (not recorded)
    quint64 cycles = 0;           // poll cycles started
    quint64 overruns = 0;         // cycles that started late because the one before was still running

    [[nodiscard]] EngineCounters operator-(const EngineCounters &earlier) const;
};

// A snapshot for observers, sent with each batch (at most ~30 a second).
struct EngineProgress {
    EngineCounters counters;
    bool polling = false;
    int run = 0;              // sweep: index of the interval being run; poll: 0
    int runs = 0;             // sweep: number of intervals; poll: 1; 0 when not polling
    qint64 intervalNs = 0;    // the interval of the run
    quint64 cycle = 0;        // cycles started in this run
    quint64 cyclesPlanned = 0; // the run's count (0: until the duration ends or stop)
    qint64 elapsedNs = 0;     // since the run started
    qint64 durationNs = 0;    // the run's duration (0: none)
    quint64 ok = 0;           // this run's transactions so far
    quint64 failed = 0;
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::EngineProgress)
