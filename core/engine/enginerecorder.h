#pragma once

#include "engineprogress.h"
#include "recordlistener.h"

#include "exchange/trafficentry.h"
#include "traffic/journalendpoints.h"
#include "exchange/transaction.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QTimer>

#include <atomic>

namespace mbscope {

class TrafficLog;

// Where the engine's records and frames go, in the engine's thread: the record listeners (the
// poller) at once by a direct call, recorded() for whoever waits on one transaction, the traffic
// log (journaled to disk within its batch time even on a quiet link) and, in batches of at most
// one every batchIntervalMs, the observers in other threads: transactionsFinished(), then
// framesLogged() (when frames are published), then progress().
class EngineRecorder : public QObject
{
    Q_OBJECT
public:
    // counters and progress: the engine's, published with each batch.
    EngineRecorder(const EngineCounters *counters, EngineProgress *progress, QObject *parent);

    void setBatchInterval(int ms) { m_batchIntervalMs = ms; }
    // The log frames go to (nullptr: none), and the link they are logged under (a shared log,
    // TrafficLog::setShared: a link id of this engine's own, TrafficLog::addConnection).
    void setTrafficLog(TrafficLog *log);
    void setLink(const QString &url);
    // The log's pending journal batch to the disk now.
    void flushLog();
    [[nodiscard]] const QString &link() const { return m_link; }

    // Whether every frame logged also goes to observers, in framesLogged() batches (off by
    // default: the copies cost a list entry per frame). Any thread.
    void setFramesPublished(bool published);

    // The link opened over a connection with these ends (client: mbscope's socket, server: the
    // target's): a note in the journal (journalendpoints.h). Empty ends: nothing.
    void noteEndpoints(const QString &local, const QString &peer);
    void logOutgoing(const QByteArray &bytes, qint64 ns, quint64 id);
    void logIncoming(const QByteArray &bytes, qint64 firstNs, TrafficVerdict verdict, quint64 id = 0);
    // A record made: to the listeners, recorded(), the log (when no answer frame was logged) and
    // the next batch.
    void record(Transaction transaction, quint64 tag);

    // Listeners get every record at once, by a direct call, before recorded() is emitted. A
    // listener removes itself before it goes (it may do so from inside onRecord()).
    void addRecordListener(RecordListener *listener);
    void removeRecordListener(RecordListener *listener);

    void scheduleBatch();
    // Emits what is waiting for observers now (end of a poll), then the progress.
    void flushBatch();

Q_SIGNALS:
    // In the engine thread, as soon as a record is made, after the record listeners (direct
    // connections only).
    void recorded(const mbscope::Transaction &transaction, quint64 tag);
    void transactionsFinished(const QList<mbscope::Transaction> &transactions);
    // When frames are published: every frame logged since the last batch, just after the
    // transactions, exactly as the traffic log holds them (requests when written, answers with
    // their verdicts, an empty frame in for a transaction that got no answer, unsolicited frames
    // and garbage); sequence counts the frames published; link: the target's URL.
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void progress(const mbscope::EngineProgress &progress);

protected:
    // recorded() is emitted only while something is connected to it (its emission with no
    // receiver was ~100 instructions per transaction).
    void connectNotify(const QMetaMethod &signal) override;
    void disconnectNotify(const QMetaMethod &signal) override;

private:
    void attachLog();
    void logFrame(qint64 tNs, TrafficDirection direction, TrafficVerdict verdict, quint64 id, const QByteArray &bytes);

    const EngineCounters *m_counters;
    EngineProgress *m_progress;
    TrafficLog *m_log = nullptr;
    QString m_link;
    quint16 m_logLink = 0;
    JournalEndpoints m_endpoints; // of the open link's connection, for a log attached later
    const TrafficLog *m_logAttached = nullptr; // the log and link m_logLink was given for
    QString m_linkAttached;
    QList<RecordListener *> m_listeners;
    std::atomic<int> m_recordedReceivers{0};
    QTimer m_batchTimer;
    QTimer m_journalTimer;
    int m_batchIntervalMs = 33;
    qint64 m_lastBatchNs = 0;
    QList<Transaction> m_batch;
    std::atomic<bool> m_framesPublished{false};
    quint64 m_framesLogged = 0;
    QList<TrafficFrame> m_frames; // logged since the last batch, when published
};

} // namespace mbscope
