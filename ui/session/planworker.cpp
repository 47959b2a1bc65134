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
    if (m_stopRequested)
        runner.stop(); // stopped before it started: every step is reported skipped, as in the CLI
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
