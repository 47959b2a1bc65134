#pragma once

#include "pollbaselines.h"

namespace mbscope::bench {

struct EnginePollSettings {
    // Where every frame goes: nowhere; a TrafficLog in memory only (the window's log without a
    // journal); a TrafficRecording journaling to a file, as a command's --record does (the
    // metadata first, a small in-memory window, a batch write per 1,024 frames or 100 ms).
    enum class Log { Off, Memory, Journal };
    PollPlan plan;
    Log log = Log::Journal;
    int pipelineDepth = 1; // requests in flight (EngineOptions::pipelineDepth)
};

// mbscope's TransactionEngine polling the same request back to back (interval 0) through a
// TcpLink: a warm-up poll, then the measured one. Latencies are the engine's own (doneNs - sentNs,
// the statistics of the run), the time is the run's elapsed time (first cycle's start to the
// last answer). Needs a QCoreApplication (the engine delivers its report through the event loop).
[[nodiscard]] PollFigures pollEngine(const EnginePollSettings &settings);

} // namespace mbscope::bench
