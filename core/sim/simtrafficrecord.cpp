#include "sim/simtrafficrecord.h"

namespace mbscope {

SimTrafficRecord SimTrafficRecord::of(const SimLogEntry &entry, const FaultPlan *plan)
{
    SimTrafficRecord record;
    record.entry = entry;
    if (!plan)
        return record;
    record.planned = true;
    record.dropped = plan->drop || plan->closeBefore;
    record.closedAfter = plan->closeAfter;
    if (record.dropped)
        return record;
    for (const ResponseChunk &chunk : plan->chunks) {
        record.sent += chunk.bytes;
        record.delayNs += chunk.delayNs;
    }
    return record;
}

} // namespace mbscope
