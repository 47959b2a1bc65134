#pragma once

#include "jobend.h"

#include <QtCore/QObject>
#include <QtCore/QPointer>

#include <functional>

class QThread;

namespace mbscope {

class Job;

// A worker thread for long synchronous work (the scanners, which wait for each answer in a local
// event loop of their own): the worker objects are moved into the thread once (adopt) and live
// there with everything they own (probe channel, engine, link), so the thread that started a job
// never nests an event loop while it runs. run() hands the work to the thread; the work returns
// how it ended and what to deliver (its results, by value), and both come back to the job's
// thread in one queued call: deliver() first, then Job::finish(). Destroying the JobThread
// cancels the job, ends the thread (every local loop in it returns) and deletes the adopted
// objects there.
class JobThread : public QObject
{
    Q_OBJECT
public:
    struct Outcome {
        JobEnd end = JobEnd::Completed;
        std::function<void()> deliver; // runs in the job's thread, before Job::finish
    };

    explicit JobThread(QObject *parent = nullptr);
    ~JobThread() override;

    // Moves worker (an object without a parent, in the caller's thread) into the thread.
    void adopt(QObject *worker);
    // Begins job and runs work in the thread; false (nothing run) while a job of this thread is
    // active.
    bool run(Job *job, std::function<Outcome()> work);
    [[nodiscard]] bool isBusy() const;
    [[nodiscard]] QThread *thread() const { return m_thread; }

private:
    QThread *m_thread;
    QObject *m_anchor; // lives in m_thread: what run() posts to
    QPointer<Job> m_job;
};

} // namespace mbscope
