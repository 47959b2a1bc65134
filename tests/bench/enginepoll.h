#pragma once

#include "pollbaselines.h"

namespace mbscope::bench {

struct EnginePollSettings {
    PollPlan plan;
    bool logTraffic = true; // every frame into a TrafficLog journaled to a file, as the CLI does
    int pipelineDepth = 1;  // requests in flight (EngineOptions::pipelineDepth)
};

// mbscope's TransactionEngine polling the same request back to back (interval 0) through a
// TcpLink: a warm-up poll, then the measured one. Latencies are the engine's own (doneNs - sentNs,
// the statistics of the run), the time is the run's elapsed time (first cycle's start to the
// last answer). Needs a QCoreApplication (the engine delivers its report through the event loop).
[[nodiscard]] PollFigures pollEngine(const EnginePollSettings &settings);

} // namespace mbscope::bench
