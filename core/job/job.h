#pragma once

#include "jobend.h"
#include "jobprogress.h"
#include "jobstate.h"

#include <QtCore/QMutex>
#include <QtCore/QObject>
#include <QtCore/QStringList>

#include <atomic>
#include <optional>

namespace mbscope {

// One run of long work (a scan, a sampling run) as whoever started it sees it: its state, its
// progress (0..1 with the time since it began and an estimate of the time left), how it ended and
// the problems it met. Every call is thread-safe: the job lives in the thread that shows it, its
// work reports from another (JobThread), and the signals reach receivers in the job's thread by
// queued connections. cancel() does not end the work by itself: the work connects its stop to
// cancelRequested() (queued into the work's thread), ends at its next step and keeps what it got.
class Job : public QObject
{
    Q_OBJECT
public:
    explicit Job(QObject *parent = nullptr);

    [[nodiscard]] JobState state() const;
    [[nodiscard]] bool isActive() const; // Running or Stopping
    [[nodiscard]] JobProgress progress() const;
    // How the last run ended: nullopt while one runs, and before the first.
    [[nodiscard]] std::optional<JobEnd> end() const;
    [[nodiscard]] QStringList problems() const;
    [[nodiscard]] bool isCancelRequested() const { return m_cancel.load(); }

    // A new run: Running, progress and problems cleared.
    void begin();
    // Asks the work to stop (Stopping, cancelRequested()); nothing when no run is active.
    void cancel();
    // From the work, any thread: where it stands, a problem met.
    void report(const mbscope::JobProgress &progress);
    void addProblem(const QString &problem);
    // The run is over: Finished, with why.
    void finish(mbscope::JobEnd end);

Q_SIGNALS:
    void stateChanged(mbscope::JobState state);
    void progressChanged(const mbscope::JobProgress &progress);
    void cancelRequested();
    void finished(mbscope::JobEnd end);

private:
    void setState(JobState state);

    mutable QMutex m_lock;
    JobState m_state = JobState::Idle;
    JobProgress m_progress;
    std::optional<JobEnd> m_end;
    QStringList m_problems;
    std::atomic<bool> m_cancel{false};
};

} // namespace mbscope
