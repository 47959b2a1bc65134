#include "enginecore.h"

#include "protocol/rtuframer.h"
#include "protocol/streamframer.h"
#include "transport/monotonicclock.h"
#include "transport/seriallink.h"

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
    , m_recorder(new EngineRecorder(&m_counters, &m_progress, this))
    , m_deadlineTimer(this)
    , m_silenceTimer(this)
    , m_openTimer(this)
    , m_gapTimer(this)
{
    setUpTimer(m_deadlineTimer);
    setUpTimer(m_silenceTimer);
    setUpTimer(m_openTimer);
    connect(&m_deadlineTimer, &QTimer::timeout, this, &EngineCore::onDeadline);
    connect(&m_silenceTimer, &QTimer::timeout, this, &EngineCore::onSilence);
    connect(&m_gapTimer, &DueTimer::timeout, this, &EngineCore::pump);
    connect(&m_openTimer, &QTimer::timeout, this, [this] {
        if (m_opening)
            onLinkError(LinkError{LinkError::Kind::Timeout,
                                  QStringLiteral("%1: the link did not open within %2 ms")
                                      .arg(m_url.toString()).arg(m_url.connectTimeoutMs)});
    });
    setTarget(LinkUrl{}, EngineOptions{});
    // The default target is no link: a journal attached before the real target (a scan's, a
    // watch's) must not get a nameless "tcp://:502" link with no frames.
    m_recorder->setLink(QString());
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

void EngineCore::setTarget(const LinkUrl &url, const EngineOptions &given)
{
    const EngineOptions options = given.withPaceOf(url);
    m_deferPump = true;
    failInFlight(QStringLiteral("%1: the target changed to %2").arg(m_url.toString(), url.toString()));
    m_deferPump = false;
    m_scheduler.forgetWrites();
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
    m_router.reset(m_framing, options.lateWindow);
    m_frameGapNs = url.kind == LinkKind::Rtu && m_framing.framing == Framing::Rtu ? RtuFramer::t35Ns(url.serial.baud) : 0;
    m_lineQuietNs = 0;
    m_requestGapNs = std::chrono::nanoseconds(options.requestGap).count();
    m_gapTimer.stop();
    updateBroadcastWait();
    m_recorder->setBatchInterval(options.batchIntervalMs);
    m_recorder->setLink(m_url.toString());
}

int EngineCore::pipelineDepth() const
{
    const bool mbap = !m_framing.delimited && (m_framing.framing == Framing::Tcp || m_framing.framing == Framing::Udp);
    return mbap && !m_options.closeAfterAnswer ? qMax(1, m_options.pipelineDepth) : 1;
}

void EngineCore::submit(const RequestItem &item, quint64 id, int itemIndex, quint64 tag)
{
    m_scheduler.enqueue(OutgoingRequest{item, id, itemIndex, 0, tag, {}});
    pump();
}

void EngineCore::cancel(quint64 tag)
{
    m_counters.abandoned += quint64(m_scheduler.cancel(tag));
    armDeadline();
    m_recorder->scheduleBatch();
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
    if (m_hangUpPending)
        return; // the link closes first (closeAfterAnswer); then this pumps again
    m_pumping = true;
    // A pipelined stream link gets the requests of one turn in one write: one system call and one
    // segment for all of them, and a server that reads what has come answers them together.
    // Datagram links carry one request per datagram.
    const int depth = pipelineDepth();
    const bool together = depth > 1 && !m_framing.datagram;
    while (m_scheduler.hasQueued()) {
        if (!m_link || m_link->state() != Link::State::Open) {
            ensureLink();
            break;
        }
        if (!m_scheduler.mayStage(depth) || !lineQuiet())
            break;
        stageNext();
        if (!together)
            writeStaged();
    }
    writeStaged();
    m_pumping = false;
}

bool EngineCore::lineQuiet()
{
    if (m_lineQuietNs == 0 || monotonicNowNs() >= m_lineQuietNs)
        return true;
    if (!m_gapTimer.isActive())
        m_gapTimer.start(m_lineQuietNs);
    return false;
}

void EngineCore::resetFramer()
{
    m_scheduler.forgetWrites();
    m_silenceTimer.stop();
    m_framer->reset();
    m_stamps.clear();
}

void EngineCore::stageNext()
{
    const InFlightRequest &p = m_scheduler.stage(pipelineDepth(), monotonicNowNs(), broadcastWaitNs());
    if (m_requestGapNs > 0) // pipelined requests too go out the device's gap apart
        m_lineQuietNs = qMax(m_lineQuietNs, p.writeStartNs + m_requestGapNs);
    ++m_counters.requestsSent;
    m_counters.bytesOut += quint64(p.sent.size());
    m_recorder->logOutgoing(p.sent, p.writeStartNs, p.out.id);
}

void EngineCore::writeStaged()
{
    if (!m_scheduler.hasStaged())
        return;
    WriteScheduler::WriteMarks staged;
    const QByteArray bytes = m_scheduler.takeStaged(&staged);
    if (!m_link->write(bytes)) {
        m_scheduler.forgetWrite(staged);
        for (const WriteScheduler::WriteMark &mark : staged) {
            const qsizetype i = m_scheduler.indexOfId(mark.id);
            if (i >= 0 && m_scheduler.inFlight().at(i).out.attempt == mark.attempt)
                finish(i, TransactionStatus::LinkError, QStringLiteral("%1: the link did not take the request").arg(m_url.toString()));
        }
    } else if (const auto *serial = qobject_cast<const SerialLink *>(m_link)) {
        // A serial link knows when the last byte will have left the line before it says so
        // (it signals once that time has come), and a fast answer may come first. (Serial links
        // carry one request per write.)
        const qsizetype i = m_scheduler.indexOfId(staged.last().id);
        if (i >= 0 && m_scheduler.inFlight().at(i).sentNs == 0 && serial->lineFreeNs() >= m_scheduler.inFlight().at(i).writeStartNs) {
            InFlightRequest &p = m_scheduler.inFlightAt(i);
            p.predictedSentNs = serial->lineFreeNs();
            p.characterNs = SerialLink::lineCharacterNs(serial->url().serial);
            p.deadlineNs = serial->lineFreeNs() + WriteScheduler::waitNs(p.out.item, broadcastWaitNs());
        }
        if (m_frameGapNs > 0)
            m_lineQuietNs = qMax(m_lineQuietNs, serial->lineFreeNs() + m_frameGapNs);
    }
    armDeadline();
    m_recorder->scheduleBatch();
}

void EngineCore::updateBroadcastWait()
{
    const qint64 linkTurnaround = m_link ? m_link->turnaroundNs() : 0;
    m_broadcastWaitNs = linkTurnaround > 0 ? linkTurnaround : qint64(m_options.broadcastTurnaroundMs) * 1000000;
}

void EngineCore::onBytesWritten(qint64 lastByteNs)
{
    m_scheduler.written(lastByteNs, broadcastWaitNs());
    armDeadline();
}

void EngineCore::armDeadline()
{
    // Restarting a QTimer unregisters and registers it with the event dispatcher, which per
    // request was a large share of the engine's work. The timer is armed only when it would fire
    // too late (or not at all); one that fires early, because the request it was armed for was
    // answered, finds nothing due and arms itself for the next deadline. With nothing in flight
    // it is left to fire once for nothing.
    if (m_scheduler.inFlight().isEmpty())
        return;
    const qint64 earliest = m_scheduler.earliestDeadline();
    if (m_deadlineTimer.isActive() && m_deadlineArmedNs <= earliest)
        return;
    m_deadlineArmedNs = earliest;
    m_deadlineTimer.start(msUntil(earliest, monotonicNowNs()));
}

void EngineCore::onDeadline()
{
    const qint64 now = monotonicNowNs();
    QList<quint64> due;
    for (const InFlightRequest &p : m_scheduler.inFlight()) {
        if (p.deadlineNs <= now)
            due.append(p.out.id);
    }
    for (const quint64 id : due) {
        qsizetype i = m_scheduler.indexOfId(id);
        if (i < 0)
            continue;
        if (m_scheduler.inFlight().at(i).out.item.broadcast) {
            finish(i, TransactionStatus::Broadcast, {});
            continue;
        }
        QString partial;
        if (m_scheduler.inFlight().size() == 1) {
            // Bytes the framer still holds may be this request's answer cut short.
            const qint64 held = flushPartial();
            i = m_scheduler.indexOfId(id);
            if (i < 0)
                continue;
            if (held > 0)
                partial = QStringLiteral("; %1 bytes of an unfinished answer were skipped").arg(held);
        }
        const InFlightRequest &late = m_scheduler.inFlight().at(i);
        m_router.timedOut(late, now);
        finish(i, TransactionStatus::Timeout, QStringLiteral("no answer within %1 ms").arg(late.out.item.timeoutMs) + partial);
    }
    armDeadline();
}

void EngineCore::finish(qsizetype index, TransactionStatus status, const QString &problem, const QByteArray &response,
                        qint64 firstNs, qint64 lastNs, quint8 exceptionCode)
{
    const InFlightRequest p = m_scheduler.takeInFlight(index);
    if (m_requestGapNs > 0) // the next request waits the device's gap after this exchange ended
        m_lineQuietNs = qMax(m_lineQuietNs, qMax(lastNs, monotonicNowNs()) + m_requestGapNs);
    if (retryable(status) && p.out.attempt < p.out.item.retries) {
        OutgoingRequest again = p.out;
        again.history += QStringLiteral("attempt %1: %2: %3; ").arg(again.attempt + 1).arg(transactionStatusName(status), problem);
        ++again.attempt;
        ++m_counters.retries;
        m_scheduler.retry(std::move(again));
        armDeadline();
        pump();
        return;
    }
    if (!response.isEmpty())
        m_router.answered(p.out.item);
    // Before the record: its listeners (a poll) submit the next request at once.
    if (m_options.closeAfterAnswer)
        hangUpWhenIdle();
    record(p.toTransaction(status, problem, response, firstNs, lastNs, exceptionCode), p.out.tag);
    armDeadline();
    pump();
}

void EngineCore::hangUpWhenIdle()
{
    if (m_hangUpPending || !m_scheduler.inFlight().isEmpty() || !m_link || m_link->state() != Link::State::Open)
        return;
    // Not inside the link's own callback (an answer being read): from the event loop.
    m_hangUpPending = true;
    QMetaObject::invokeMethod(this, [this] {
        m_hangUpPending = false;
        if (m_scheduler.inFlight().isEmpty() && m_link && m_link->state() == Link::State::Open)
            closeLink();
        pump();
    }, Qt::QueuedConnection);
}

void EngineCore::record(Transaction transaction, quint64 tag)
{
    ++m_counters.transactions;
    if (transaction.status == TransactionStatus::Late)
        ++m_counters.late;
    m_recorder->record(std::move(transaction), tag);
}

} // namespace mbscope

#include "moc_enginecore.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
