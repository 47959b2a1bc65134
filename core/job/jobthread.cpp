#include "jobthread.h"

#include "job.h"

#include <QtCore/QThread>

namespace mbscope {

JobThread::JobThread(QObject *parent)
    : QObject(parent)
    , m_thread(new QThread(this))
    , m_anchor(new QObject)
{
    m_thread->setObjectName(QStringLiteral("mbscope-job"));
    m_anchor->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_anchor, &QObject::deleteLater);
    m_thread->start();
}

JobThread::~JobThread()
{
    if (m_job)
        m_job->cancel();
    // exit() ends every event loop of the thread, the work's local ones too: it returns at once.
    m_thread->quit();
    m_thread->wait();
}

void JobThread::adopt(QObject *worker)
{
    Q_ASSERT(!worker->parent());
    worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, worker, &QObject::deleteLater);
}

bool JobThread::isBusy() const
{
    return m_job && m_job->isActive();
}

bool JobThread::run(Job *job, std::function<Outcome()> work)
{
    if (isBusy())
        return false;
    m_job = job;
    job->begin();
    QMetaObject::invokeMethod(m_anchor, [job, work = std::move(work)] {
        const Outcome outcome = work();
        // To the job's thread; dropped when the job is gone by then.
        QMetaObject::invokeMethod(job, [job, outcome] {
            if (outcome.deliver)
                outcome.deliver();
            job->finish(outcome.end);
        });
    });
    return true;
}

} // namespace mbscope

#include "moc_jobthread.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
