#pragma once

#include "protocol/framing.h"
#include "sim/faultplan.h"
#include "sim/simlogentry.h"

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>

#include <optional>

namespace mbscope {

// One line of the simulator's own traffic: what came in (SimLogEntry) together with the fault
// plan made for its answer. The Simulator logs a request right after its fault hook has planned
// the answer, so the record pairs the two (SimFaultPlanRecorder).
struct SimTrafficRecord {
    SimLogEntry entry;
    Framing framing = Framing::Tcp; // the endpoint's, to read the frames
    // The plan the answer went through; none when the request never reached the fault hook
    // (silence, malformed frames, connection events).
    std::optional<FaultPlan> plan;

    // The plan sent nothing (drop) or closed the connection instead of answering.
    [[nodiscard]] bool isDropped() const { return plan && (plan->drop || plan->closeBefore); }
    [[nodiscard]] bool isFaulted() const { return isDropped() || !entry.faults.isEmpty(); }
    // The bytes that left: the plan's chunks, or the answer as built when there was no plan.
    [[nodiscard]] QByteArray sentBytes() const;
    // The plan's delays, summed (0 without a plan).
    [[nodiscard]] qint64 delayNs() const;
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::SimTrafficRecord)
