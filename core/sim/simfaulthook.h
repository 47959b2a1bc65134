#pragma once

#include "sim/simulator.h"

namespace mbscope {

class FaultInjector;

// The Simulator's fault hook that asks injector for each answer's plan (FaultInjector::plan
// with FaultContext::forExchange). The injector must outlive the simulator or be detached first
// (setFaultHook({})); its rules may change while the simulator runs.
//
//     FaultInjector injector;
//     ProfileApplier::configure(&injector, profile);
//     sim.setFaultHook(faultHookFor(&injector));
[[nodiscard]] Simulator::FaultHook faultHookFor(FaultInjector *injector);

} // namespace mbscope
