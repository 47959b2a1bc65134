#include "engineprogress.h"

namespace mbscope {

EngineCounters EngineCounters::operator-(const EngineCounters &earlier) const
{
    EngineCounters d;
    d.requestsSent = requestsSent - earlier.requestsSent;
    d.transactions = transactions - earlier.transactions;
    d.retries = retries - earlier.retries;
    d.late = late - earlier.late;
    d.unsolicitedFrames = unsolicitedFrames - earlier.unsolicitedFrames;
    d.duplicateFrames = duplicateFrames - earlier.duplicateFrames;
    d.skippedRuns = skippedRuns - earlier.skippedRuns;
    d.skippedBytes = skippedBytes - earlier.skippedBytes;
    d.bytesIn = bytesIn - earlier.bytesIn;
    d.bytesOut = bytesOut - earlier.bytesOut;
    d.connects = connects - earlier.connects;
    d.linkErrors = linkErrors - earlier.linkErrors;
    d.abandoned = abandoned - earlier.abandoned;
    d.cycles = cycles - earlier.cycles;
    d.overruns = overruns - earlier.overruns;
    return d;
}

} // namespace mbscope
