#include "enginerecorder.h"

#include "traffic/trafficlog.h"
#include "transport/monotonicclock.h"

#include <QtCore/QMetaMethod>

#include <utility>

namespace mbscope {

EngineRecorder::EngineRecorder(const EngineCounters *counters, EngineProgress *progress, QObject *parent)
    : QObject(parent)
    , m_counters(counters)
    , m_progress(progress)
    , m_batchTimer(this)
    , m_journalTimer(this)
{
    m_batchTimer.setSingleShot(true);
    m_batchTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_batchTimer, &QTimer::timeout, this, &EngineRecorder::flushBatch);
    m_journalTimer.setInterval(50);
    connect(&m_journalTimer, &QTimer::timeout, this, [this] {
        if (m_log)
            m_log->flushIfDue(monotonicNowNs());
    });
}

void EngineRecorder::setTrafficLog(TrafficLog *log)
{
    if (m_log && m_log != log)
        m_log->flush();
    m_log = log;
    attachLog();
}

void EngineRecorder::setLink(const QString &url)
{
    m_link = url;
    attachLog();
}

void EngineRecorder::flushLog()
{
    if (m_log)
        m_log->flush();
}

void EngineRecorder::attachLog()
{
    if (!m_log) {
        m_logAttached = nullptr; // a log given again, or another at its address, is named anew
        m_journalTimer.stop();
        return;
    }
    // A shared log (the links of a watch run or a scan, each on its engine) gives every engine a
    // link id of its own, since each numbers its transactions from 1; asked once per log and
    // link, so that an engine's frames stay on one id; not before the engine has its target
    // (nothing crosses a link before), so that no nameless link is left in the journal.
    if (m_link.isEmpty()) {
        m_logAttached = nullptr;
        m_journalTimer.start();
        return;
    }
    if (m_log != m_logAttached || m_link != m_linkAttached)
        m_logLink = m_log->isShared() ? m_log->addConnection(m_link) : m_log->addLink(m_link);
    m_logAttached = m_log;
    m_linkAttached = m_link;
    // A log attached once the link is open (poll --record) still learns the connection's ends.
    if (!m_endpoints.client.isEmpty())
        m_log->setEndpoints(m_logLink, monotonicNowNs(), 0, m_endpoints);
    m_journalTimer.start();
}

void EngineRecorder::setFramesPublished(bool published)
{
    m_framesPublished.store(published, std::memory_order_relaxed);
}

void EngineRecorder::logFrame(qint64 tNs, TrafficDirection direction, TrafficVerdict verdict, quint64 id,
                              const QByteArray &bytes)
{
    if (m_log)
        m_log->append(tNs, direction, m_logLink, verdict, id, bytes);
    if (!m_framesPublished.load(std::memory_order_relaxed))
        return;
    TrafficFrame frame;
    frame.sequence = m_framesLogged++;
    frame.tNs = tNs;
    frame.transactionId = id;
    frame.direction = direction;
    frame.verdict = verdict;
    frame.bytes = bytes; // shared, not copied
    m_frames.append(std::move(frame));
    scheduleBatch();
}

void EngineRecorder::noteEndpoints(const QString &local, const QString &peer)
{
    if (local.isEmpty() || peer.isEmpty())
        return;
    m_endpoints = JournalEndpoints{local, peer};
    if (m_log)
        m_log->setEndpoints(m_logLink, monotonicNowNs(), 0, m_endpoints);
}

void EngineRecorder::logOutgoing(const QByteArray &bytes, qint64 ns, quint64 id)
{
    logFrame(ns, TrafficDirection::Out, TrafficVerdict::Sent, id, bytes);
}

void EngineRecorder::logIncoming(const QByteArray &bytes, qint64 firstNs, TrafficVerdict verdict, quint64 id)
{
    logFrame(firstNs, TrafficDirection::In, verdict, id, bytes);
}

void EngineRecorder::record(Transaction transaction, quint64 tag)
{
    // A transaction whose answer was logged carries its verdict on that frame. One without an
    // answer (timeout, link error, broadcast) is logged as an empty frame in with its verdict,
    // so that the log holds every transaction's outcome. A first attempt never written (the link
    // never came up) put nothing on the line: a frame in for it would be an answer to a request
    // the log does not hold (analyze counted it as an answer matching no request).
    const bool neverOnTheLine = transaction.writeNs == 0 && transaction.attempt == 0;
    if (transaction.response.isEmpty() && !neverOnTheLine && (m_log || m_framesPublished.load(std::memory_order_relaxed)))
        logFrame(monotonicNowNs(), TrafficDirection::In, trafficVerdict(transaction.status), transaction.id, {});
    if (m_listeners.size() == 1) {
        m_listeners.constFirst()->onRecord(transaction, tag);
    } else if (!m_listeners.isEmpty()) {
        // A listener may go (or add another) while records are handed out: each one still
        // listening gets this record once.
        const QList<RecordListener *> listeners = m_listeners;
        for (RecordListener *listener : listeners) {
            if (m_listeners.contains(listener))
                listener->onRecord(transaction, tag);
        }
    }
    if (m_recordedReceivers.load(std::memory_order_relaxed) > 0)
        Q_EMIT recorded(transaction, tag);
    m_batch.append(std::move(transaction));
    scheduleBatch();
}

void EngineRecorder::connectNotify(const QMetaMethod &signal)
{
    if (signal == QMetaMethod::fromSignal(&EngineRecorder::recorded))
        m_recordedReceivers.fetch_add(1, std::memory_order_relaxed);
}

void EngineRecorder::disconnectNotify(const QMetaMethod &signal)
{
    // An invalid method (everything disconnected at once) does not say which: the count stays,
    // and recorded() goes on being emitted, which is only slower.
    if (signal == QMetaMethod::fromSignal(&EngineRecorder::recorded))
        m_recordedReceivers.fetch_sub(1, std::memory_order_relaxed);
}

void EngineRecorder::addRecordListener(RecordListener *listener)
{
    if (!m_listeners.contains(listener))
        m_listeners.append(listener);
}

void EngineRecorder::removeRecordListener(RecordListener *listener)
{
    m_listeners.removeAll(listener);
}

void EngineRecorder::scheduleBatch()
{
    if (m_batchTimer.isActive())
        return;
    // Round up: a timer that fires early would only be armed again.
    const qint64 due = m_lastBatchNs + qint64(m_batchIntervalMs) * 1000000 - monotonicNowNs();
    m_batchTimer.start(due <= 0 ? 0 : int(qMin<qint64>((due + 999999) / 1000000, 24LL * 3600 * 1000)));
}

void EngineRecorder::flushBatch()
{
    m_batchTimer.stop();
    m_lastBatchNs = monotonicNowNs();
    if (!m_batch.isEmpty()) {
        const qsizetype size = m_batch.size();
        Q_EMIT transactionsFinished(std::exchange(m_batch, {}));
        // The observers keep the list that was sent; the next one is likely as long, and growing
        // a list of records copies them at every step.
        m_batch.reserve(size);
    }
    if (!m_frames.isEmpty())
        Q_EMIT framesLogged(std::exchange(m_frames, {}), m_link);
    m_progress->counters = *m_counters;
    Q_EMIT progress(*m_progress);
}

} // namespace mbscope

#include "moc_enginerecorder.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
