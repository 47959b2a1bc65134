#pragma once

#include "protocol/framing.h"
#include "sim/faultplan.h"
#include "sim/simlogentry.h"

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>

namespace mbscope {

// One line of the simulator's own traffic: what came in (SimLogEntry) together with what the
// fault plan made of the answer. The Simulator logs a request right after its fault hook has
// planned the answer, so the record pairs the two (SimFaultPlanRecorder).
struct SimTrafficRecord {
    SimLogEntry entry;
    Framing framing = Framing::Tcp; // the endpoint's, to read the frames
    bool planned = false;   // the answer went through the fault hook (entry.response is set)
    bool dropped = false;   // the plan sent nothing (drop) or closed the connection instead
    bool closedAfter = false;
    QByteArray sent;        // the bytes the plan wrote, all chunks (empty when dropped)
    qint64 delayNs = 0;     // the plan's delays, summed

    [[nodiscard]] bool isFaulted() const { return dropped || !entry.faults.isEmpty(); }
    // entry with plan (nullptr: the request never reached the hook: silence, malformed, events).
    [[nodiscard]] static SimTrafficRecord of(const SimLogEntry &entry, const FaultPlan *plan);
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::SimTrafficRecord)
