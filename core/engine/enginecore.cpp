#include "enginecore.h"

#include "traffic/trafficlog.h"

#include "protocol/streamframer.h"
#include "transport/monotonicclock.h"
#include "transport/seriallink.h"

#include <QtCore/QMetaMethod>
#include <QtCore/QVarLengthArray>

#include <algorithm>
#include <utility>

namespace mbscope {

namespace {

int msUntil(qint64 deadlineNs, qint64 nowNs)
{
    // Round up: a timer that fires early would only be armed again.
    const qint64 ns = deadlineNs - nowNs;
    return ns <= 0 ? 0 : int(qMin<qint64>((ns + 999999) / 1000000, 24LL * 3600 * 1000));
}

// Another attempt makes sense when the device's answer was missing or unusable; an exception is
// a clear answer and a link error ends the request (the next request reconnects).
bool retryable(TransactionStatus status)
{
    return status == TransactionStatus::Timeout || status == TransactionStatus::CrcError
        || status == TransactionStatus::Malformed || status == TransactionStatus::Unexpected;
}

void setUpTimer(QTimer &timer)
{
    timer.setSingleShot(true);
    timer.setTimerType(Qt::PreciseTimer);
}

} // namespace

EngineCore::EngineCore(QObject *parent)
    : QObject(parent)
    , m_deadlineTimer(this)
    , m_silenceTimer(this)
    , m_openTimer(this)
    , m_batchTimer(this)
    , m_journalTimer(this)
{
    setUpTimer(m_deadlineTimer);
    setUpTimer(m_silenceTimer);
    setUpTimer(m_openTimer);
    setUpTimer(m_batchTimer);
    m_journalTimer.setInterval(50);
    connect(&m_journalTimer, &QTimer::timeout, this, [this] {
        if (m_log)
            m_log->flushIfDue(monotonicNowNs());
    });
    connect(&m_deadlineTimer, &QTimer::timeout, this, &EngineCore::onDeadline);
    connect(&m_silenceTimer, &QTimer::timeout, this, &EngineCore::onSilence);
    connect(&m_batchTimer, &QTimer::timeout, this, &EngineCore::flushBatch);
    connect(&m_openTimer, &QTimer::timeout, this, [this] {
        if (m_opening)
            onLinkError(LinkError{LinkError::Kind::Timeout,
                                  QStringLiteral("%1: the link did not open within %2 ms")
                                      .arg(m_url.toString()).arg(m_url.connectTimeoutMs)});
    });
    setTarget(LinkUrl{}, EngineOptions{});
}

EngineCore::~EngineCore()
{
    // The link goes first, while everything it could reach is still whole.
    if (m_link) {
        disconnect(m_link, nullptr, this, nullptr);
        m_link->setReceiver(nullptr);
        delete m_link;
    }
}

void EngineCore::setTarget(const LinkUrl &url, const EngineOptions &options)
{
    m_deferPump = true;
    failInFlight(QStringLiteral("%1: the target changed to %2").arg(m_url.toString(), url.toString()));
    m_deferPump = false;
    m_writeOrder.clear();
    if (m_link) {
        m_closingQuietly = true;
        m_link->close();
        m_link->setReceiver(nullptr);
        delete m_link;
        m_link = nullptr;
        m_closingQuietly = false;
    }
    m_opening = false;
    m_url = url;
    m_options = options;
    m_framing = LinkFraming::of(url, options);
    m_framer = m_framing.createFramer(url);
    m_verdict = std::make_unique<ResponseVerdict>(m_framing.framing, m_framing.delimited);
    m_stamps.clear();
    m_timedOut.clear();
    m_answered.clear();
    attachLog();
}

int EngineCore::pipelineDepth() const
{
    const bool mbap = !m_framing.delimited && (m_framing.framing == Framing::Tcp || m_framing.framing == Framing::Udp);
    return mbap ? qMax(1, m_options.pipelineDepth) : 1;
}

void EngineCore::submit(const RequestItem &item, quint64 id, int itemIndex, quint64 tag)
{
    m_queue.append(Outgoing{item, id, itemIndex, 0, tag, {}});
    pump();
}

void EngineCore::cancel(quint64 tag)
{
    m_queue.removeIf([tag](const Outgoing &o) { return o.tag == tag; });
    const qsizetype before = m_inFlight.size();
    m_inFlight.removeIf([tag](const Pending &p) { return p.out.tag == tag; });
    m_counters.abandoned += quint64(before - m_inFlight.size());
    armDeadline();
    scheduleBatch();
}

int EngineCore::outstanding(quint64 tag) const
{
    int n = 0;
    for (const Outgoing &o : m_queue)
        n += o.tag == tag ? 1 : 0;
    for (const Pending &p : m_inFlight)
        n += p.out.tag == tag ? 1 : 0;
    return n;
}

void EngineCore::schedulePump()
{
    if (m_pumpScheduled)
        return;
    m_pumpScheduled = true;
    QMetaObject::invokeMethod(this, [this] {
        m_pumpScheduled = false;
        pump();
    }, Qt::QueuedConnection);
}

void EngineCore::pump()
{
    if (m_processing) {
        m_pumpAfterProcessing = true; // sent as soon as the frames of this read are handled
        return;
    }
    if (m_pumping || m_deferPump) {
        schedulePump();
        return;
    }
    m_pumping = true;
    // A pipelined stream link gets the requests of one turn in one write: one system call and one
    // segment for all of them, and a server that reads what has come answers them together.
    // Datagram links carry one request per datagram.
    const int depth = pipelineDepth();
    const bool together = depth > 1 && !m_framing.datagram;
    while (!m_queue.isEmpty()) {
        if (!m_link || m_link->state() != Link::State::Open) {
            ensureLink();
            break;
        }
        if (!m_inFlight.isEmpty()) {
            // A broadcast occupies the line alone until its turnaround has passed.
            if (m_inFlight.size() >= depth || m_inFlight.constFirst().out.item.broadcast
                || m_queue.constFirst().item.broadcast)
                break;
        }
        stageNext();
        if (!together)
            writeStaged();
    }
    writeStaged();
    m_pumping = false;
}

void EngineCore::resetFramer()
{
    m_writeOrder.clear();
    m_silenceTimer.stop();
    m_framer->reset();
    m_stamps.clear();
}

void EngineCore::stageNext()
{
    Pending p;
    p.out = m_queue.takeFirst();
    p.sent = p.out.item.bytes;
    if (pipelineDepth() > 1 && p.out.item.rule == MatchRule::Mbap && p.sent.size() >= 2) {
        // Pipelining needs a distinct transaction id per request in flight (Messaging on TCP/IP
        // V1.0b, 3.1.3: the id pairs a response with its request).
        quint16 tid = m_nextTransactionId++;
        for (int guard = 0; guard < 65536; ++guard) {
            bool used = false;
            for (const Pending &q : m_inFlight)
                used = used || q.out.item.transactionId == tid;
            if (!used)
                break;
            tid = m_nextTransactionId++;
        }
        p.sent[0] = char(tid >> 8);
        p.sent[1] = char(tid & 0xFF);
        p.rewritten = tid != p.out.item.transactionId;
        p.out.item.transactionId = tid;
    }
    p.writeStartNs = monotonicNowNs();
    p.deadlineNs = p.writeStartNs + waitNs(p.out.item);
    ++m_counters.requestsSent;
    m_counters.bytesOut += quint64(p.sent.size());
    logOutgoing(p.sent, p.writeStartNs, p.out.id);
    // bytesWritten() comes once per write, in order, possibly before write() returns; it times
    // every request of that write.
    m_writeOrder.append(WriteMark{p.out.id, p.out.attempt, false});
    if (m_stagedCount++ == 0)
        m_staged = p.sent; // shared, not copied: a single request is written as it is
    else
        m_staged.append(p.sent);
    m_inFlight.append(std::move(p));
}

void EngineCore::writeStaged()
{
    if (m_stagedCount == 0)
        return;
    // The staged requests are the last entries of the write order (nothing ran since staging).
    QVarLengthArray<WriteMark, 16> staged;
    for (qsizetype i = m_writeOrder.size() - m_stagedCount; i < m_writeOrder.size(); ++i)
        staged.append(m_writeOrder.at(i));
    m_writeOrder.last().endsWrite = true;
    m_stagedCount = 0;
    const QByteArray bytes = std::exchange(m_staged, {});
    if (!m_link->write(bytes)) {
        m_writeOrder.removeIf([&staged](const WriteMark &m) {
            return std::any_of(staged.cbegin(), staged.cend(),
                               [&m](const WriteMark &s) { return s.id == m.id && s.attempt == m.attempt; });
        });
        for (const WriteMark &mark : staged) {
            const qsizetype i = indexOfId(mark.id);
            if (i >= 0 && m_inFlight.at(i).out.attempt == mark.attempt)
                finish(i, TransactionStatus::LinkError, QStringLiteral("%1: the link did not take the request").arg(m_url.toString()));
        }
    } else if (const auto *serial = qobject_cast<const SerialLink *>(m_link)) {
        // A serial link knows when the last byte will have left the line before it says so
        // (it signals once that time has come), and a fast answer may come first. (Serial links
        // carry one request per write.)
        const qsizetype i = indexOfId(staged.last().id);
        if (i >= 0 && m_inFlight.at(i).sentNs == 0 && serial->lineFreeNs() >= m_inFlight.at(i).writeStartNs) {
            m_inFlight[i].predictedSentNs = serial->lineFreeNs();
            m_inFlight[i].deadlineNs = serial->lineFreeNs() + waitNs(m_inFlight.at(i).out.item);
        }
    }
    armDeadline();
    scheduleBatch();
}

qint64 EngineCore::waitNs(const RequestItem &item) const
{
    if (!item.broadcast)
        return qint64(item.timeoutMs) * 1000000;
    // After a broadcast: the link's RS485 turnaround delay when the URL gives one, else the
    // engine's (Serial Line V1.02, 2.4.1).
    const qint64 linkTurnaround = m_link ? m_link->turnaroundNs() : 0;
    return linkTurnaround > 0 ? linkTurnaround : qint64(m_options.broadcastTurnaroundMs) * 1000000;
}

void EngineCore::onBytesWritten(qint64 lastByteNs)
{
    while (!m_writeOrder.isEmpty()) {
        const WriteMark mark = m_writeOrder.takeFirst();
        const qsizetype i = indexOfId(mark.id);
        // The request may have ended already (an answer that came before the link said the bytes
        // had left: the answer's time then bounds the send time, see finish()).
        if (i >= 0 && m_inFlight.at(i).out.attempt == mark.attempt && m_inFlight.at(i).sentNs == 0) {
            Pending &p = m_inFlight[i];
            p.sentNs = lastByteNs;
            // Timeouts (and a broadcast's turnaround) run from the moment the request left.
            p.deadlineNs = lastByteNs + waitNs(p.out.item);
        }
        if (mark.endsWrite)
            break;
    }
    armDeadline();
}

void EngineCore::armDeadline()
{
    // Restarting a QTimer unregisters and registers it with the event dispatcher, which per
    // request was a large share of the engine's work. The timer is armed only when it would fire
    // too late (or not at all); one that fires early, because the request it was armed for was
    // answered, finds nothing due and arms itself for the next deadline. With nothing in flight
    // it is left to fire once for nothing.
    if (m_inFlight.isEmpty())
        return;
    qint64 earliest = m_inFlight.constFirst().deadlineNs;
    for (const Pending &p : m_inFlight)
        earliest = qMin(earliest, p.deadlineNs);
    if (m_deadlineTimer.isActive() && m_deadlineArmedNs <= earliest)
        return;
    m_deadlineArmedNs = earliest;
    m_deadlineTimer.start(msUntil(earliest, monotonicNowNs()));
}

void EngineCore::onDeadline()
{
    const qint64 now = monotonicNowNs();
    QList<quint64> due;
    for (const Pending &p : m_inFlight) {
        if (p.deadlineNs <= now)
            due.append(p.out.id);
    }
    for (const quint64 id : due) {
        qsizetype i = indexOfId(id);
        if (i < 0)
            continue;
        if (m_inFlight.at(i).out.item.broadcast) {
            finish(i, TransactionStatus::Broadcast, {});
            continue;
        }
        QString partial;
        if (m_inFlight.size() == 1) {
            // Bytes the framer still holds may be this request's answer cut short.
            const qint64 held = flushPartial();
            i = indexOfId(id);
            if (i < 0)
                continue;
            if (held > 0)
                partial = QStringLiteral("; %1 bytes of an unfinished answer were skipped").arg(held);
        }
        Pending late = m_inFlight.at(i);
        late.timedOutNs = now;
        m_timedOut.append(late);
        m_lastEndAnswered = false;
        while (m_timedOut.size() > qMax(0, m_options.lateWindow))
            m_timedOut.removeFirst();
        finish(i, TransactionStatus::Timeout, QStringLiteral("no answer within %1 ms").arg(late.out.item.timeoutMs) + partial);
    }
    armDeadline();
}

qsizetype EngineCore::indexOfId(quint64 id) const
{
    for (qsizetype i = 0; i < m_inFlight.size(); ++i) {
        if (m_inFlight.at(i).out.id == id)
            return i;
    }
    return -1;
}

void EngineCore::finish(qsizetype index, TransactionStatus status, const QString &problem, const QByteArray &response,
                        qint64 firstNs, qint64 lastNs, quint8 exceptionCode)
{
    Pending p = m_inFlight.takeAt(index);
    if (retryable(status) && p.out.attempt < p.out.item.retries) {
        Outgoing again = p.out;
        again.item.bytes = p.out.item.bytes;
        again.history += QStringLiteral("attempt %1: %2: %3; ").arg(again.attempt + 1).arg(transactionStatusName(status), problem);
        ++again.attempt;
        ++m_counters.retries;
        m_queue.prepend(again);
        armDeadline();
        pump();
        return;
    }
    if (!response.isEmpty()) {
        m_answered.append(p.out.item);
        m_lastEndAnswered = true;
        if (m_answered.size() > 8)
            m_answered.removeFirst();
    }
    Transaction t;
    t.id = p.out.id;
    t.item = p.out.itemIndex;
    t.attempt = p.out.attempt;
    t.request = p.sent;
    t.response = response;
    t.status = status;
    t.exceptionCode = exceptionCode;
    t.problem = p.out.history + problem;
    t.sentNs = sentTime(p, firstNs);
    t.firstByteNs = firstNs;
    t.doneNs = lastNs;
    t.transactionIdRewritten = p.rewritten;
    record(std::move(t), p.out.tag);
    armDeadline();
    pump();
}

qint64 EngineCore::sentTime(const Pending &p, qint64 firstNs)
{
    // The link's time for the last request byte, unless the answer began before it (a serial
    // link's drain time is computed, and a pseudo terminal drains at once): an answer cannot
    // begin before its request left, so its first byte bounds the send time, and the moment the
    // write began is the latest time known to be before it.
    const qint64 linkNs = p.sentNs != 0 ? p.sentNs : p.predictedSentNs;
    if (linkNs != 0 && (firstNs == 0 || linkNs <= firstNs))
        return linkNs;
    return p.writeStartNs;
}

void EngineCore::record(Transaction transaction, quint64 tag)
{
    ++m_counters.transactions;
    if (transaction.status == TransactionStatus::Late)
        ++m_counters.late;
    logTransaction(transaction);
    if (m_recordListeners.size() == 1) {
        m_recordListeners.constFirst()->onRecord(transaction, tag);
    } else if (!m_recordListeners.isEmpty()) {
        // A listener may go (or add another) while records are handed out: each one still
        // listening gets this record once.
        const QList<RecordListener *> listeners = m_recordListeners;
        for (RecordListener *listener : listeners) {
            if (m_recordListeners.contains(listener))
                listener->onRecord(transaction, tag);
        }
    }
    if (m_recordedReceivers.load(std::memory_order_relaxed) > 0)
        Q_EMIT recorded(transaction, tag);
    m_batch.append(std::move(transaction));
    scheduleBatch();
}

void EngineCore::connectNotify(const QMetaMethod &signal)
{
    if (signal == QMetaMethod::fromSignal(&EngineCore::recorded))
        m_recordedReceivers.fetch_add(1, std::memory_order_relaxed);
}

void EngineCore::disconnectNotify(const QMetaMethod &signal)
{
    // An invalid method (everything disconnected at once) does not say which: the count stays,
    // and recorded() goes on being emitted, which is only slower.
    if (signal == QMetaMethod::fromSignal(&EngineCore::recorded))
        m_recordedReceivers.fetch_sub(1, std::memory_order_relaxed);
}

void EngineCore::addRecordListener(RecordListener *listener)
{
    if (!m_recordListeners.contains(listener))
        m_recordListeners.append(listener);
}

void EngineCore::removeRecordListener(RecordListener *listener)
{
    m_recordListeners.removeAll(listener);
}

void EngineCore::scheduleBatch()
{
    if (m_batchTimer.isActive())
        return;
    const qint64 intervalNs = qint64(m_options.batchIntervalMs) * 1000000;
    m_batchTimer.start(msUntil(m_lastBatchNs + intervalNs, monotonicNowNs()));
}

void EngineCore::flushBatch()
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
    if (!m_unmatched.isEmpty())
        Q_EMIT unmatchedFrames(std::exchange(m_unmatched, {}), m_url.toString());
    m_progress.counters = m_counters;
    Q_EMIT progress(m_progress);
}

} // namespace mbscope
