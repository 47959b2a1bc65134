#pragma once

#include "capture/capturedframe.h"
#include "protocol/framing.h"
#include "protocol/streamframe.h"

#include <QtCore/QByteArrayView>

#include <functional>
#include <memory>

namespace mbscope {

class StreamFramer;

// What a listen-only tap on a serial line saw, frame by frame.
struct BusCounters {
    quint64 frames = 0;       // frames (valid, truncated, without a length rule, or RTU answers with a wrong CRC)
    quint64 requests = 0;
    quint64 responses = 0;    // answers, the damaged ones included
    quint64 crcErrors = 0;    // frames whose CRC (RTU) or LRC (ASCII) was wrong
    quint64 truncated = 0;    // RTU frames a silence cut before the length their code predicts
    quint64 malformed = 0;    // ASCII frames with bad digits or too short; RTU frames without a length rule and a valid CRC
    qint64 skippedBytes = 0;  // bytes no frame could use (a run with a wrong CRC too short to name its unit and function)
    quint64 skippedRuns = 0;
};

// Both directions of one serial line as one byte stream, cut into frames that know which way
// they went. A monitor's tap sees the master's requests and the slaves' answers interleaved, with
// nothing to say who sent what, so:
// - RTU is framed by RtuFramer in Direction::Auto (the length rules of requests and answers, the
//   CRC confirming), and by the silence the caller reports (t3.5, Serial Line V1.02, 2.5.1.1);
//   ASCII by ':' ... CR LF (2.5.2);
// - a frame is an answer when its function code has bit 7 set (an exception), or when a request
//   to the same unit with the same function is waiting (the line answers one request at a time,
//   2.1) and the frame's length is the one an answer would have: a read request (8 bytes) is never
//   taken for the answer to the read before it. Anything else is a request; a request to unit 0
//   (broadcast) waits for no answer;
// - an RTU run of bytes the framer skipped for a wrong CRC is counted as a CRC error, and (4 bytes
//   or more) as a frame and an answer offered to the pairer undelimited (CapturedFrame::undelimited):
//   when a request with its unit and function is waiting, it is that request's damaged answer.
// Frames come out in stream order through the sink, numbered 1, 2, 3... in CapturedFrame::packet.
class BusFramer
{
public:
    using FrameSink = std::function<void(const CapturedFrame &)>;
    // Bytes that were not a frame, with the time of the chunk that brought their last byte.
    using GarbageSink = std::function<void(const SkippedBytes &, qint64 timeNs)>;

    // answerWindowNs: how long a request waits for its answer (the pairer's timeout); a frame
    // after that is never taken for the answer.
    BusFramer(Framing framing, qint64 answerWindowNs, FrameSink sink);
    ~BusFramer();
    BusFramer(const BusFramer &) = delete;
    BusFramer &operator=(const BusFramer &) = delete;

    void setGarbageSink(GarbageSink sink) { m_garbageSink = std::move(sink); }

    // Bytes as the tap read them; every byte of the chunk gets timeNs.
    void feed(QByteArrayView bytes, qint64 timeNs);
    // The line has been quiet for the inter-frame time: whatever is pending ends there.
    void silence();

    [[nodiscard]] Framing framing() const { return m_framing; }
    [[nodiscard]] const BusCounters &counters() const { return m_counters; }
    [[nodiscard]] qsizetype pendingSize() const;

private:
    void collect();
    void frame(const StreamFrame &frame);
    void skipped(const SkippedBytes &run);
    [[nodiscard]] bool isAnswer(const QByteArray &bytes, qint64 timeNs, FrameStatus status) const;
    void emitFrame(const QByteArray &bytes, qint64 timeNs, Direction direction, FrameStatus status, bool undelimited);

    Framing m_framing;
    qint64 m_answerWindowNs;
    FrameSink m_sink;
    GarbageSink m_garbageSink;
    std::unique_ptr<StreamFramer> m_framer;
    BusCounters m_counters;
    quint64 m_number = 0;
    qint64 m_lastFeedNs = 0;
    // The request the line is waiting to see answered (none once answered, or for a broadcast).
    bool m_waiting = false;
    quint8 m_waitingUnit = 0;
    quint8 m_waitingFunction = 0;
    qint64 m_waitingSinceNs = 0;
};

} // namespace mbscope
