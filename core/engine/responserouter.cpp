#include "responserouter.h"

namespace mbscope {

namespace {

constexpr qsizetype kAnsweredKept = 8;

} // namespace

void ResponseRouter::reset(const LinkFraming &framing, int lateWindow)
{
    m_framing = framing;
    m_lateWindow = qMax(0, lateWindow);
    clear();
}

void ResponseRouter::clear()
{
    m_timedOut.clear();
    m_answered.clear();
    m_lastEndAnswered = false;
}

FrameKeys ResponseRouter::keysOf(QByteArrayView frame) const
{
    return m_framing.delimited ? FrameKeys{} : ResponseMatcher::keysOf(frame, m_framing.framing);
}

ResponseRouter::Route ResponseRouter::route(const FrameKeys &keys, qint64 firstNs, const QList<InFlightRequest> &inFlight)
{
    // Only requests written before the frame's first byte are candidates.
    qsizetype candidate = -1;
    int eligible = 0;
    for (qsizetype i = 0; i < inFlight.size(); ++i) {
        const InFlightRequest &p = inFlight.at(i);
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
    if (candidate >= 0 && eligible > 1 && inFlight.at(candidate).out.item.rule == MatchRule::Mbap)
        candidate = -1; // several in flight and no transaction id matches: nobody's answer
    if (candidate < 0)
        return unmatched(keys, firstNs);

    const InFlightRequest &p = inFlight.at(candidate);
    if (p.out.item.broadcast) {
        m_problem = QStringLiteral("an answer came to a broadcast (unit 0 is never answered: Serial Line V1.02, 2.1)");
        return {Route::Kind::Unexpected, candidate};
    }
    const ResponseMatcher::Result match = m_framing.delimited ? ResponseMatcher::Result{ResponseMatcher::Outcome::Match, {}}
                                                             : ResponseMatcher::match(p.out.item, keys);
    if (match.matched())
        return {Route::Kind::Answer, candidate};
    const Route other = unmatched(keys, firstNs);
    if (other.kind != Route::Kind::Unsolicited)
        return other;
    m_problem = match.problem;
    return {Route::Kind::Unexpected, candidate};
}

ResponseRouter::Route ResponseRouter::unmatched(const FrameKeys &keys, qint64 firstNs)
{
    if (isSecondCopyOfLatest(keys))
        return {Route::Kind::Duplicate, -1};
    if (findLate(keys, firstNs))
        return {Route::Kind::Late, -1};
    if (isDuplicate(keys))
        return {Route::Kind::Duplicate, -1};
    return {};
}

qsizetype ResponseRouter::routeSkipped(QByteArrayView bytes, qint64 firstNs, const QList<InFlightRequest> &inFlight) const
{
    const FrameKeys keys = ResponseMatcher::keysOf(bytes, Framing::Rtu);
    for (qsizetype i = 0; i < inFlight.size(); ++i) {
        const InFlightRequest &p = inFlight.at(i);
        if (!p.out.item.broadcast && firstNs >= p.writeStartNs && ResponseMatcher::match(p.out.item, keys).matched())
            return i;
    }
    return -1;
}

bool ResponseRouter::isSecondCopyOfLatest(const FrameKeys &keys) const
{
    // On RTU and ASCII only unit and function code name an answer, so a second copy of the answer
    // just received would also "match" any older timed-out request with the same keys. A serial
    // exchange is strictly sequential: the copy of a newer answer is a duplicate, not a late
    // answer to an older request. MBAP answers carry their transaction id and need no such rule.
    // Only when the latest request to end was answered: after a timeout the frame may well be
    // that request's late answer.
    const bool keyedById = m_framing.framing == Framing::Tcp || m_framing.framing == Framing::Udp;
    return !keyedById && m_lastEndAnswered && !m_answered.isEmpty() && m_answered.last().rule != MatchRule::NextFrame
        && ResponseMatcher::match(m_answered.last(), keys).matched();
}

bool ResponseRouter::findLate(const FrameKeys &keys, qint64 firstNs)
{
    // The most recent timed-out request that this frame answers (and that was written before it).
    for (qsizetype i = m_timedOut.size() - 1; i >= 0; --i) {
        const InFlightRequest &p = m_timedOut.at(i);
        if (firstNs < p.writeStartNs)
            continue;
        if (!m_framing.delimited && !ResponseMatcher::match(p.out.item, keys).matched())
            continue;
        m_late = m_timedOut.takeAt(i);
        return true;
    }
    return false;
}

bool ResponseRouter::isDuplicate(const FrameKeys &keys) const
{
    if (m_framing.delimited || !keys.valid)
        return false;
    for (const RequestItem &item : m_answered) {
        if (item.rule != MatchRule::NextFrame && ResponseMatcher::match(item, keys).matched())
            return true;
    }
    return false;
}

void ResponseRouter::timedOut(const InFlightRequest &request, qint64 nowNs)
{
    m_timedOut.append(request);
    m_timedOut.last().timedOutNs = nowNs;
    m_lastEndAnswered = false;
    while (m_timedOut.size() > m_lateWindow)
        m_timedOut.removeFirst();
}

void ResponseRouter::answered(const RequestItem &item)
{
    m_answered.append(item);
    m_lastEndAnswered = true;
    if (m_answered.size() > kAnsweredKept)
        m_answered.removeFirst();
}

} // namespace mbscope
