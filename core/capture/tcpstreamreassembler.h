#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>

#include <functional>
#include <map>

namespace mbscope {

// One direction of a TCP connection put back in order from captured segments, as the receiver's
// socket would read it: retransmitted bytes are dropped, overlapping segments trimmed, segments
// that came early kept until the hole before them is filled. Bytes the capture never saw (a
// dropped packet, a capture started mid-stream) are given up on once more than maxBuffered bytes
// wait behind the hole, or at finish(), and reported as a gap so the framer above can start over.
class TcpStreamReassembler
{
public:
    // In stream order: gapBytes lost just before bytes (0 almost always), then bytes.
    using Sink = std::function<void(qint64 gapBytes, QByteArrayView bytes)>;

    explicit TcpStreamReassembler(Sink sink, qsizetype maxBuffered = 1 << 20);

    // One captured segment (flags as in the TCP header: SYN 0x02, FIN 0x01, RST 0x04).
    void add(quint32 sequence, quint8 flags, QByteArrayView payload);
    // The connection or the capture ended: what waits behind a hole is delivered after its gap.
    void finish();
    // A new connection on the same ports (a SYN after data): forget everything.
    void reset();

    [[nodiscard]] qint64 delivered() const { return m_offset; }   // bytes handed on (gaps included)
    [[nodiscard]] qint64 retransmittedBytes() const { return m_retransmitted; }
    [[nodiscard]] qint64 lostBytes() const { return m_lost; }
    [[nodiscard]] qint64 gaps() const { return m_gaps; }
    [[nodiscard]] qsizetype bufferedBytes() const { return m_bufferedBytes; }

private:
    void deliverInOrder(QByteArrayView bytes, qint64 gap);
    void drain();
    void skipHole();

    Sink m_sink;
    qsizetype m_maxBuffered;
    bool m_started = false;
    quint32 m_next = 0;  // sequence number expected next
    qint64 m_offset = 0; // stream offset of m_next
    std::map<qint64, QByteArray> m_early; // by stream offset
    qsizetype m_bufferedBytes = 0;
    qint64 m_retransmitted = 0;
    qint64 m_lost = 0;
    qint64 m_gaps = 0;
};

} // namespace mbscope
