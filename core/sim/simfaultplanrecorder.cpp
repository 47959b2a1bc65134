#include "sim/simfaultplanrecorder.h"

#include "sim/faultinjector.h"
#include "sim/simexchange.h"
#include "sim/simulator.h"

namespace mbscope {

SimFaultPlanRecorder::SimFaultPlanRecorder(Simulator *simulator, FaultInjector *injector, QObject *parent)
    : QObject(parent), m_simulator(simulator)
{
    simulator->setFaultHook([this, injector](const SimExchange &exchange) {
        m_plan = injector->plan(exchange);
        return *m_plan;
    });
    connect(simulator, &Simulator::logged, this, &SimFaultPlanRecorder::onLogged, Qt::DirectConnection);
}

SimFaultPlanRecorder::~SimFaultPlanRecorder()
{
    if (m_simulator)
        m_simulator->setFaultHook({});
}

void SimFaultPlanRecorder::onLogged(const SimLogEntry &entry)
{
    SimTrafficRecord record;
    record.entry = entry;
    if (!entry.response.isEmpty())
        record.plan.swap(m_plan);
    m_plan.reset();
    Q_EMIT recorded(record);
}

} // namespace mbscope

#include "moc_simfaultplanrecorder.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
