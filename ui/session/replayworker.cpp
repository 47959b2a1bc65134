#include "replayworker.h"

#include "engine/engineoptions.h"
#include "replay/replayrunner.h"
#include "replay/replayscript.h"

namespace mbscope {

ReplayWorker::ReplayWorker(std::shared_ptr<const ReplayScript> script, const LinkUrl &target, double speed, bool sendWrites,
                           int timeoutMs)
    : m_script(std::move(script)), m_target(target), m_speed(speed), m_sendWrites(sendWrites), m_timeoutMs(timeoutMs)
{
    qRegisterMetaType<mbscope::ReplayOutcome>();
    qRegisterMetaType<mbscope::ReplayResult>();
}

ReplayWorker::~ReplayWorker() = default;

void ReplayWorker::run()
{
    ReplayRunner runner(*m_script, m_target, EngineOptions{}, m_timeoutMs);
    runner.setSpeed(m_speed);
    runner.setSendWrites(m_sendWrites);
    m_runner = &runner;
    if (m_stopRequested)
        runner.stop();
    QString linkProblem;
    const ReplayResult result = runner.run([&](const ReplayOutcome &outcome) {
        Q_EMIT outcomeReady(outcome);
        if (outcome.replayed.status == TransactionStatus::LinkError && linkProblem.isEmpty()) {
            linkProblem = outcome.replayed.problem;
            runner.stop();
        }
    });
    m_runner = nullptr;
    Q_EMIT finished(result, linkProblem);
}

void ReplayWorker::stop()
{
    m_stopRequested = true;
    if (m_runner)
        m_runner->stop();
}

} // namespace mbscope
