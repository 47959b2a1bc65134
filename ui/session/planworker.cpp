#include "planworker.h"

#include "session/planrunner.h"

namespace mbscope {

PlanWorker::PlanWorker(const SessionDocument &document, const LinkUrl &url)
    : m_document(document), m_url(url)
{
    qRegisterMetaType<mbscope::StepResult>();
    qRegisterMetaType<mbscope::PlanResult>();
}

PlanWorker::~PlanWorker() = default;

void PlanWorker::run()
{
    PlanRunner runner(m_document, m_url, m_document.target);
    runner.setFramesObserver([this](const QList<TrafficFrame> &frames, const QString &link) { Q_EMIT framesLogged(frames, link); });
    m_runner = &runner;
    if (m_stopRequested) {
        m_runner = nullptr;
        PlanResult none;
        none.name = m_document.name;
        none.target = m_url.toString();
        none.interrupted = true;
        Q_EMIT finished(none);
        return;
    }
    const PlanResult result = runner.run([this](const StepResult &step) { Q_EMIT stepFinished(step); });
    m_runner = nullptr;
    Q_EMIT finished(result);
}

void PlanWorker::stop()
{
    m_stopRequested = true;
    if (m_runner)
        m_runner->stop();
}

} // namespace mbscope
