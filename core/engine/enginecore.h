#pragma once

#include "chunkstamps.h"
#include "enginerecorder.h"
#include "engineoptions.h"
#include "engineprogress.h"
#include "inflightrequest.h"
#include "linkframing.h"
#include "responserouter.h"
#include "writescheduler.h"

#include "exchange/requestitem.h"
#include "exchange/responseverdict.h"
#include "exchange/transaction.h"

#include "transport/duetimer.h"
#include "transport/link.h"
#include "transport/linkreceiver.h"
#include "transport/linkurl.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QTimer>

#include <atomic>
#include <functional>
#include <memory>

namespace mbscope {

class StreamFramer;
class TrafficLog;

// The engine's work, in the engine's thread (TransactionEngine owns the thread and posts to it):
// it opens the link on demand, writes requests, frames what comes back and decides each
// transaction's status. Its parts: the WriteScheduler (queue, requests in flight, writes, when
// each is due), the ResponseRouter (which request a frame answers: in flight, late, duplicate or
// none) and the EngineRecorder (records and frames to the poller, the traffic log and, in
// batches of at most one every EngineOptions::batchIntervalMs, the observers). EngineCore drives
// the link and the timers and joins the three; nothing on the receive path goes through a signal.
//
// Timing truth: sentNs is the link's bytesWritten time of the last request byte; firstByteNs and
// doneNs are the link's read times of the first and the last byte of the matched frame.
class EngineCore : public QObject, private LinkReceiver
{
    Q_OBJECT
public:
    using LinkFactory = std::function<Link *(const LinkUrl &url, QObject *parent)>;

    explicit EngineCore(QObject *parent = nullptr);
    ~EngineCore() override;

    // Engine thread only, except reserveId().
    void setLinkFactory(LinkFactory factory) { m_factory = std::move(factory); }
    // Closes the current link; the next request opens one to the new target.
    void setTarget(const LinkUrl &url, const EngineOptions &options);
    void setTrafficLog(TrafficLog *log) { m_recorder->setTrafficLog(log); }
    [[nodiscard]] const LinkUrl &target() const { return m_url; }
    [[nodiscard]] const EngineOptions &options() const { return m_options; }

    // A fresh transaction id; thread-safe.
    [[nodiscard]] quint64 reserveId() { return m_nextId.fetch_add(1) + 1; }
    // Queues a request. tag groups requests of one poll run (0: single sends).
    void submit(const RequestItem &item, quint64 id, int itemIndex = -1, quint64 tag = 0);
    // Drops the queued requests of a tag and abandons those in flight (not recorded; their
    // answers, should they come, count as unsolicited).
    void cancel(quint64 tag);
    // Requests of a tag queued or in flight.
    [[nodiscard]] int outstanding(quint64 tag) const { return m_scheduler.outstanding(tag); }
    // Drops a tag's requests not yet written (a poll's cycle the device's pace still holds when
    // the poll's time is up), and whether a request is still waiting to be written.
    void dropQueued(quint64 tag) { m_scheduler.dropQueued(tag); }
    [[nodiscard]] bool isQueued(quint64 id) const { return m_scheduler.isQueued(id); }
    // How many requests may be in flight at once on this target.
    [[nodiscard]] int pipelineDepth() const;
    void closeLink();
    // Opens the link now (Connect), instead of with the first request; linkOpened() or
    // linkMessage() says how it went.
    void openLink();

    [[nodiscard]] EngineCounters &counters() { return m_counters; }
    [[nodiscard]] EngineProgress &progressState() { return m_progress; }
    // Records, frames and batches for observers (its signals are the engine's).
    [[nodiscard]] EngineRecorder *recorder() const { return m_recorder; }

Q_SIGNALS:
    void linkMessage(const QString &message);
    void linkOpened();

private:
    // enginelink.cpp: opening, errors and closing of the link
    void ensureLink();
    void onOpened();
    void onClosed(const QString &reason);
    void onLinkError(const LinkError &error);
    void failInFlight(const QString &problem);
    void failHead(const QString &problem);

    // enginecore.cpp: sending, timers, records
    void pump();
    void schedulePump();
    void stageNext();
    // Writes what stageNext() gathered in one write.
    void writeStaged();
    void armDeadline();
    // False (and the gap timer armed) while the next request must wait: on an RTU serial port
    // until the line has been silent t3.5 since its last frame (Serial Line V1.02, 2.5.1.1); on
    // any link for the device's pace (EngineOptions::requestGap, warmUp).
    [[nodiscard]] bool lineQuiet();
    void onBytesWritten(qint64 lastByteNs);
    void onDeadline();
    void resetFramer();
    // Removes in-flight entry index and records (or retries) it.
    void finish(qsizetype index, TransactionStatus status, const QString &problem,
                const QByteArray &response = {}, qint64 firstNs = 0, qint64 lastNs = 0, quint8 exceptionCode = 0);
    void record(Transaction transaction, quint64 tag);
    // EngineOptions::closeAfterAnswer: closes the link, from the event loop, once nothing is in flight.
    void hangUpWhenIdle();
    // The wait after a broadcast: the link's RS485 turnaround when its URL gives one, else the
    // engine's (Serial Line V1.02, 2.4.1). Worked out once per link, not per request.
    [[nodiscard]] qint64 broadcastWaitNs() const { return m_broadcastWaitNs; }
    void updateBroadcastWait();

    // LinkReceiver: the link calls these directly (links that emit signals reach the same slots).
    void linkBytesReceived(const QByteArray &bytes, qint64 firstNs, qint64 lastNs) override { onBytesReceived(bytes, firstNs, lastNs); }
    void linkBytesWritten(qint64 lastByteNs) override { onBytesWritten(lastByteNs); }

    // enginereceive.cpp: framing, and acting on what the router decides
    void onBytesReceived(const QByteArray &bytes, qint64 firstNs, qint64 lastNs);
    void processFramerOutput();
    void handleOutput(const QList<StreamFrame> &frames, const QList<SkippedBytes> &skipped);
    void handleFrame(const StreamFrame &frame, qint64 firstNs, qint64 lastNs);
    void handleSkipped(const SkippedBytes &run, qint64 firstNs, qint64 lastNs);
    void answer(qsizetype index, const StreamFrame &frame, qint64 firstNs, qint64 lastNs);
    void recordLate(InFlightRequest late, const StreamFrame &frame, qint64 firstNs, qint64 lastNs);
    void unsolicited(const QByteArray &bytes, qint64 firstNs);
    void onSilence();
    void armSilence();
    [[nodiscard]] qint64 flushPartial(); // flushes the framer; returns the bytes it held

    LinkUrl m_url;
    EngineOptions m_options;
    LinkFraming m_framing;
    LinkFactory m_factory;
    Link *m_link = nullptr;
    bool m_opening = false;
    qint64 m_broadcastWaitNs = 0;
    std::unique_ptr<StreamFramer> m_framer;
    std::unique_ptr<ResponseVerdict> m_verdict;
    ChunkStamps m_stamps;
    // The framer's output of one read, kept so that neither list is allocated per frame.
    QList<StreamFrame> m_frames;
    QList<SkippedBytes> m_skipped;

    WriteScheduler m_scheduler;
    ResponseRouter m_router;
    EngineCounters m_counters;
    EngineProgress m_progress;
    EngineRecorder *m_recorder; // a child: it moves to the engine's thread with the core
    std::atomic<quint64> m_nextId{0};

    QTimer m_deadlineTimer;
    qint64 m_deadlineArmedNs = 0; // the deadline m_deadlineTimer fires for, while it is active
    QTimer m_silenceTimer;
    QTimer m_openTimer;
    // RTU on a serial port: t3.5 of the line's baud rate (0: no gap kept, every other link), the
    // moment the line will have been silent that long (from the last byte read or sent), and the
    // timer (microseconds: t3.5 is 1.75 ms above 19200 baud) that sends the next request then.
    // The line stays quiet until m_lineQuietNs also for the device's pace (EngineOptions::requestGap
    // and warmUp), 0 until something sets it.
    qint64 m_frameGapNs = 0;
    qint64 m_requestGapNs = 0;
    qint64 m_lineQuietNs = 0;
    DueTimer m_gapTimer;
    bool m_pumpScheduled = false;
    bool m_pumping = false;
    bool m_deferPump = false;      // inside a link callback: pump from the event loop
    bool m_processing = false;     // handling the frames of one read
    bool m_pumpAfterProcessing = false;
    bool m_hangUpPending = false;  // closeAfterAnswer: the link closes before the next request
    bool m_closingQuietly = false; // closing on purpose: the closed() that follows says nothing new
    bool m_linkLost = false;       // flushing what a lost link left: a cut answer is a link error
};

} // namespace mbscope
