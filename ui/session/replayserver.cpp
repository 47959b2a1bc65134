#include "replayserver.h"

#include "replay/replayscript.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"

#include <QtCore/QMetaObject>

namespace mbscope {

ReplayServer::ReplayServer(QObject *parent)
    : QObject(parent)
{
    m_thread.setObjectName(QStringLiteral("mbscope replay server"));
}

ReplayServer::~ReplayServer()
{
    stop();
}

bool ReplayServer::start(const ReplayScript &script, const QString &url, ReplayResponder::Unrecorded unrecorded, double speed,
                         QString *error)
{
    stop();
    auto responder = std::make_unique<ReplayResponder>(script, unrecorded, speed);
    m_anchor = new QObject;
    m_thread.start();
    m_anchor->moveToThread(&m_thread);
    ReplayResponder *rawResponder = responder.get();
    Simulator *simulator = nullptr;
    LinkUrl bound;
    QString problem;
    // Sockets and timers belong to the thread that makes them: the simulator is made there.
    QMetaObject::invokeMethod(
        m_anchor,
        [&] {
            auto sim = std::make_unique<Simulator>();
            rawResponder->install(*sim);
            SimEndpoint *endpoint = sim->listen(url, rawResponder->endpointOptions(), &problem);
            if (!endpoint) {
                sim->setFaultHook({});
                return;
            }
            bound = endpoint->boundUrl();
            simulator = sim.release();
        },
        Qt::BlockingQueuedConnection);
    if (!simulator) {
        if (error)
            *error = tr("Cannot serve the recording on %1: %2").arg(url, problem);
        m_thread.quit();
        m_thread.wait();
        delete m_anchor;
        m_anchor = nullptr;
        return false;
    }
    m_simulator = simulator;
    m_responder = std::move(responder);
    m_distinct = m_responder->distinctRequests();
    m_bound = bound;
    Q_EMIT servingChanged(true);
    return true;
}

void ReplayServer::stop()
{
    if (!m_simulator)
        return;
    Simulator *simulator = m_simulator;
    QMetaObject::invokeMethod(
        m_anchor,
        [simulator] {
            simulator->closeAll();
            simulator->setFaultHook({});
            delete simulator;
        },
        Qt::BlockingQueuedConnection);
    m_simulator = nullptr;
    m_thread.quit();
    m_thread.wait();
    delete m_anchor;
    m_anchor = nullptr;
    m_responder.reset();
    Q_EMIT servingChanged(false);
}

ReplayResponder::Counters ReplayServer::counters() const
{
    if (!m_simulator || !m_responder)
        return {};
    ReplayResponder::Counters counters;
    const ReplayResponder *responder = m_responder.get();
    QMetaObject::invokeMethod(
        m_anchor, [&counters, responder] { counters = responder->counters(); }, Qt::BlockingQueuedConnection);
    return counters;
}

} // namespace mbscope
