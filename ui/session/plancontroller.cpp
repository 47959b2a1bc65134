#include "plancontroller.h"

#include "link/linkcontroller.h"
#include "planresultmodel.h"
#include "planworker.h"

#include "engine/transactionengine.h"
#include "session/junitreport.h"
#include "transport/linkurl.h"

#include <QtCore/QThread>

namespace mbscope {

PlanController::PlanController(LinkController *link, QObject *parent)
    : QObject(parent), m_link(link), m_results(new PlanResultModel(this))
{
    qRegisterMetaType<mbscope::StepResult>();
    qRegisterMetaType<mbscope::PlanResult>();
}

PlanController::~PlanController()
{
    if (m_worker) {
        QMetaObject::invokeMethod(m_worker, &PlanWorker::stop, Qt::QueuedConnection);
        m_thread->quit(); // ends the runner's local loops as well
        m_thread->wait();
        delete m_worker;
        delete m_thread;
    }
}

bool PlanController::run(const SessionDocument &document, QString *error)
{
    const auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (m_worker)
        return refuse(tr("The plan is already running."));
    if (document.plan.empty())
        return refuse(tr("The session has no test plan: add a \"plan\" to the session document (see docs/sessions.md)."));
    if (m_link->isPolling())
        return refuse(tr("Stop the poll first: the plan's steps need the device to themselves."));
    LinkUrl url;
    if (m_link->isConnected()) {
        url = m_link->url();
    } else {
        if (document.target.url.isEmpty())
            return refuse(tr("Connect to a device, or save a target in the session, to run the plan against."));
        const LinkUrl::Result parsed = LinkUrl::parse(document.target.url);
        if (!parsed.url)
            return refuse(tr("The session's target %1 is not a target: %2").arg(document.target.url, parsed.error));
        url = *parsed.url;
    }
    if (m_link->engine())
        m_link->engine()->closeLink();

    m_last.reset();
    m_summary.clear();
    m_results->reset(document);
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("mbscope plan"));
    m_worker = new PlanWorker(document, url);
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::started, m_worker, &PlanWorker::run);
    connect(m_worker, &PlanWorker::stepFinished, this, &PlanController::onStep);
    connect(m_worker, &PlanWorker::finished, this, &PlanController::onFinished);
    connect(m_worker, &PlanWorker::framesLogged, this, &PlanController::framesLogged);
    m_thread->start();
    Q_EMIT started(document.name, url.toString());
    Q_EMIT runningChanged(true);
    return true;
}

void PlanController::stop()
{
    if (m_worker)
        QMetaObject::invokeMethod(m_worker, &PlanWorker::stop, Qt::QueuedConnection);
}

void PlanController::onStep(const StepResult &step)
{
    m_results->appendStep(step);
    Q_EMIT stepFinished(step);
}

void PlanController::onFinished(const PlanResult &result)
{
    m_thread->quit();
    m_thread->wait();
    delete m_worker;
    m_worker = nullptr;
    delete m_thread;
    m_thread = nullptr;
    m_last = result;
    m_summary = summaryOf(result);
    Q_EMIT runningChanged(false);
    Q_EMIT finished(m_summary, result.passed());
}

QString PlanController::summaryOf(const PlanResult &result)
{
    QString text = tr("Steps: %1; passed %2, failed %3, errors %4, skipped %5; %6 s against %7.")
                       .arg(result.total())
                       .arg(result.count(StepResult::Outcome::Passed))
                       .arg(result.count(StepResult::Outcome::Failed))
                       .arg(result.count(StepResult::Outcome::Error))
                       .arg(result.count(StepResult::Outcome::Skipped))
                       .arg(QString::number(double(result.elapsedNs) / 1e9, 'f', 3), result.target);
    if (result.linkFailed)
        text = tr("%1 The link failed: %2").arg(text, result.linkMessage);
    else if (result.interrupted)
        text = tr("%1 Stopped before the end.").arg(text);
    return result.passed() ? tr("Passed. %1").arg(text) : tr("Failed. %1").arg(text);
}

bool PlanController::exportJUnit(const QString &path, QString *error) const
{
    if (!m_last) {
        if (error)
            *error = tr("Run the plan before exporting its results.");
        return false;
    }
    return JUnitReport::write(*m_last, path, error);
}

} // namespace mbscope
