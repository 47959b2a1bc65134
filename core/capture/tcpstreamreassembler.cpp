#include "tcpstreamreassembler.h"

namespace mbscope {

namespace {
constexpr quint8 kFin = 0x01;
constexpr quint8 kSyn = 0x02;
} // namespace

TcpStreamReassembler::TcpStreamReassembler(Sink sink, qsizetype maxBuffered)
    : m_sink(std::move(sink)), m_maxBuffered(maxBuffered)
{
}

void TcpStreamReassembler::reset()
{
    m_started = false;
    m_joinedMidStream = false;
    m_announceMidStream = false;
    m_finSeen = false;
    m_fin = 0;
    m_next = 0;
    m_offset = 0;
    m_early.clear();
    m_bufferedBytes = 0;
}

void TcpStreamReassembler::add(quint32 sequence, quint8 flags, QByteArrayView payload)
{
    if (flags & kSyn) {
        // The SYN takes one sequence number; data (rare, TCP Fast Open) follows it.
        if (!m_started || m_offset == 0) {
            m_started = true;
            m_next = sequence + 1;
        }
        sequence += 1;
    }
    if (flags & kFin) {
        // The FIN takes the sequence number after the payload (RFC 9293, 3.4).
        m_finSeen = true;
        m_fin = sequence + quint32(payload.size());
    }
    if (payload.isEmpty())
        return;
    if (!m_started) {
        // A capture that began mid-connection: the first segment seen starts the stream.
        m_started = true;
        m_joinedMidStream = true;
        m_announceMidStream = true;
        m_next = sequence;
    }
    // Sequence numbers wrap at 2^32: the signed difference says before or after.
    qint64 diff = qint32(sequence - m_next);
    if (diff < 0) {
        const qint64 old = std::min<qint64>(-diff, payload.size());
        m_retransmitted += old;
        payload = payload.sliced(old);
        diff = 0;
        if (payload.isEmpty())
            return;
    }
    if (diff == 0) {
        deliverInOrder(payload, 0);
        drain();
        return;
    }
    const qint64 at = m_offset + diff;
    auto [it, inserted] = m_early.try_emplace(at, payload.toByteArray());
    if (!inserted) {
        if (it->second.size() < payload.size()) {
            m_bufferedBytes -= it->second.size();
            it->second = payload.toByteArray();
        } else {
            m_retransmitted += payload.size();
            return;
        }
    }
    m_bufferedBytes += payload.size();
    while (m_bufferedBytes > m_maxBuffered && !m_early.empty()) {
        skipHole();
        drain();
    }
}

void TcpStreamReassembler::acknowledged(quint32 ack)
{
    if (!m_started)
        return;
    if (m_finSeen && ack == m_fin + 1)
        ack = m_fin;
    const qint64 diff = qint32(ack - m_next);
    if (diff <= 0)
        return;
    const qint64 until = m_offset + diff;
    while (!m_early.empty() && m_early.begin()->first < until) {
        skipHole();
        drain();
    }
    if (m_offset < until) {
        const qint64 gap = until - m_offset;
        m_lost += gap;
        ++m_gaps;
        deliverInOrder({}, gap);
        drain();
    }
}

void TcpStreamReassembler::finish()
{
    while (!m_early.empty()) {
        skipHole();
        drain();
    }
}

void TcpStreamReassembler::deliverInOrder(QByteArrayView bytes, qint64 gap)
{
    m_offset += gap + bytes.size();
    m_next += quint32(gap + bytes.size());
    if (m_announceMidStream) {
        m_announceMidStream = false;
        gap = kJoinedMidStream;
    }
    m_sink(gap, bytes);
}

// Segments that now continue the stream, trimmed where they overlap what was delivered.
void TcpStreamReassembler::drain()
{
    while (!m_early.empty() && m_early.begin()->first <= m_offset) {
        auto node = m_early.extract(m_early.begin());
        const QByteArray &bytes = node.mapped();
        m_bufferedBytes -= bytes.size();
        const qint64 old = std::min<qint64>(m_offset - node.key(), bytes.size());
        m_retransmitted += old;
        if (old < bytes.size())
            deliverInOrder(QByteArrayView(bytes).sliced(old), 0);
    }
}

// Gives up on the bytes missing before the first early segment and delivers it.
void TcpStreamReassembler::skipHole()
{
    auto node = m_early.extract(m_early.begin());
    const QByteArray &bytes = node.mapped();
    m_bufferedBytes -= bytes.size();
    const qint64 gap = node.key() - m_offset;
    m_lost += gap;
    ++m_gaps;
    deliverInOrder(bytes, gap);
}

} // namespace mbscope
