#include "enginecore.h"

#include "protocol/framing.h"
#include "protocol/streamframer.h"
#include "transport/monotonicclock.h"

#include <utility>

namespace mbscope {

namespace {

QString msText(qint64 ns)
{
    return QString::number(double(ns) / 1e6, 'f', 3);
}

} // namespace

void EngineCore::onBytesReceived(const QByteArray &bytes, qint64 firstNs, qint64 lastNs)
{
    if (bytes.isEmpty())
        return;
    m_counters.bytesIn += quint64(bytes.size());
    if (m_frameGapNs > 0) // before the answer is handled: the next request waits for t3.5 after it
        m_lineQuietNs = qMax(m_lineQuietNs, lastNs + m_frameGapNs);
    m_stamps.add(m_framer->streamSize(), bytes.size(), firstNs, lastNs);
    m_framer->feed(bytes, lastNs);
    // A datagram is whole: nothing in it waits for the next one (Modbus UDP and RTU over UDP
    // carry one ADU per datagram).
    if (m_framing.datagram)
        m_framer->flushOnSilence();
    processFramerOutput();
    armSilence();
}

void EngineCore::armSilence()
{
    if (m_framing.silenceNs <= 0 || (m_framer->pendingSize() == 0 && m_framer->openSkippedRunSize() == 0)) {
        m_silenceTimer.stop();
        return;
    }
    const qint64 due = m_framer->lastFeedNs() + m_framing.silenceNs;
    const qint64 now = monotonicNowNs();
    m_silenceTimer.start(due <= now ? 0 : int((due - now + 999999) / 1000000));
}

void EngineCore::onSilence()
{
    // Serial RTU: the framer itself checks that t3.5 has passed since the last byte (Serial Line
    // V1.02, 2.5.1.1); a timer that fired early is armed again.
    if (!m_framer->onSilence(monotonicNowNs())) {
        armSilence();
        return;
    }
    processFramerOutput();
}

qint64 EngineCore::flushPartial()
{
    const qint64 held = m_framer->pendingSize() + m_framer->openSkippedRunSize();
    m_framer->flushOnSilence();
    processFramerOutput();
    m_silenceTimer.stop();
    return held;
}

void EngineCore::processFramerOutput()
{
    if (m_processing) {
        // Frames framed while those of a read are being handled (a flush from an error handler):
        // lists of their own, the engine's are in use.
        QList<StreamFrame> frames;
        QList<SkippedBytes> skipped;
        if (m_framer->takeOutput(frames, skipped))
            handleOutput(frames, skipped);
        return;
    }
    if (!m_framer->takeOutput(m_frames, m_skipped))
        return;
    // The next request goes out once every frame of this read has been handled, not in the
    // middle (a write may fail and reset the stream these frames came from).
    m_processing = true;
    handleOutput(m_frames, m_skipped);
    // Emptied but kept: their memory serves the next read (the frames' bytes live on in records).
    m_frames.clear();
    m_skipped.clear();
    m_processing = false;
    if (std::exchange(m_pumpAfterProcessing, false))
        pump();
}

void EngineCore::handleOutput(const QList<StreamFrame> &frames, const QList<SkippedBytes> &skipped)
{
    // Frames and skipped runs in stream order, as the bytes came.
    qsizetype f = 0;
    qsizetype s = 0;
    while (f < frames.size() || s < skipped.size()) {
        const bool takeSkipped = s < skipped.size() && (f >= frames.size() || skipped.at(s).offset < frames.at(f).offset);
        if (takeSkipped) {
            const SkippedBytes &run = skipped.at(s++);
            handleSkipped(run, m_stamps.firstNs(run.offset), m_stamps.lastNs(run.offset + run.count() - 1));
        } else {
            const StreamFrame &frame = frames.at(f++);
            handleFrame(frame, m_stamps.firstNs(frame.offset), m_stamps.lastNs(frame.offset + frame.bytes.size() - 1));
        }
    }
}

void EngineCore::handleSkipped(const SkippedBytes &run, qint64 firstNs, qint64 lastNs)
{
    ++m_counters.skippedRuns;
    m_counters.skippedBytes += quint64(run.count());
    // An RTU answer with a wrong CRC, or cut short, cannot be delimited by the framer, which
    // skips it; its unit and function code may still name the pending request, whose status
    // then says what was wrong instead of a bare timeout.
    // Bytes left unfinished when the link was lost are the link's failure, not a bad answer: the
    // pending request ends as a link error that counts them.
    const bool cutByLoss = m_linkLost && run.reason == SkipReason::Incomplete;
    const bool rtuCandidate = !m_framing.delimited && m_framing.framing == Framing::Rtu && run.count() >= 4 && !cutByLoss
        && (run.reason == SkipReason::ChecksumMismatch || run.reason == SkipReason::Incomplete);
    const qsizetype i = rtuCandidate ? m_router.routeSkipped(run.bytes, firstNs, m_scheduler.inFlight()) : -1;
    if (i < 0) {
        m_recorder->logIncoming(run.bytes, firstNs, TrafficVerdict::Garbage);
        return;
    }
    const InFlightRequest &p = m_scheduler.inFlight().at(i);
    ResponseVerdict::Result v = m_verdict->judge(run.bytes, p.sent);
    if (run.reason == SkipReason::Incomplete) {
        // Ended by the silence before its length: cut short, as a Truncated frame is (ResponseVerdict).
        v.status = TransactionStatus::Malformed;
        v.exceptionCode = 0;
        v.problem = QStringLiteral("the answer was cut short: %1 bytes arrived before the silence").arg(run.count());
    } else if (v.status == TransactionStatus::Ok || v.status == TransactionStatus::Exception) {
        v.status = TransactionStatus::Malformed;
        v.problem = QStringLiteral("the answer's bytes could not be delimited as an RTU frame (%1)")
                        .arg(QString::fromLatin1(skipReasonName(run.reason)));
    }
    m_recorder->logIncoming(run.bytes, firstNs, trafficVerdict(v.status), p.out.id);
    finish(i, v.status, v.problem, run.bytes, firstNs, lastNs, v.exceptionCode);
}

void EngineCore::handleFrame(const StreamFrame &frame, qint64 firstNs, qint64 lastNs)
{
    if (m_linkLost && frame.status == FrameStatus::Truncated) {
        // The link went away in the middle of an answer: the request ends as a link error that
        // counts these bytes, not as a CRC error of a frame that never finished.
        ++m_counters.skippedRuns;
        m_counters.skippedBytes += quint64(frame.bytes.size());
        m_recorder->logIncoming(frame.bytes, firstNs, TrafficVerdict::Garbage);
        return;
    }
    const ResponseRouter::Route route = m_router.route(m_router.keysOf(frame.bytes), firstNs, m_scheduler.inFlight());
    using Kind = ResponseRouter::Route::Kind;
    switch (route.kind) {
    case Kind::Answer:
        answer(route.index, frame, firstNs, lastNs);
        return;
    case Kind::Unexpected:
        m_recorder->logIncoming(frame.bytes, firstNs, TrafficVerdict::Unexpected, m_scheduler.inFlight().at(route.index).out.id);
        finish(route.index, TransactionStatus::Unexpected, m_router.problem(), frame.bytes, firstNs, lastNs);
        return;
    case Kind::Late:
        recordLate(m_router.takeLate(), frame, firstNs, lastNs);
        return;
    case Kind::Duplicate:
        ++m_counters.duplicateFrames;
        unsolicited(frame.bytes, firstNs);
        return;
    case Kind::Unsolicited:
        unsolicited(frame.bytes, firstNs);
        return;
    }
}

void EngineCore::answer(qsizetype index, const StreamFrame &frame, qint64 firstNs, qint64 lastNs)
{
    const InFlightRequest &p = m_scheduler.inFlight().at(index);
    const ResponseVerdict::Result v = m_verdict->judge(frame, p.sent);
    m_recorder->logIncoming(frame.bytes, firstNs, trafficVerdict(v.status), p.out.id);
    finish(index, v.status, v.problem, frame.bytes, firstNs, lastNs, v.exceptionCode);
}

void EngineCore::recordLate(InFlightRequest late, const StreamFrame &frame, qint64 firstNs, qint64 lastNs)
{
    const ResponseVerdict::Result v = m_verdict->judge(frame, late.sent);
    // The request's earlier attempts were told with its timeout record; this one tells the answer.
    late.out.history.clear();
    const qint64 sentNs = late.sentTime(firstNs, lastNs, frame.bytes.size());
    QString problem = QStringLiteral("the answer came %1 ms after the request, %2 ms after its %3 ms timeout")
                          .arg(msText(lastNs - sentNs), msText(lastNs - late.timedOutNs)).arg(late.out.item.timeoutMs);
    if (v.status != TransactionStatus::Ok)
        problem += QStringLiteral("; the answer itself: %1%2%3")
                       .arg(transactionStatusName(v.status), v.problem.isEmpty() ? QString() : QStringLiteral(": "), v.problem);
    m_recorder->logIncoming(frame.bytes, firstNs, TrafficVerdict::Late, late.out.id);
    record(late.toTransaction(TransactionStatus::Late, problem, frame.bytes, firstNs, lastNs, v.exceptionCode), late.out.tag);
}

void EngineCore::unsolicited(const QByteArray &bytes, qint64 firstNs)
{
    ++m_counters.unsolicitedFrames;
    m_recorder->logIncoming(bytes, firstNs, TrafficVerdict::Unsolicited);
    m_recorder->scheduleBatch();
}

} // namespace mbscope
