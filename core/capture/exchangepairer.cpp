#include "exchangepairer.h"
#include "protocol/framingtraits.h"

#include <algorithm>

#include "protocol/hexnumber.h"
#include "exchange/responsematcher.h"
#include "protocol/dissector.h"
#include "protocol/functioncode.h"

namespace mbscope {

ExchangePairer::ExchangePairer(qint64 timeoutNs, Sink sink) : m_timeoutNs(timeoutNs), m_sink(std::move(sink)) {}

ExchangePairer::~ExchangePairer() = default;

ExchangePairer::Conversation &ExchangePairer::conversation(quint32 id)
{
    while (m_conversations.size() <= id)
        m_conversations.push_back(std::make_unique<Conversation>());
    return *m_conversations[id];
}

namespace {

// RTU and ASCII travel on a serial line (or tunnelled from one): one transaction at a time,
// answers known by unit and function code, not by an id.
} // namespace

ResponseVerdict &ExchangePairer::verdictFor(Framing framing)
{
    const int index = framing == Framing::Ascii ? 3 : framing == Framing::Rtu ? 2 : framing == Framing::Udp ? 1 : 0;
    if (!m_verdicts[index])
        m_verdicts[index] = std::make_unique<ResponseVerdict>(framing, false);
    return *m_verdicts[index];
}

void ExchangePairer::problem(const QString &what)
{
    if (m_problemCount++ < kMaxProblems)
        m_problems.append(what);
}

void ExchangePairer::add(const CapturedFrame &frame)
{
    expire(frame.timeNs);
    if (frame.direction == Direction::Request)
        addRequest(frame);
    else
        addResponse(frame);
    emitReady();
}

void ExchangePairer::finish(qint64 endNs)
{
    for (Slot &s : m_slots) {
        if (s.done)
            continue;
        const qint64 sentNs = s.exchange.transaction.sentNs;
        const bool timedOut = endNs < 0 || (endNs > sentNs && quint64(endNs) - quint64(sentNs) > quint64(m_timeoutNs));
        timeOut(s, endNs >= 0 && timedOut ? QStringLiteral("no answer within %1 ms").arg(double(m_timeoutNs) / 1e6)
                                          : QStringLiteral("no answer before the capture ended"));
        if (timedOut)
            continue;
        // Its timeout reaches past the end of the capture.
        ++m_counters.unansweredAtEnd;
        s.exchange.kind = CaptureExchange::Kind::Unanswered;
        s.exchange.transaction.problem =
            QStringLiteral("unanswered at the end of the capture: it ends %1 ms after this request, before its %2 ms timeout ran out")
                .arg(QString::number(double(std::max<qint64>(0, endNs - sentNs)) / 1e6, 'f', 3))
                .arg(double(m_timeoutNs) / 1e6);
    }
    emitReady();
}

void ExchangePairer::advance(qint64 nowNs)
{
    expire(nowNs);
    emitReady();
}

void ExchangePairer::answersLost(quint32 id)
{
    Conversation &c = conversation(id);
    while (!c.waitingInOrder.empty())
        timeOut(slot(c.waitingInOrder.front()), QStringLiteral("no answer in the capture: the bytes a gap lost may have held it"));
    emitReady();
}

void ExchangePairer::noteRequestProblems(const CapturedFrame &frame)
{
    Dissector::dissect(frame.bytes, DissectOptions{frame.framing, Direction::Request, {}}, m_requestDissection);
    if (m_requestDissection.fields.worstSeverity() < Severity::Error) {
        m_lastGoodRequest = frame.bytes;
        m_lastGoodFraming = frame.framing;
        return;
    }
    ++m_counters.malformedRequests;
    QString first;
    for (const Field &f : m_requestDissection.fields.fields()) {
        if (f.severity >= Severity::Error) {
            first = f.message;
            break;
        }
    }
    problem(QStringLiteral("packet %1: malformed request %2: %3")
                .arg(frame.packet)
                .arg(QString::fromLatin1(frame.bytes.left(24).toHex(' ').toUpper()), first));
}

void ExchangePairer::addRequest(const CapturedFrame &frame)
{
    ++m_counters.requests;
    // A poll repeats its requests: bytes the last well-formed request had (the MBAP transaction
    // id apart, which nothing checks) are well-formed too, and are not dissected again.
    const qsizetype same = frame.framing == Framing::Tcp || frame.framing == Framing::Udp ? 2 : 0;
    const bool known = !m_lastGoodRequest.isEmpty() && frame.framing == m_lastGoodFraming
        && frame.bytes.size() == m_lastGoodRequest.size() && frame.bytes.size() >= same
        && QByteArrayView(frame.bytes).sliced(same) == QByteArrayView(m_lastGoodRequest).sliced(same);
    if (!known)
        noteRequestProblems(frame);

    const quint64 index = m_firstSlot + m_slots.size();
    Slot &s = m_slots.emplace_back();
    s.exchange.conversation = frame.conversation;
    s.exchange.framing = frame.framing;
    s.exchange.requestPacket = frame.packet;
    Transaction &t = s.exchange.transaction;
    t.id = index;
    t.request = frame.bytes;
    t.sentNs = frame.timeNs;
    t.status = TransactionStatus::Timeout;

    const FrameKeys keys = ResponseMatcher::keysOf(frame.bytes, frame.framing);
    Conversation &c = conversation(frame.conversation);
    if (isSerialLine(frame.framing)) {
        if (keys.valid && keys.unit == 0) {
            t.status = TransactionStatus::Broadcast;
            s.done = true;
            return;
        }
        c.waitingInOrder.push_back(index);
        return;
    }
    if (!keys.valid)
        return; // too short for a transaction id: nothing can answer it; it times out
    const auto waiting = c.waitingById.constFind(keys.transactionId);
    if (waiting != c.waitingById.cend()) {
        timeOut(slot(waiting.value()), QStringLiteral("no answer before the client used transaction id %1 again").arg(keys.transactionId));
    }
    c.waitingById.insert(keys.transactionId, index);
}

void ExchangePairer::addResponse(const CapturedFrame &frame)
{
    const FrameKeys keys = ResponseMatcher::keysOf(frame.bytes, frame.framing);
    if (frame.undelimited) {
        // Skipped bytes that may be an answer: only a waiting request can make them one.
        Conversation &c = conversation(frame.conversation);
        for (auto it = c.waitingInOrder.begin(); it != c.waitingInOrder.end(); ++it) {
            const FrameKeys asked = ResponseMatcher::keysOf(slot(*it).exchange.transaction.request, frame.framing);
            if (!keys.valid || asked.unit != keys.unit || !ResponseMatcher::answersFunction(asked.functionCode, keys.functionCode))
                continue;
            ++m_counters.responses;
            const quint64 index = *it;
            c.waitingInOrder.erase(it);
            answer(index, frame, true, {});
            return;
        }
        return;
    }
    ++m_counters.responses;
    if (!keys.valid) {
        unmatched(frame, QStringLiteral("too short to say which request it answers"));
        return;
    }
    Conversation &c = conversation(frame.conversation);
    if (!isSerialLine(frame.framing)) {
        const auto waiting = c.waitingById.find(keys.transactionId);
        if (waiting != c.waitingById.end()) {
            const quint64 index = waiting.value();
            c.waitingById.erase(waiting);
            const FrameKeys asked = ResponseMatcher::keysOf(slot(index).exchange.transaction.request, frame.framing);
            QString mismatch;
            if (asked.unit != keys.unit)
                mismatch = QStringLiteral("transaction id %1 answered by unit %2, but the request was for unit %3")
                               .arg(keys.transactionId).arg(keys.unit).arg(asked.unit);
            else if (!ResponseMatcher::answersFunction(asked.functionCode, keys.functionCode))
                mismatch = QStringLiteral("transaction id %1 answered with function 0x%2, but the request was 0x%3")
                               .arg(keys.transactionId)
                               .arg(hexNumber(keys.functionCode, 2))
                               .arg(hexNumber(asked.functionCode, 2));
            answer(index, frame, mismatch.isEmpty(), mismatch);
            return;
        }
        const auto timedOut = c.timedOutById.find(keys.transactionId);
        if (timedOut != c.timedOutById.end()) {
            const TimedOut request = timedOut.value();
            c.timedOutById.erase(timedOut);
            late(request, frame);
            return;
        }
        unmatched(frame, QStringLiteral("no request with transaction id %1 is waiting").arg(keys.transactionId));
        return;
    }
    for (auto it = c.waitingInOrder.begin(); it != c.waitingInOrder.end(); ++it) {
        const FrameKeys asked = ResponseMatcher::keysOf(slot(*it).exchange.transaction.request, frame.framing);
        if (asked.unit != keys.unit || !ResponseMatcher::answersFunction(asked.functionCode, keys.functionCode))
            continue;
        const quint64 index = *it;
        // Earlier requests were passed over: on a line that answers one request at a time,
        // they will not be answered now.
        while (c.waitingInOrder.front() != index)
            timeOut(slot(c.waitingInOrder.front()), QStringLiteral("no answer: the line answered a later request"));
        c.waitingInOrder.pop_front();
        answer(index, frame, true, {});
        return;
    }
    const FrameKeys previous = ResponseMatcher::keysOf(c.lastTimedOut.request, frame.framing);
    if (c.lastTimedOut.id != 0 && previous.valid && previous.unit == keys.unit
        && ResponseMatcher::answersFunction(previous.functionCode, keys.functionCode)) {
        const TimedOut request = c.lastTimedOut;
        c.lastTimedOut = {};
        late(request, frame);
        return;
    }
    unmatched(frame, QStringLiteral("no request to unit %1 with function 0x%2 is waiting")
                         .arg(keys.unit)
                         .arg(hexNumber(keys.functionCode & 0x7f, 2)));
}

void ExchangePairer::answer(quint64 slotIndex, const CapturedFrame &frame, bool keysMatch, const QString &mismatch)
{
    Slot &s = slot(slotIndex);
    Transaction &t = s.exchange.transaction;
    s.exchange.responsePacket = frame.packet;
    t.response = frame.bytes;
    t.firstByteNs = t.doneNs = frame.timeNs;
    if (keysMatch) {
        ResponseVerdict::Result verdict = verdictFor(frame.framing).judge(frame.bytes, t.request);
        if (frame.undelimited && (verdict.status == TransactionStatus::Ok || verdict.status == TransactionStatus::Exception)) {
            verdict.status = TransactionStatus::Malformed;
            verdict.problem = QStringLiteral("the answer's bytes could not be delimited as an RTU frame");
        }
        t.status = verdict.status;
        t.exceptionCode = verdict.exceptionCode;
        t.problem = std::move(verdict.problem);
    } else {
        t.status = TransactionStatus::Unexpected;
        t.problem = mismatch;
    }
    s.done = true;
}

void ExchangePairer::late(const TimedOut &request, const CapturedFrame &frame)
{
    ++m_counters.lateResponses;
    Slot &s = m_slots.emplace_back();
    s.exchange.conversation = frame.conversation;
    s.exchange.framing = frame.framing;
    s.exchange.requestPacket = request.packet;
    s.exchange.responsePacket = frame.packet;
    Transaction &t = s.exchange.transaction;
    t.id = m_firstSlot + m_slots.size() - 1;
    t.request = request.request;
    t.response = frame.bytes;
    t.sentNs = request.sentNs;
    t.firstByteNs = t.doneNs = frame.timeNs;
    t.status = TransactionStatus::Late;
    t.problem = QStringLiteral("an answer %1 ms after its request (packet %2), which had timed out")
                    .arg(QString::number(double(frame.timeNs - request.sentNs) / 1e6, 'f', 3))
                    .arg(request.packet);
    s.done = true;
}

void ExchangePairer::unmatched(const CapturedFrame &frame, const QString &why)
{
    ++m_counters.unmatchedResponses;
    problem(QStringLiteral("packet %1: an answer that matches no request (%2): %3")
                .arg(frame.packet)
                .arg(why, QString::fromLatin1(frame.bytes.left(24).toHex(' ').toUpper())));
    Slot &s = m_slots.emplace_back();
    s.exchange.kind = CaptureExchange::Kind::UnmatchedResponse;
    s.exchange.conversation = frame.conversation;
    s.exchange.framing = frame.framing;
    s.exchange.responsePacket = frame.packet;
    Transaction &t = s.exchange.transaction;
    t.id = m_firstSlot + m_slots.size() - 1;
    t.response = frame.bytes;
    t.firstByteNs = t.doneNs = frame.timeNs;
    t.status = TransactionStatus::Unexpected;
    t.problem = why;
    s.done = true;
}

void ExchangePairer::expire(qint64 nowNs)
{
    for (Slot &s : m_slots) {
        if (s.done)
            continue;
        // A damaged capture's times can be anything: the difference is taken so that it cannot
        // overflow (a clock going backwards has not expired anything).
        const qint64 sentNs = s.exchange.transaction.sentNs;
        if (nowNs <= sentNs || quint64(nowNs) - quint64(sentNs) <= quint64(m_timeoutNs))
            break;
        timeOut(s, QStringLiteral("no answer within %1 ms").arg(double(m_timeoutNs) / 1e6));
    }
}

void ExchangePairer::timeOut(Slot &s, const QString &why)
{
    Transaction &t = s.exchange.transaction;
    Conversation &c = conversation(s.exchange.conversation);
    const FrameKeys keys = ResponseMatcher::keysOf(t.request, s.exchange.framing);
    const TimedOut record{t.request, t.sentNs, s.exchange.requestPacket, t.id};
    if (isSerialLine(s.exchange.framing)) {
        for (auto it = c.waitingInOrder.begin(); it != c.waitingInOrder.end(); ++it) {
            if (*it == t.id) {
                c.waitingInOrder.erase(it);
                break;
            }
        }
        c.lastTimedOut = record;
    } else if (keys.valid) {
        const auto waiting = c.waitingById.constFind(keys.transactionId);
        if (waiting != c.waitingById.cend() && waiting.value() == t.id)
            c.waitingById.erase(waiting);
        c.timedOutById.insert(keys.transactionId, record);
    }
    t.status = TransactionStatus::Timeout;
    t.problem = why;
    s.done = true;
}

void ExchangePairer::emitReady()
{
    while (!m_slots.empty() && m_slots.front().done) {
        m_sink(m_slots.front().exchange);
        m_slots.pop_front();
        ++m_firstSlot;
    }
}

} // namespace mbscope
