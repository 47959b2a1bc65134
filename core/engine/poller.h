#pragma once

#include "pollreport.h"
#include "pollsettings.h"
#include "recordlistener.h"

#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QTimer>

namespace mbscope {

class EngineCore;
class EngineRecorder;
struct Transaction;

// One poll run in the engine's thread: the items submitted in cycles (PollSettings says how),
// each record added to the run's statistics as it is made. A cycle that could not start when it
// was due, because the one before was still running, starts as soon as that one ends and counts
// as an overrun: the interval runs from one cycle's actual start to the next, the moment its first
// request was handed to the link (which may be later than the cycle was begun: the link may still
// be opening, or the engine busy with an answer). A cycle whose first request the device's pace
// held (EngineOptions::requestGap, warmUp) past its due time is an overrun too.
class Poller : public QObject, private RecordListener
{
    Q_OBJECT
public:
    Poller(EngineCore *core, const PollSettings &settings, quint64 tag, QObject *parent = nullptr);
    ~Poller() override;

    void start();
    // Starts no more cycles and abandons the requests still queued or in flight; finished() follows
    // at once with the run so far.
    void stop();

    [[nodiscard]] const PollRun &run() const { return m_run; }
    [[nodiscard]] bool isFinished() const { return m_finished; }

Q_SIGNALS:
    void finished();

private:
    void onRecord(const Transaction &transaction, quint64 tag) override;
    void advance(bool fromRecord);
    void startCycle(qint64 nowNs);
    [[nodiscard]] bool moreCycles(qint64 nowNs) const;
    [[nodiscard]] bool hasRoom() const;
    void finish();
    void updateProgress(qint64 nowNs);
    void countOverrun();

    EngineCore *m_core;
    // The engine may go first (a sweep, and its poller, are the engine's children): only a
    // living engine is told that this listener leaves.
    QPointer<EngineRecorder> m_listenedTo;
    PollSettings m_settings;
    quint64 m_tag;
    PollRun m_run;
    EngineCounters m_countersAtStart;
    QTimer m_timer;
    qint64 m_startNs = 0;
    qint64 m_nextDueNs = 0;
    quint64 m_cycleFirstId = 0; // the request that begins the latest cycle
    qint64 m_cycleDueNs = 0;    // when the latest cycle was due
    bool m_cycleOverrun = false; // the latest cycle is counted as an overrun already
    bool m_started = false;
    bool m_finished = false;
};

} // namespace mbscope
