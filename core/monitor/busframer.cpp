#include "busframer.h"

#include "exchange/responsematcher.h"
#include "protocol/asciiframer.h"
#include "protocol/checksum.h"
#include "protocol/pdusize.h"
#include "protocol/rtuframer.h"

#include <cctype>

namespace mbscope {

namespace {

// The PDU of a whole frame: RTU without unit id and CRC; ASCII's hex digits read, without unit
// id and LRC. Empty when the frame is too short to hold one.
QByteArray pduOf(const QByteArray &frame, Framing framing)
{
    if (framing == Framing::Ascii) {
        if (frame.size() < 9)
            return {};
        const QByteArray binary = QByteArray::fromHex(frame.mid(1, frame.size() - 3));
        return binary.size() >= 3 ? binary.mid(1, binary.size() - 2) : QByteArray();
    }
    return frame.size() >= 4 ? frame.mid(1, frame.size() - 3) : QByteArray();
}

// ASCII: a frame whose digits read well but whose LRC does not match (the framer says only
// Malformed, for this and for bad digits alike).
bool asciiLrcWrong(const QByteArray &frame)
{
    if (frame.size() < 9 || (frame.size() - 3) % 2 != 0)
        return false;
    const QByteArray digits = frame.mid(1, frame.size() - 3);
    for (char c : digits) {
        if (!std::isxdigit(static_cast<unsigned char>(c)))
            return false;
    }
    const QByteArray binary = QByteArray::fromHex(digits);
    return checksum::lrc(QByteArrayView(binary).first(binary.size() - 1)) != quint8(binary.back());
}

} // namespace

BusFramer::BusFramer(Framing framing, qint64 answerWindowNs, FrameSink sink)
    : m_framing(framing == Framing::Ascii ? Framing::Ascii : Framing::Rtu)
    , m_answerWindowNs(answerWindowNs)
    , m_sink(std::move(sink))
{
    if (m_framing == Framing::Ascii)
        m_framer = std::make_unique<AsciiFramer>();
    else
        m_framer = std::make_unique<RtuFramer>(Direction::Auto);
}

BusFramer::~BusFramer() = default;

qsizetype BusFramer::pendingSize() const
{
    return m_framer->pendingSize() + m_framer->openSkippedRunSize();
}

void BusFramer::feed(QByteArrayView bytes, qint64 timeNs)
{
    if (bytes.isEmpty())
        return;
    m_lastFeedNs = timeNs;
    m_framer->feed(bytes, timeNs);
    collect();
}

void BusFramer::silence()
{
    m_framer->flushOnSilence();
    collect();
}

void BusFramer::collect()
{
    QList<StreamFrame> frames;
    QList<SkippedBytes> skippedRuns;
    if (!m_framer->takeOutput(frames, skippedRuns))
        return;
    // Frames and skipped runs in stream order, as the bytes came.
    qsizetype f = 0;
    qsizetype k = 0;
    while (f < frames.size() || k < skippedRuns.size()) {
        if (k < skippedRuns.size() && (f >= frames.size() || skippedRuns.at(k).offset < frames.at(f).offset))
            skipped(skippedRuns.at(k++));
        else
            frame(frames.at(f++));
    }
}

bool BusFramer::isAnswer(const QByteArray &bytes, qint64 timeNs, FrameStatus status) const
{
    const FrameKeys keys = ResponseMatcher::keysOf(bytes, m_framing);
    if (!keys.valid)
        return false;
    if (keys.functionCode & 0x80)
        return true; // only answers carry an exception code (V1.1b3, 7)
    if (!m_waiting || keys.unit != m_waitingUnit || keys.functionCode != m_waitingFunction
        || timeNs - m_waitingSinceNs > m_answerWindowNs)
        return false;
    if (status != FrameStatus::Valid)
        return true; // cut short or unverified: its keys are all there is to go by
    const QByteArray pdu = pduOf(bytes, m_framing);
    const pdusize::Expected answer = pdusize::expectedPduSize(pdu, Direction::Response);
    if (answer.status == pdusize::Status::Complete && answer.size == pdu.size())
        return true; // an echo (05, 06, 08) fits both rules: the waiting request makes it the answer
    const pdusize::Expected request = pdusize::expectedPduSize(pdu, Direction::Request);
    // No rule fits either way (a code without a length rule): the line's turn-taking decides.
    return answer.status != pdusize::Status::Complete
        && !(request.status == pdusize::Status::Complete && request.size == pdu.size());
}

void BusFramer::frame(const StreamFrame &f)
{
    ++m_counters.frames;
    if (f.status == FrameStatus::Truncated)
        ++m_counters.truncated;
    if (m_framing == Framing::Ascii && f.status == FrameStatus::Malformed) {
        if (asciiLrcWrong(f.bytes))
            ++m_counters.crcErrors;
        else
            ++m_counters.malformed;
    }
    if (m_framing == Framing::Rtu && f.status == FrameStatus::Unverified)
        ++m_counters.malformed;
    const Direction direction = isAnswer(f.bytes, f.lastByteNs, f.status) ? Direction::Response : Direction::Request;
    if (direction == Direction::Response) {
        ++m_counters.responses;
        m_waiting = false;
    } else {
        ++m_counters.requests;
        const FrameKeys keys = ResponseMatcher::keysOf(f.bytes, m_framing);
        // A broadcast (unit 0) is answered by nobody (Serial Line V1.02, 2.1).
        m_waiting = keys.valid && keys.unit != 0;
        m_waitingUnit = keys.unit;
        m_waitingFunction = keys.functionCode;
        m_waitingSinceNs = f.lastByteNs;
    }
    emitFrame(f.bytes, f.lastByteNs, direction, f.status, false);
}

void BusFramer::skipped(const SkippedBytes &run)
{
    const bool crcError = m_framing == Framing::Rtu && run.reason == SkipReason::ChecksumMismatch;
    if (crcError)
        ++m_counters.crcErrors;
    if (!crcError || run.count() < 4) {
        m_counters.skippedBytes += run.count();
        ++m_counters.skippedRuns;
        ++m_number;
        if (m_garbageSink)
            m_garbageSink(run, m_lastFeedNs);
        return;
    }
    // A damaged answer still names its unit and function: the pairer gives it to the request
    // waiting for them, if any (as the engine does with a bad CRC). It is an answer the line
    // carried, counted with the frames and answers as the exchange listing it is (tryout 8,
    // item 5: "answers 8" beside 10 answered exchanges), not as bytes no frame could use.
    const FrameKeys keys = ResponseMatcher::keysOf(run.bytes, Framing::Rtu);
    if (m_waiting && keys.valid && keys.unit == m_waitingUnit
        && ResponseMatcher::answersFunction(m_waitingFunction, keys.functionCode))
        m_waiting = false;
    ++m_counters.frames;
    ++m_counters.responses;
    emitFrame(run.bytes, m_lastFeedNs, Direction::Response, FrameStatus::Malformed, true);
}

void BusFramer::emitFrame(const QByteArray &bytes, qint64 timeNs, Direction direction, FrameStatus status, bool undelimited)
{
    CapturedFrame frame;
    frame.timeNs = timeNs;
    frame.packet = ++m_number;
    frame.framing = m_framing;
    frame.direction = direction;
    frame.status = status;
    frame.undelimited = undelimited;
    frame.bytes = bytes;
    m_sink(frame);
}

} // namespace mbscope
