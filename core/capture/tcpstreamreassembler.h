#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>

#include <functional>
#include <map>

namespace mbscope {

// One direction of a TCP connection put back in order from captured segments, as the receiver's
// socket would read it: retransmitted bytes are dropped, overlapping segments trimmed, segments
// that came early kept until the hole before them is filled. Bytes the capture never saw (a
// packet the capture dropped) are given up on as soon as the peer acknowledges them (RFC 9293,
// 3.4: the receiver has them, so no retransmission will bring them into the capture), else once
// more than maxBuffered bytes wait behind the hole, or at finish(); they are reported as a gap so
// the framer above can find the next frame boundary. A stream whose first segment was not
// preceded by its SYN (a capture started mid-stream) starts with kJoinedMidStream.
class TcpStreamReassembler
{
public:
    // In stream order: gapBytes lost just before bytes (0 almost always), then bytes (empty when
    // an acknowledgement alone revealed the gap).
    using Sink = std::function<void(qint64 gapBytes, QByteArrayView bytes)>;
    // gapBytes of the first delivery of a stream joined mid-way: how much came before is unknown.
    static constexpr qint64 kJoinedMidStream = -1;

    explicit TcpStreamReassembler(Sink sink, qsizetype maxBuffered = 1 << 20);

    // One captured segment (flags as in the TCP header: SYN 0x02, FIN 0x01, RST 0x04).
    void add(quint32 sequence, quint8 flags, QByteArrayView payload);
    // The peer acknowledged everything before sequence number ack (a segment the other way with
    // the ACK flag): bytes up to it that the capture did not see are lost, and delivered as a gap.
    void acknowledged(quint32 ack);
    // The connection or the capture ended: what waits behind a hole is delivered after its gap.
    void finish();
    // A new connection on the same ports (a SYN after data): forget everything.
    void reset();

    [[nodiscard]] qint64 delivered() const { return m_offset; }   // bytes handed on (gaps included)
    [[nodiscard]] qint64 retransmittedBytes() const { return m_retransmitted; }
    [[nodiscard]] qint64 lostBytes() const { return m_lost; }
    [[nodiscard]] qint64 gaps() const { return m_gaps; }
    [[nodiscard]] qsizetype bufferedBytes() const { return m_bufferedBytes; }
    [[nodiscard]] bool joinedMidStream() const { return m_joinedMidStream; }

private:
    void deliverInOrder(QByteArrayView bytes, qint64 gap);
    void drain();
    void skipHole();

    Sink m_sink;
    qsizetype m_maxBuffered;
    bool m_started = false;
    bool m_joinedMidStream = false;
    bool m_announceMidStream = false; // the next delivery says kJoinedMidStream
    bool m_finSeen = false;
    quint32 m_fin = 0;   // the FIN's sequence number: its acknowledgement is not a lost byte
    quint32 m_next = 0;  // sequence number expected next
    qint64 m_offset = 0; // stream offset of m_next
    std::map<qint64, QByteArray> m_early; // by stream offset
    qsizetype m_bufferedBytes = 0;
    qint64 m_retransmitted = 0;
    qint64 m_lost = 0;
    qint64 m_gaps = 0;
};

} // namespace mbscope
