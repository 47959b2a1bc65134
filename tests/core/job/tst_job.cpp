// The job model (core/job): a Job's life (Idle, Running, Stopping, Finished) with its progress and
// end, and JobThread running work on a thread of its own: the work runs there (its objects too),
// its results and end come back to the job's thread, cancel() from the job's thread reaches the
// work, and a JobThread destroyed mid-work ends it.

#include "job/job.h"
#include "job/jobthread.h"

#include <QtCore/QEventLoop>
#include <QtCore/QThread>
#include <QtCore/QTimer>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <atomic>

using namespace mbscope;

namespace {

// Work as the scanners do it: steps, each waiting in a local event loop, until stop().
class Stepper : public QObject
{
    Q_OBJECT
public:
    int run(int steps)
    {
        int done = 0;
        for (; done < steps && !m_stop; ++done) {
            QEventLoop loop;
            connect(this, &Stepper::stopping, &loop, &QEventLoop::quit);
            QTimer::singleShot(5, &loop, &QEventLoop::quit);
            loop.exec();
            Q_EMIT stepped(JobProgress{done + 1, steps, 0, 0, 0});
        }
        return done;
    }
    void stop()
    {
        m_stop = true;
        Q_EMIT stopping();
    }
    bool m_stop = false;
Q_SIGNALS:
    void stepped(const mbscope::JobProgress &progress);
    void stopping();
};

} // namespace

class TestJob : public QObject
{
    Q_OBJECT

private slots:
    void lifeOfAJob();
    void workRunsOnItsThread();
    void cancelKeepsWhatWasDone();
    void destroyedMidWorkEnds();
};

void TestJob::lifeOfAJob()
{
    Job job;
    QCOMPARE(job.state(), JobState::Idle);
    QVERIFY(!job.end());
    job.cancel(); // nothing runs: nothing to cancel
    QCOMPARE(job.state(), JobState::Idle);
    job.begin();
    QCOMPARE(job.state(), JobState::Running);
    job.report(JobProgress{1, 4, 0, 100, 300});
    QCOMPARE(job.progress().fraction(), 0.25);
    QSignalSpy cancelled(&job, &Job::cancelRequested);
    job.cancel();
    QCOMPARE(cancelled.size(), 1);
    QCOMPARE(job.state(), JobState::Stopping);
    QVERIFY(job.isCancelRequested());
    job.addProblem(QStringLiteral("unit 3 did not answer"));
    job.finish(JobEnd::Stopped);
    QCOMPARE(job.state(), JobState::Finished);
    QCOMPARE(*job.end(), JobEnd::Stopped);
    QCOMPARE(job.problems(), QStringList{QStringLiteral("unit 3 did not answer")});
    job.begin();
    QVERIFY(!job.end());
    QVERIFY(job.problems().isEmpty());
    QVERIFY(!job.isCancelRequested());
    QCOMPARE(JobProgress{}.fraction(), 0.0);
}

void TestJob::workRunsOnItsThread()
{
    JobThread thread;
    auto *stepper = new Stepper;
    thread.adopt(stepper);
    Job job;
    connect(stepper, &Stepper::stepped, &job, &Job::report);
    QSignalSpy progress(&job, &Job::progressChanged);
    QSignalSpy finished(&job, &Job::finished);
    std::atomic<QThread *> workThread{nullptr};
    QThread *deliverThread = nullptr;
    int delivered = -1;
    int loopLevelSeen = 0;
    QTimer probe;
    connect(&probe, &QTimer::timeout, this, [&] { loopLevelSeen = qMax(loopLevelSeen, QThread::currentThread()->loopLevel()); });
    probe.start(1);
    QVERIFY(thread.run(&job, [&, stepper]() -> JobThread::Outcome {
        workThread = QThread::currentThread();
        const int done = stepper->run(5);
        return {JobEnd::Completed, [&, done] {
                    deliverThread = QThread::currentThread();
                    delivered = done;
                }};
    }));
    QVERIFY(thread.isBusy());
    QVERIFY(!thread.run(&job, [] { return JobThread::Outcome{}; })); // one at a time
    QVERIFY(finished.wait(10000));
    QCOMPARE(workThread.load(), thread.thread());
    QCOMPARE(stepper->thread(), thread.thread());
    QCOMPARE(deliverThread, QThread::currentThread());
    QCOMPARE(delivered, 5);
    QCOMPARE(finished.first().first().value<JobEnd>(), JobEnd::Completed);
    QCOMPARE(progress.size(), 5);
    QCOMPARE(job.progress().done, 5);
    QCOMPARE(job.state(), JobState::Finished);
    QVERIFY(!thread.isBusy());
    QCOMPARE(loopLevelSeen, 1); // the wait's loop only: the work's loops were in its thread
}

void TestJob::cancelKeepsWhatWasDone()
{
    JobThread thread;
    auto *stepper = new Stepper;
    thread.adopt(stepper);
    Job job;
    connect(&job, &Job::cancelRequested, stepper, &Stepper::stop);
    connect(stepper, &Stepper::stepped, &job, &Job::report);
    connect(&job, &Job::progressChanged, &job, [&job](const JobProgress &p) {
        if (p.done == 3)
            job.cancel();
    });
    int delivered = -1;
    QSignalSpy finished(&job, &Job::finished);
    thread.run(&job, [&, stepper]() -> JobThread::Outcome {
        const int done = stepper->run(100000);
        return {done < 100000 ? JobEnd::Stopped : JobEnd::Completed, [&, done] { delivered = done; }};
    });
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.first().first().value<JobEnd>(), JobEnd::Stopped);
    QVERIFY2(delivered >= 3 && delivered < 100, qPrintable(QString::number(delivered)));
}

void TestJob::destroyedMidWorkEnds()
{
    Job job;
    std::atomic<int> done{-1};
    {
        JobThread thread;
        auto *stepper = new Stepper;
        thread.adopt(stepper);
        connect(&job, &Job::cancelRequested, stepper, &Stepper::stop);
        thread.run(&job, [&, stepper]() -> JobThread::Outcome {
            done = stepper->run(100000);
            return {};
        });
        QTRY_VERIFY(done.load() == -1 && job.isActive());
        QTest::qWait(20);
    }
    QVERIFY(done.load() >= 0 && done.load() < 100000);
}

QTEST_GUILESS_MAIN(TestJob)
#include "tst_job.moc"
