#include "enginecore.h"

#include "protocol/framing.h"
#include "protocol/rtuframer.h"
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
    if (m_framing.baud > 0) {
        // Serial RTU: the framer itself checks that t3.5 has passed since the last byte
        // (Serial Line V1.02, 2.5.1.1); a timer that fired early is armed again.
        if (!static_cast<RtuFramer *>(m_framer.get())->onSilence(monotonicNowNs())) {
            armSilence();
            return;
        }
    } else {
        m_framer->flushOnSilence();
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
    if (rtuCandidate) {
        const FrameKeys keys = ResponseMatcher::keysOf(run.bytes, Framing::Rtu);
        for (qsizetype i = 0; i < m_inFlight.size(); ++i) {
            const Pending &p = m_inFlight.at(i);
            if (p.out.item.broadcast || firstNs < p.writeStartNs || !ResponseMatcher::match(p.out.item, keys).matched())
                continue;
            ResponseVerdict::Result v = m_verdict->judge(run.bytes, p.sent);
            if (v.status == TransactionStatus::Ok || v.status == TransactionStatus::Exception) {
                v.status = TransactionStatus::Malformed;
                v.problem = QStringLiteral("the answer's bytes could not be delimited as an RTU frame (%1)")
                                .arg(QString::fromLatin1(skipReasonName(run.reason)));
            }
            logIncoming(run.bytes, firstNs, trafficVerdict(v.status), p.out.id);
            finish(i, v.status, v.problem, run.bytes, firstNs, lastNs, v.exceptionCode);
            return;
        }
    }
    logIncoming(run.bytes, firstNs, TrafficVerdict::Garbage);
}

void EngineCore::handleFrame(const StreamFrame &frame, qint64 firstNs, qint64 lastNs)
{
    if (m_linkLost && frame.status == FrameStatus::Truncated) {
        // The link went away in the middle of an answer: the request ends as a link error that
        // counts these bytes, not as a CRC error of a frame that never finished.
        ++m_counters.skippedRuns;
        m_counters.skippedBytes += quint64(frame.bytes.size());
        logIncoming(frame.bytes, firstNs, TrafficVerdict::Garbage);
        return;
    }
    const FrameKeys keys = m_framing.delimited ? FrameKeys{} : ResponseMatcher::keysOf(frame.bytes, m_framing.framing);
    // An answer cannot begin before its request was written: only requests written before the
    // frame's first byte are candidates.
    qsizetype candidate = -1;
    int eligible = 0;
    for (qsizetype i = 0; i < m_inFlight.size(); ++i) {
        const Pending &p = m_inFlight.at(i);
        if (firstNs < p.writeStartNs)
            continue;
        ++eligible;
        if (candidate < 0)
            candidate = i;
        if (p.out.item.rule == MatchRule::Mbap && keys.valid && keys.transactionId == p.out.item.transactionId) {
            candidate = i; // the transaction id names its request, whatever its place in the pipeline
            eligible = 1;
            break;
        }
    }
    if (candidate >= 0 && eligible > 1 && m_inFlight.at(candidate).out.item.rule == MatchRule::Mbap)
        candidate = -1; // several in flight and no transaction id matches: nobody's answer

    if (candidate >= 0) {
        const Pending &p = m_inFlight.at(candidate);
        if (p.out.item.broadcast) {
            const QString problem = QStringLiteral("an answer came to a broadcast (unit 0 is never answered: Serial Line V1.02, 2.1)");
            logIncoming(frame.bytes, firstNs, TrafficVerdict::Unexpected, p.out.id);
            finish(candidate, TransactionStatus::Unexpected, problem, frame.bytes, firstNs, lastNs);
            return;
        }
        const ResponseMatcher::Result match = m_framing.delimited ? ResponseMatcher::Result{ResponseMatcher::Outcome::Match, {}}
                                                                 : ResponseMatcher::match(p.out.item, keys);
        if (match.matched()) {
            answer(candidate, frame, firstNs, lastNs);
            return;
        }
        if (duplicateFirst(keys) || tryLate(frame, keys, firstNs, lastNs)) {
            if (m_duplicateSeen)
                unsolicited(frame.bytes, firstNs);
            return;
        }
        if (isDuplicate(keys)) {
            ++m_counters.duplicateFrames;
            unsolicited(frame.bytes, firstNs);
            return;
        }
        logIncoming(frame.bytes, firstNs, TrafficVerdict::Unexpected, p.out.id);
        finish(candidate, TransactionStatus::Unexpected, match.problem, frame.bytes, firstNs, lastNs);
        return;
    }
    if (duplicateFirst(keys) || tryLate(frame, keys, firstNs, lastNs)) {
        if (m_duplicateSeen)
            unsolicited(frame.bytes, firstNs);
        return;
    }
    if (isDuplicate(keys)) {
        ++m_counters.duplicateFrames;
        unsolicited(frame.bytes, firstNs);
        return;
    }
    unsolicited(frame.bytes, firstNs);
}

bool EngineCore::duplicateFirst(const FrameKeys &keys)
{
    // On RTU and ASCII only unit and function code name an answer, so a second copy of the answer
    // just received would also "match" any older timed-out request with the same keys. A serial
    // exchange is strictly sequential: the copy of a newer answer is a duplicate, not a late
    // answer to an older request. MBAP answers carry their transaction id and need no such rule.
    m_duplicateSeen = false;
    // Only when the latest request to end was answered: after a timeout the frame may well be
    // that request's late answer.
    const bool keyedById = m_framing.framing == Framing::Tcp || m_framing.framing == Framing::Udp;
    if (keyedById || !m_lastEndAnswered || m_answered.isEmpty() || m_answered.last().rule == MatchRule::NextFrame
        || !ResponseMatcher::match(m_answered.last(), keys).matched())
        return false;
    ++m_counters.duplicateFrames;
    m_duplicateSeen = true;
    return true;
}

void EngineCore::answer(qsizetype index, const StreamFrame &frame, qint64 firstNs, qint64 lastNs)
{
    const ResponseVerdict::Result v = m_verdict->judge(frame, m_inFlight.at(index).sent);
    logIncoming(frame.bytes, firstNs, trafficVerdict(v.status), m_inFlight.at(index).out.id);
    finish(index, v.status, v.problem, frame.bytes, firstNs, lastNs, v.exceptionCode);
}

bool EngineCore::tryLate(const StreamFrame &frame, const FrameKeys &keys, qint64 firstNs, qint64 lastNs)
{
    // The most recent timed-out request that this frame answers (and that was written before it).
    for (qsizetype i = m_timedOut.size() - 1; i >= 0; --i) {
        const Pending &p = m_timedOut.at(i);
        if (firstNs < p.writeStartNs)
            continue;
        if (!m_framing.delimited && !ResponseMatcher::match(p.out.item, keys).matched())
            continue;
        const Pending late = m_timedOut.takeAt(i);
        const ResponseVerdict::Result v = m_verdict->judge(frame, late.sent);
        Transaction t;
        t.id = late.out.id;
        t.item = late.out.itemIndex;
        t.attempt = late.out.attempt;
        t.request = late.sent;
        t.response = frame.bytes;
        t.status = TransactionStatus::Late;
        t.exceptionCode = v.exceptionCode;
        t.sentNs = sentTime(late, firstNs);
        t.firstByteNs = firstNs;
        t.doneNs = lastNs;
        t.transactionIdRewritten = late.rewritten;
        t.problem = QStringLiteral("the answer came %1 ms after the request, %2 ms after its %3 ms timeout")
                        .arg(msText(lastNs - t.sentNs), msText(lastNs - late.timedOutNs)).arg(late.out.item.timeoutMs);
        if (v.status != TransactionStatus::Ok)
            t.problem += QStringLiteral("; the answer itself: %1%2%3")
                             .arg(transactionStatusName(v.status), v.problem.isEmpty() ? QString() : QStringLiteral(": "), v.problem);
        logIncoming(frame.bytes, firstNs, TrafficVerdict::Late, late.out.id);
        record(std::move(t), late.out.tag);
        return true;
    }
    return false;
}

bool EngineCore::isDuplicate(const FrameKeys &keys) const
{
    if (m_framing.delimited || !keys.valid)
        return false;
    for (const RequestItem &item : m_answered) {
        if (item.rule != MatchRule::NextFrame && ResponseMatcher::match(item, keys).matched())
            return true;
    }
    return false;
}

void EngineCore::unsolicited(const QByteArray &bytes, qint64 firstNs)
{
    ++m_counters.unsolicitedFrames;
    logIncoming(bytes, firstNs, TrafficVerdict::Unsolicited);
    scheduleBatch();
}

} // namespace mbscope
