#pragma once

#include "chunkstamps.h"
#include "engineoptions.h"
#include "engineprogress.h"
#include "linkframing.h"
#include "recordlistener.h"
#include "exchange/requestitem.h"
#include "exchange/responsematcher.h"
#include "exchange/responseverdict.h"
#include "exchange/trafficentry.h"
#include "exchange/transaction.h"

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
// it opens the link on demand, writes requests, frames what comes back, matches answers to
// requests, decides each transaction's status and hands the records on: at once (recorded(), for
// the poller in the same thread) and in batches for observers (transactionsFinished(), at most
// every EngineOptions::batchIntervalMs, never from the receive path).
//
// Timing truth: sentNs is the link's bytesWritten time of the last request byte; firstByteNs and
// doneNs are the link's read times of the first and the last byte of the matched frame. An answer
// cannot begin before its request was written, so a frame whose first byte came earlier belongs to
// an earlier request (late) or to none (unsolicited), whatever its keys say.
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
    void setTrafficLog(TrafficLog *log);
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
    [[nodiscard]] int outstanding(quint64 tag) const;
    // How many requests may be in flight at once on this target.
    [[nodiscard]] int pipelineDepth() const;
    void closeLink();

    [[nodiscard]] EngineCounters &counters() { return m_counters; }
    [[nodiscard]] EngineProgress &progressState() { return m_progress; }
    // Listeners get every record at once, by a direct call, before recorded() is emitted. A
    // listener removes itself before it goes (it may do so from inside onRecord()).
    void addRecordListener(RecordListener *listener);
    void removeRecordListener(RecordListener *listener);
    // Emits what is waiting for observers now (end of a poll), then the progress.
    void flushBatch();
    void scheduleBatch();

Q_SIGNALS:
    // In the engine thread, as soon as a record is made, after the record listeners (direct
    // connections only).
    void recorded(const mbscope::Transaction &transaction, quint64 tag);
    // For observers in other threads: batches of records and the progress.
    void transactionsFinished(const QList<mbscope::Transaction> &transactions);
    // Frames read that belong to no transaction (unsolicited, duplicates, garbage), in the same
    // batches, just after them; link: the target's URL (enginelog.cpp).
    void unmatchedFrames(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void progress(const mbscope::EngineProgress &progress);
    void linkMessage(const QString &message);

protected:
    // recorded() is emitted only while something is connected to it (its emission with no
    // receiver was ~100 instructions per transaction).
    void connectNotify(const QMetaMethod &signal) override;
    void disconnectNotify(const QMetaMethod &signal) override;

private:
    struct Outgoing {
        RequestItem item;
        quint64 id = 0;
        int itemIndex = -1;
        int attempt = 0;
        quint64 tag = 0;
        QString history; // what went wrong with earlier attempts
    };
    struct Pending {
        Outgoing out;
        QByteArray sent;        // the bytes written
        bool rewritten = false; // transaction id given by the engine (pipelining)
        qint64 writeStartNs = 0;
        qint64 sentNs = 0;      // 0 until the link reports the write
        qint64 predictedSentNs = 0; // serial: when the link computes the last byte will have left
        qint64 deadlineNs = 0;
        qint64 timedOutNs = 0;  // for late answers
        bool answeredBroadcast = false;
    };

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
    // Takes the head of the queue in flight, logs it and adds its bytes to the next write.
    void stageNext();
    // Writes what stageNext() gathered in one write.
    void writeStaged();
    void armDeadline();
    void onBytesWritten(qint64 lastByteNs);
    void onDeadline();
    void resetFramer();
    // Removes in-flight entry index and records (or retries) it.
    void finish(qsizetype index, TransactionStatus status, const QString &problem,
                const QByteArray &response = {}, qint64 firstNs = 0, qint64 lastNs = 0, quint8 exceptionCode = 0);
    void record(Transaction transaction, quint64 tag);
    [[nodiscard]] qsizetype indexOfId(quint64 id) const;
    [[nodiscard]] qint64 waitNs(const RequestItem &item) const;
    [[nodiscard]] static qint64 sentTime(const Pending &p, qint64 firstNs);

    // LinkReceiver: the link calls these directly (links that emit signals reach the same slots).
    void linkBytesReceived(const QByteArray &bytes, qint64 firstNs, qint64 lastNs) override { onBytesReceived(bytes, firstNs, lastNs); }
    void linkBytesWritten(qint64 lastByteNs) override { onBytesWritten(lastByteNs); }

    // enginereceive.cpp: framing, matching, late and unsolicited answers
    void onBytesReceived(const QByteArray &bytes, qint64 firstNs, qint64 lastNs);
    void processFramerOutput();
    void handleOutput(const QList<StreamFrame> &frames, const QList<SkippedBytes> &skipped);
    void handleFrame(const StreamFrame &frame, qint64 firstNs, qint64 lastNs);
    void handleSkipped(const SkippedBytes &run, qint64 firstNs, qint64 lastNs);
    void answer(qsizetype index, const StreamFrame &frame, qint64 firstNs, qint64 lastNs);
    [[nodiscard]] bool tryLate(const StreamFrame &frame, const FrameKeys &keys, qint64 firstNs, qint64 lastNs);
    [[nodiscard]] bool isDuplicate(const FrameKeys &keys) const;
    bool duplicateFirst(const FrameKeys &keys);
    void unsolicited(const QByteArray &bytes, qint64 firstNs);
    void onSilence();
    void armSilence();
    [[nodiscard]] qint64 flushPartial(); // flushes the framer; returns the bytes it held

    // enginelog.cpp: the traffic log, when one is attached
    void attachLog();
    void logOutgoing(const QByteArray &bytes, qint64 ns, quint64 id);
    void logIncoming(const QByteArray &bytes, qint64 firstNs, TrafficVerdict verdict, quint64 id = 0);
    void logTransaction(const Transaction &transaction);

    LinkUrl m_url;
    EngineOptions m_options;
    LinkFraming m_framing;
    LinkFactory m_factory;
    TrafficLog *m_log = nullptr;
    quint16 m_logLink = 0;
    Link *m_link = nullptr;
    bool m_opening = false;
    std::unique_ptr<StreamFramer> m_framer;
    std::unique_ptr<ResponseVerdict> m_verdict;
    ChunkStamps m_stamps;
    // The framer's output of one read, kept so that neither list is allocated per frame.
    QList<StreamFrame> m_frames;
    QList<SkippedBytes> m_skipped;
    QList<RecordListener *> m_recordListeners;

    QList<Outgoing> m_queue;
    QList<Pending> m_inFlight;
    struct WriteMark {
        quint64 id = 0;
        int attempt = 0;
        bool endsWrite = true; // the last request of its write (a pipelined write carries several)
    };
    QList<WriteMark> m_writeOrder; // requests whose write's bytesWritten() has not come yet, in order
    QByteArray m_staged;           // requests staged for the next write
    qsizetype m_stagedCount = 0;
    QList<Pending> m_timedOut;   // newest last, at most lateWindow
    QList<RequestItem> m_answered; // recently answered requests, for second answers
    quint16 m_nextTransactionId = 1;
    std::atomic<quint64> m_nextId{0};
    std::atomic<int> m_recordedReceivers{0};

    QTimer m_deadlineTimer;
    qint64 m_deadlineArmedNs = 0; // the deadline m_deadlineTimer fires for, while it is active
    QTimer m_silenceTimer;
    QTimer m_openTimer;
    QTimer m_batchTimer;
    QTimer m_journalTimer; // journal batches reach the disk within their batch time on a quiet link
    bool m_pumpScheduled = false;
    bool m_pumping = false;
    bool m_deferPump = false;      // inside a link callback: pump from the event loop
    bool m_processing = false;     // handling the frames of one read
    bool m_pumpAfterProcessing = false;
    bool m_closingQuietly = false; // closing on purpose: the closed() that follows says nothing new
    bool m_linkLost = false;
    bool m_duplicateSeen = false;
    bool m_lastEndAnswered = false; // the latest request to end was answered (not timed out)  // set by duplicateFirst() for the frame being handled       // flushing what a lost link left: a cut answer is a link error
    qint64 m_lastBatchNs = 0;
    QList<Transaction> m_batch;
    QList<TrafficFrame> m_unmatched; // frames of no transaction, for the next batch
    EngineCounters m_counters;
    EngineProgress m_progress;
};

} // namespace mbscope
