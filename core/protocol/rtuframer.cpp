#include "rtuframer.h"

#include "checksum.h"
#include "hexformat.h"
#include "pdusize.h"

#include <array>
#include <limits>
#include <utility>
#include <algorithm>

namespace mbscope {

namespace {

// A frame with its CRC appended low byte first has a CRC of zero (Serial Line V1.02, 6.2.2), so one
// pass over the candidate both computes and compares.
bool crcValid(QByteArrayView frame)
{
    return checksum::crc16Modbus(frame) == 0;
}

constexpr int kMinAduSize = 4; // unit id, function code, CRC

// halves / 2 character times of 11 bits at baud, or fixedNs above 19200 baud, where Serial Line
// V1.02, 2.5.1.1 fixes t1.5 at 750 us and t3.5 at 1.75 ms.
qint64 characterIntervalNs(int baud, int halves, qint64 fixedNs)
{
    if (baud <= 0)
        return 0;
    if (baud > 19200)
        return fixedNs;
    return halves * 1'000'000'000LL * 11 / (2LL * baud);
}

} // namespace

RtuFramer::RtuFramer(Direction direction)
    : m_direction(direction)
{
}

qint64 RtuFramer::characterTimeNs(int baud)
{
    if (baud <= 0)
        return 0;
    return 11LL * 1'000'000'000LL / baud;
}

qint64 RtuFramer::t15Ns(int baud)
{
    return characterIntervalNs(baud, 3, 750'000);
}

qint64 RtuFramer::t35Ns(int baud)
{
    return characterIntervalNs(baud, 7, 1'750'000);
}

bool RtuFramer::onSilence(qint64 nowNs)
{
    const qint64 last = lastFeedNs();
    if (m_baud > 0 && nowNs > 0 && last > 0 && nowNs - last < t35Ns(m_baud))
        return false;
    flushOnSilence();
    return true;
}

bool RtuFramer::isImpossible(quint8 functionCode) const
{
    // 0 is no function code; 0x80 would be the exception of function 0 (V1.1b3, 6 and 7); codes of
    // 0x80 and above only travel in responses.
    if (functionCode == 0x00 || functionCode == 0x80)
        return true;
    return m_direction == Direction::Request && functionCode > 0x80;
}

bool RtuFramer::hasLengthRule(QByteArrayView bytes) const
{
    const QByteArrayView pdu = bytes.sliced(1);
    for (Direction direction : {Direction::Request, Direction::Response}) {
        if (m_direction != Direction::Auto && m_direction != direction)
            continue;
        if (pdusize::expectedPduSize(pdu, direction).status != pdusize::Status::Unknown)
            return true;
    }
    return false;
}

qsizetype RtuFramer::predictedLength(QByteArrayView bytes) const
{
    const QByteArrayView pdu = bytes.sliced(1);
    qsizetype best = 0;
    for (Direction direction : {Direction::Request, Direction::Response}) {
        if (m_direction != Direction::Auto && m_direction != direction)
            continue;
        const pdusize::Expected expected = pdusize::expectedPduSize(pdu, direction);
        const qsizetype length = 1 + expected.size + 2;
        if (expected.status == pdusize::Status::Complete && length > bytes.size() && (best == 0 || length < best))
            best = length;
    }
    return best;
}

RtuFramer::Decision RtuFramer::decide(QByteArrayView bytes, bool atBoundary)
{
    const qsizetype available = bytes.size();
    if (available < 2)
        return {Verdict::Wait, 0, {}, 2};
    if (isImpossible(quint8(bytes[1])))
        return {Verdict::Reject, 0, SkipReason::ImpossibleFunction, 0};

    const QByteArrayView pdu = bytes.sliced(1);
    std::array<qsizetype, 2> lengths{};
    int candidates = 0;
    qsizetype needed = 0; // the fewest bytes that can change a Wait
    auto needAtLeast = [&needed](qsizetype count) { needed = needed == 0 ? count : qMin(needed, count); };
    bool noRule = false;
    bool tooLong = false;
    for (Direction direction : {Direction::Request, Direction::Response}) {
        if (m_direction != Direction::Auto && m_direction != direction)
            continue;
        const pdusize::Expected expected = pdusize::expectedPduSize(pdu, direction);
        switch (expected.status) {
        case pdusize::Status::Complete:
            if (1 + expected.size + 2 <= kMaxAduSize)
                lengths[size_t(candidates++)] = 1 + expected.size + 2;
            else
                tooLong = true; // a byte count no RTU frame can carry
            break;
        case pdusize::Status::NeedMore:
            if (1 + expected.size <= kMaxAduSize)
                needAtLeast(1 + expected.size);
            else
                tooLong = true;
            break;
        case pdusize::Status::Unknown:
            noRule = true;
            break;
        }
    }
    if (candidates == 2 && lengths[1] < lengths[0])
        std::swap(lengths[0], lengths[1]);
    for (int i = 0; i < candidates; ++i) {
        const qsizetype length = lengths[size_t(i)];
        if (length > available)
            needAtLeast(length);
        else if (crcValid(bytes.first(length)))
            return {Verdict::Accept, length, {}, 0};
    }
    if (needed > 0)
        return {Verdict::Wait, 0, {}, needed};
    if (candidates > 0)
        return {Verdict::Reject, 0, SkipReason::ChecksumMismatch, 0, lengths[0]};
    if (tooLong || !noRule)
        return {Verdict::Reject, 0, SkipReason::TooLong, 0};

    // No length rule: only a frame that starts at a known boundary can be waited for.
    if (!atBoundary)
        return {Verdict::Reject, 0, SkipReason::NoLengthRule, 0};
    const qsizetype limit = qMin<qsizetype>(available, kMaxAduSize);
    for (qsizetype length = qMax<qsizetype>(kMinAduSize, m_crcScanned + 1); length <= limit; ++length) {
        if (crcValid(bytes.first(length)))
            return {Verdict::Accept, length, {}, 0};
    }
    m_crcScanned = limit;
    if (available >= kMaxAduSize)
        return {Verdict::Reject, 0, SkipReason::TooLong, 0};
    return {Verdict::Wait, 0, {}, available + 1};
}

void RtuFramer::process()
{
    for (;;) {
        if (!m_atBoundary) {
            if (!resynchronise())
                return;
            continue;
        }
        const Decision decision = decide(pending(), true);
        m_crcScanned = decision.verdict == Verdict::Wait ? m_crcScanned : 0;
        switch (decision.verdict) {
        case Verdict::Wait:
            return;
        case Verdict::Accept:
            emitFrame(decision.length);
            break;
        case Verdict::Reject:
            if (m_dropsBadFrames && decision.badLength > 0) {
                skip(decision.badLength, decision.reason);
                break; // still at a boundary
            }
            skip(1, decision.reason);
            beginResync();
            break;
        }
    }
}

// Resynchronisation takes, among all starts after the last boundary, the frame with a valid CRC
// that ends first (ties go to the earlier start). A bogus start that predicts a long frame thus
// cannot hold back a real frame behind it. To make the choice the same however the bytes were
// chunked, pending bytes are delivered to it one at a time, as if fed one by one: each start gets
// a verdict from the bytes delivered so far, and is looked at again only when the bytes it waits
// for have come (a min-heap of those events), so each byte costs O(log n) besides the verdicts.
void RtuFramer::beginResync()
{
    m_atBoundary = false;
    m_probes.clear();
    m_probeOrigin = pendingOffset();
    m_delivered = pendingOffset();
    m_events.clear();
}

void RtuFramer::endResync()
{
    m_atBoundary = true;
    m_afterGap = false;
    m_probes.clear();
    m_events.clear();
}

bool RtuFramer::resynchronise()
{
    const auto later = [](const Event &a, const Event &b) { return a.at > b.at; };
    for (;;) {
        const qint64 base = pendingOffset();
        const QByteArrayView bytes = pending();
        if (m_delivered >= base + bytes.size())
            return false;
        ++m_delivered;

        // The start two bytes back now has a unit id and a function code to judge.
        const qint64 newStart = m_delivered - 2;
        if (newStart >= base) {
            m_probes.append(Decision{});
            m_events.push_back({m_delivered, newStart});
            std::push_heap(m_events.begin(), m_events.end(), later);
        }

        qint64 accepted = -1;
        while (!m_events.empty() && m_events.front().at <= m_delivered) {
            const qint64 start = m_events.front().start;
            std::pop_heap(m_events.begin(), m_events.end(), later);
            m_events.pop_back();
            if (start < base)
                continue;
            Decision &probe = m_probes[qsizetype(start - m_probeOrigin)];
            probe = decide(bytes.sliced(start - base, m_delivered - start), false);
            if (probe.verdict == Verdict::Wait) {
                m_events.push_back({start + probe.needed, start});
                std::push_heap(m_events.begin(), m_events.end(), later);
            } else if (probe.verdict == Verdict::Accept && (accepted < 0 || start < accepted)) {
                accepted = start;
            }
        }

        if (accepted >= 0) {
            const qsizetype length = m_probes.at(qsizetype(accepted - m_probeOrigin)).length;
            for (qint64 start = base; start < accepted; ++start)
                skip(1, m_afterGap ? SkipReason::AfterGap : m_probes.at(qsizetype(start - m_probeOrigin)).reason, true);
            emitFrame(length);
            endResync();
            return true;
        }

        // Starts at the front that cannot begin a frame are garbage: report them and let them go.
        while (pendingOffset() < m_delivered - 1) {
            const Decision &front = m_probes.at(qsizetype(pendingOffset() - m_probeOrigin));
            if (front.verdict != Verdict::Reject)
                break;
            skip(1, m_afterGap ? SkipReason::AfterGap : front.reason, true);
        }
        const qsizetype dead = qsizetype(pendingOffset() - m_probeOrigin);
        if (dead >= 512) {
            m_probes.remove(0, dead);
            m_probeOrigin += dead;
        }
    }
}

void RtuFramer::flushPending()
{
    const QByteArrayView bytes = pending();
    if (!bytes.isEmpty()) {
        if (m_atBoundary && bytes.size() >= 2 && !isImpossible(quint8(bytes[1]))) {
            if (hasLengthRule(bytes)) {
                const qsizetype predicted = predictedLength(bytes);
                const QString problem = predicted > 0
                    ? QStringLiteral("the function code and byte count predict %1 bytes but only %2 arrived "
                                     "before the silence").arg(predicted).arg(bytes.size())
                    : QStringLiteral("only %1 bytes arrived before the silence, too few to know the frame's "
                                     "length").arg(bytes.size());
                emitFrame(bytes.size(), FrameStatus::Truncated, problem);
            } else {
                emitFrame(bytes.size(), FrameStatus::Unverified,
                          QStringLiteral("function code %1 has no length rule: the frame was ended by the "
                                         "silence and no CRC in it is valid")
                              .arg(hexByte(quint8(bytes[1]))));
            }
        } else {
            skip(bytes.size(), m_afterGap ? SkipReason::AfterGap : SkipReason::Incomplete, !m_atBoundary);
        }
    }
    m_crcScanned = 0;
    endResync();
}

void RtuFramer::resetState()
{
    m_crcScanned = 0;
    endResync();
}

} // namespace mbscope
