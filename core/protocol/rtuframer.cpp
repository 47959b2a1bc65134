#include "rtuframer.h"

#include "checksum.h"
#include "pdusize.h"

#include <algorithm>
#include <array>
#include <limits>

namespace mbscope {

namespace {

// A frame with its CRC appended low byte first has a CRC of zero (Serial Line V1.02, 6.2.2), so one
// pass over the candidate both computes and compares.
bool crcValid(QByteArrayView frame)
{
    return checksum::crc16Modbus(frame) == 0;
}

constexpr int kMinAduSize = 4; // unit id, function code, CRC

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
    if (baud <= 0)
        return 0;
    if (baud > 19200)
        return 750'000;
    return 15LL * 1'000'000'000LL * 11 / (10LL * baud);
}

qint64 RtuFramer::t35Ns(int baud)
{
    if (baud <= 0)
        return 0;
    if (baud > 19200)
        return 1'750'000;
    return 35LL * 1'000'000'000LL * 11 / (10LL * baud);
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
    std::sort(lengths.begin(), lengths.begin() + candidates);
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
        return {Verdict::Reject, 0, SkipReason::ChecksumMismatch, 0};
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
            skip(1, decision.reason);
            m_atBoundary = false;
            m_probes.clear();
            break;
        }
    }
}

// Resynchronisation looks at every start after the last boundary and takes the frame whose end
// (with a valid CRC) comes first; ties go to the earlier start. A bogus start that predicts a long
// frame therefore cannot hold back a real frame behind it, and the choice is the same however the
// bytes were chunked: fed one by one, the first frame to complete is the one that ends first.
// Each start's verdict is kept (m_probes) and only looked at again once enough bytes arrived.
bool RtuFramer::resynchronise()
{
    const QByteArrayView bytes = pending();
    const qsizetype available = bytes.size();
    if (m_probes.size() < available)
        m_probes.resize(available);
    qsizetype bestStart = -1;
    qsizetype bestEnd = std::numeric_limits<qsizetype>::max();
    for (qsizetype start = 0; start < available && start + kMinAduSize <= bestEnd; ++start) {
        Decision &probe = m_probes[start];
        if (probe.verdict == Verdict::Wait && start + probe.needed <= available) {
            const Decision decision = decide(bytes.sliced(start), false);
            probe.verdict = decision.verdict;
            probe.length = decision.length;
            probe.reason = decision.reason;
            probe.needed = decision.needed;
        }
        if (probe.verdict == Verdict::Accept && start + probe.length < bestEnd) {
            bestStart = start;
            bestEnd = start + probe.length;
        }
    }
    if (bestStart >= 0) {
        for (qsizetype i = 0; i < bestStart; ++i)
            skip(1, m_probes.at(i).reason, true);
        emitFrame(bestEnd - bestStart);
        m_atBoundary = true;
        m_probes.clear();
        return true;
    }
    // Starts at the front that cannot begin a frame are garbage: report them and let them go.
    qsizetype rejected = 0;
    while (rejected < m_probes.size() && m_probes.at(rejected).verdict == Verdict::Reject) {
        skip(1, m_probes.at(rejected).reason, true);
        ++rejected;
    }
    m_probes.remove(0, rejected);
    return rejected > 0;
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
                          QStringLiteral("function code 0x%1 has no length rule: the frame was ended by the "
                                         "silence and no CRC in it is valid")
                              .arg(QString::number(quint8(bytes[1]), 16).toUpper().rightJustified(2, QLatin1Char('0'))));
            }
        } else {
            skip(bytes.size(), SkipReason::Incomplete, !m_atBoundary);
        }
    }
    m_atBoundary = true;
    m_crcScanned = 0;
    m_probes.clear();
}

void RtuFramer::resetState()
{
    m_atBoundary = true;
    m_crcScanned = 0;
    m_probes.clear();
}

} // namespace mbscope
