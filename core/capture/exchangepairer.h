#pragma once

#include "capture/captureexchange.h"
#include "capture/capturedframe.h"
#include "exchange/responseverdict.h"
#include "protocol/dissection.h"

#include <QtCore/QHash>
#include <QtCore/QStringList>

#include <deque>
#include <functional>
#include <memory>
#include <vector>

namespace mbscope {

// Pairs captured requests with their answers and judges each answer as the engine does
// (ResponseVerdict), without any device:
// - MBAP (Modbus TCP and UDP): by transaction id within the conversation; an answer whose unit or
//   function code does not fit its request is Unexpected (V1.0b, 4.4.1.2: the id is the key);
// - RTU and ASCII: the oldest waiting request with the answer's unit and function code (or its exception);
//   requests before it that were never answered are timeouts (a serial line answers one at a
//   time); unit 0 is a broadcast, which expects no answer (Serial Line V1.02, 2.1).
// A request unanswered for timeoutNs of capture time is a Timeout, and an answer that comes
// after that is a Late record, as in the engine. Exchanges come out in request order. Every
// request is dissected as well; malformed ones are counted and the first few described.
class ExchangePairer
{
public:
    using Sink = std::function<void(const CaptureExchange &)>;

    struct Counters {
        quint64 requests = 0;
        quint64 responses = 0;
        quint64 unmatchedResponses = 0;
        quint64 malformedRequests = 0;
        quint64 lateResponses = 0;
        quint64 unansweredAtEnd = 0; // requests the capture ended within the timeout of (finish)
    };
    static constexpr int kMaxProblems = 20;

    ExchangePairer(qint64 timeoutNs, Sink sink);
    ~ExchangePairer();
    ExchangePairer(const ExchangePairer &) = delete;
    ExchangePairer &operator=(const ExchangePairer &) = delete;

    void add(const CapturedFrame &frame);
    // The capture lost bytes of a conversation's answers (a gap in a TCP stream). RTU answers
    // carry no id, so the requests waiting then are timeouts now: an answer after the gap is
    // given to a request sent after it, not to the one whose answer the gap may have held.
    void answersLost(quint32 conversation);
    // Time has passed without a frame (a live bus gone quiet): requests waiting longer than the
    // timeout are timeouts now.
    void advance(qint64 nowNs);
    // The capture ended. endNs: the time of its last packet (any packet, Modbus or not). A request
    // still waiting whose timeout had not run out by then is unanswered at the end of the capture
    // (CaptureExchange::Kind::Unanswered, counted in no figure, replay leaves it out): the capture
    // does not show whether its answer came, as a journal cut with a request in flight does not.
    // One waiting longer than the timeout is a timeout. Without endNs (a live bus stopped:
    // BusMonitor), every request still waiting is a timeout.
    void finish(qint64 endNs = -1);

    [[nodiscard]] const Counters &counters() const { return m_counters; }
    [[nodiscard]] const QStringList &problems() const { return m_problems; }
    [[nodiscard]] quint64 problemCount() const { return m_problemCount; }

private:
    struct Slot {
        CaptureExchange exchange;
        bool done = false;
    };
    struct TimedOut {
        QByteArray request;
        qint64 sentNs = 0;
        quint64 packet = 0;
        quint64 id = 0;
    };
    struct Conversation {
        QHash<quint16, quint64> waitingById; // MBAP: transaction id -> slot
        std::deque<quint64> waitingInOrder;  // RTU: slots in request order
        QHash<quint16, TimedOut> timedOutById;
        TimedOut lastTimedOut;                // RTU
    };

    // Dissects a request, counts and reports it when malformed, remembers it when well-formed.
    void noteRequestProblems(const CapturedFrame &frame);
    void addRequest(const CapturedFrame &frame);
    void addResponse(const CapturedFrame &frame);
    void answer(quint64 slotIndex, const CapturedFrame &frame, bool keysMatch, const QString &mismatch);
    void late(const TimedOut &request, const CapturedFrame &frame);
    void unmatched(const CapturedFrame &frame, const QString &why);
    void expire(qint64 nowNs);
    void timeOut(Slot &slot, const QString &problem);
    void emitReady();
    [[nodiscard]] Slot &slot(quint64 index) { return m_slots[std::size_t(index - m_firstSlot)]; }
    [[nodiscard]] Conversation &conversation(quint32 id);
    [[nodiscard]] ResponseVerdict &verdictFor(Framing framing);
    void problem(const QString &what);

    qint64 m_timeoutNs;
    Sink m_sink;
    Counters m_counters;
    std::deque<Slot> m_slots;
    quint64 m_firstSlot = 1; // index of m_slots.front()
    std::vector<std::unique_ptr<Conversation>> m_conversations;
    std::unique_ptr<ResponseVerdict> m_verdicts[4]; // Tcp, Udp, Rtu, Ascii
    Dissection m_requestDissection;
    QByteArray m_lastGoodRequest; // the last request found well-formed, and its framing
    Framing m_lastGoodFraming = Framing::Auto;
    QStringList m_problems;
    quint64 m_problemCount = 0;
};

} // namespace mbscope
