#pragma once

#include "sim/faultplan.h"
#include "sim/simtrafficrecord.h"

#include <QtCore/QObject>
#include <QtCore/QPointer>

#include <optional>

namespace mbscope {

class FaultInjector;
class Simulator;

// The simulator's fault hook (the injector plans each answer) together with a record of what
// happened to every request: Simulator::handleFrame asks the hook first and logs the request
// with its answer right after, so the plan just made belongs to the next logged entry that has
// an answer. Entries without an answer (silence, malformed frames, connection events) never went
// through the hook. Lives in the simulator's thread; the injector must outlive it.
class SimFaultPlanRecorder : public QObject
{
    Q_OBJECT
public:
    SimFaultPlanRecorder(Simulator *simulator, FaultInjector *injector, QObject *parent = nullptr);
    ~SimFaultPlanRecorder() override; // detaches the hook

Q_SIGNALS:
    void recorded(const mbscope::SimTrafficRecord &record);

private:
    void onLogged(const SimLogEntry &entry);

    QPointer<Simulator> m_simulator;
    std::optional<FaultPlan> m_plan;
};

} // namespace mbscope
