#include "job.h"

namespace mbscope {

Job::Job(QObject *parent)
    : QObject(parent)
{
}

JobState Job::state() const
{
    const QMutexLocker locker(&m_lock);
    return m_state;
}

bool Job::isActive() const
{
    const JobState s = state();
    return s == JobState::Running || s == JobState::Stopping;
}

JobProgress Job::progress() const
{
    const QMutexLocker locker(&m_lock);
    return m_progress;
}

std::optional<JobEnd> Job::end() const
{
    const QMutexLocker locker(&m_lock);
    return m_end;
}

QStringList Job::problems() const
{
    const QMutexLocker locker(&m_lock);
    return m_problems;
}

void Job::setState(JobState state)
{
    {
        const QMutexLocker locker(&m_lock);
        if (m_state == state)
            return;
        m_state = state;
    }
    Q_EMIT stateChanged(state);
}

void Job::begin()
{
    {
        const QMutexLocker locker(&m_lock);
        m_progress = JobProgress{};
        m_end.reset();
        m_problems.clear();
    }
    m_cancel.store(false);
    setState(JobState::Running);
}

void Job::cancel()
{
    {
        const QMutexLocker locker(&m_lock);
        if (m_state != JobState::Running)
            return;
    }
    m_cancel.store(true);
    setState(JobState::Stopping);
    Q_EMIT cancelRequested();
}

void Job::report(const JobProgress &progress)
{
    {
        const QMutexLocker locker(&m_lock);
        m_progress = progress;
    }
    Q_EMIT progressChanged(progress);
}

void Job::addProblem(const QString &problem)
{
    const QMutexLocker locker(&m_lock);
    m_problems.append(problem);
}

void Job::finish(JobEnd end)
{
    {
        const QMutexLocker locker(&m_lock);
        m_end = end;
    }
    setState(JobState::Finished);
    Q_EMIT finished(end);
}

} // namespace mbscope

#include "moc_job.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
