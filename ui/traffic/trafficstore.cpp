#include "trafficstore.h"

#include "protocol/hexformat.h"
#include "transport/linkurl.h"

#include <algorithm>
#include <limits>

namespace mbscope {

static_assert(sizeof(TrafficStore::Row) == 48, "a traffic row is 48 bytes: keep it compact");

namespace {

int asciiByte(QByteArrayView bytes, qsizetype at)
{
    if (at + 1 >= bytes.size())
        return -1;
    const int hi = hexDigitValue(char16_t(quint8(bytes[at])));
    const int lo = hexDigitValue(char16_t(quint8(bytes[at + 1])));
    return hi < 0 || lo < 0 ? -1 : hi * 16 + lo;
}

// MBAP (MODBUS Messaging on TCP/IP V1.0b, 3.1.3): protocol id 0 and a length that counts the
// unit id and the PDU, the bytes after the six-byte header.
bool looksLikeMbap(QByteArrayView bytes)
{
    return bytes.size() >= 8 && bytes[2] == 0 && bytes[3] == 0
        && ((quint8(bytes[4]) << 8) | quint8(bytes[5])) == bytes.size() - 6;
}

} // namespace

void TrafficStore::setLinkName(quint16 link, const QString &url)
{
    if (link >= m_linkNames.size()) {
        while (m_linkNames.size() <= link)
            m_linkNames.append(QString());
        m_linkFramings.resize(size_t(link) + 1, Framing::Auto);
        m_linkDelimited.resize(size_t(link) + 1, false);
    }
    m_linkNames[link] = url;
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    m_linkFramings[link] = parsed.url ? parsed.url->framing() : Framing::Auto;
    m_linkDelimited[link] = parsed.url && parsed.url->delimited.enabled;
}

quint16 TrafficStore::linkId(const QString &url)
{
    const qsizetype found = m_linkNames.indexOf(url);
    if (found >= 0)
        return quint16(found);
    const auto id = quint16(m_linkNames.size());
    setLinkName(id, url);
    return id;
}

QString TrafficStore::linkName(quint16 link) const
{
    return link < m_linkNames.size() ? m_linkNames.at(link) : QString();
}

Framing TrafficStore::linkFraming(quint16 link) const
{
    return link < m_linkFramings.size() ? m_linkFramings[link] : Framing::Auto;
}

TrafficStore::Row TrafficStore::keysOf(QByteArrayView bytes, Framing framing)
{
    Row keys;
    if (framing == Framing::Auto)
        framing = looksLikeMbap(bytes) ? Framing::Tcp : (!bytes.isEmpty() && bytes[0] == ':') ? Framing::Ascii : Framing::Rtu;
    int unit = -1;
    int function = -1;
    switch (framing) {
    case Framing::Rtu:
        unit = bytes.size() >= 1 ? quint8(bytes[0]) : -1;
        function = bytes.size() >= 2 ? quint8(bytes[1]) : -1;
        break;
    case Framing::Tcp:
    case Framing::Udp:
        unit = bytes.size() >= 7 ? quint8(bytes[6]) : -1;
        function = bytes.size() >= 8 ? quint8(bytes[7]) : -1;
        break;
    case Framing::Ascii: // ':' then the unit and the function as two hex digits each
        unit = asciiByte(bytes, 1);
        function = asciiByte(bytes, 3);
        break;
    case Framing::Pdu:
        function = bytes.size() >= 1 ? quint8(bytes[0]) : -1;
        break;
    case Framing::Auto:
        break;
    }
    if (unit >= 0) {
        keys.unit = quint8(unit);
        keys.flags |= HasUnit;
    }
    if (function >= 0) {
        keys.function = quint8(function);
        keys.flags |= HasFunction;
    }
    return keys;
}

quint64 TrafficStore::storeBytes(QByteArrayView bytes)
{
    if (bytes.isEmpty())
        return 0;
    if (m_chunks.empty() || m_chunks.back().capacity() - m_chunks.back().size() < bytes.size()) {
        QByteArray chunk;
        chunk.reserve(std::max(kChunkBytes, bytes.size()));
        m_chunks.push_back(std::move(chunk));
    }
    QByteArray &chunk = m_chunks.back();
    const quint64 offset = quint64(chunk.size());
    chunk.append(bytes);
    return (quint64(m_chunks.size() - 1) + m_chunkBase) << 32 | offset;
}

QByteArrayView TrafficStore::bytes(qsizetype index) const
{
    const Row &r = row(index);
    if (r.length == 0)
        return {};
    const QByteArray &chunk = m_chunks[size_t((r.byteOffset >> 32) - m_chunkBase)];
    return QByteArrayView(chunk.constData() + (r.byteOffset & 0xFFFFFFFFu), r.length);
}

void TrafficStore::append(qint64 tNs, TrafficDirection direction, quint16 link, TrafficVerdict verdict,
                          quint64 transactionId, QByteArrayView bytes, qint64 latencyNs)
{
    const bool delimited = link < m_linkDelimited.size() && m_linkDelimited[link];
    // Skipped bytes are not a frame: their first bytes name no unit or function.
    Row r = verdict == TrafficVerdict::Garbage || delimited ? Row{} : keysOf(bytes, linkFraming(link));
    r.tNs = tNs;
    r.transactionId = transactionId;
    r.byteOffset = storeBytes(bytes);
    r.length = quint32(bytes.size());
    r.link = link;
    r.direction = direction;
    r.verdict = verdict;
    if (latencyNs >= 0)
        r.latencyUs = qint32(std::min<qint64>(latencyNs / 1000, std::numeric_limits<qint32>::max()));
    m_rows.push_back(r);
    if (direction == TrafficDirection::In && transactionId != 0)
        pair(size() - 1);
}

// An answer belongs to the latest request of its transaction (a retry's bytes were the last
// written). The request points on to its first answer that has bytes.
void TrafficStore::pair(qsizetype index)
{
    Row &answer = m_rows[size_t(index)];
    const qsizetype stop = std::max<qsizetype>(0, index - kPairWindow);
    for (qsizetype i = index - 1; i >= stop; --i) {
        Row &request = m_rows[size_t(i)];
        if (request.direction != TrafficDirection::Out || request.transactionId != answer.transactionId)
            continue;
        answer.pairDelta = quint32(index - i);
        if (answer.latencyUs < 0 && answer.length > 0)
            answer.latencyUs = qint32(std::clamp<qint64>((answer.tNs - request.tNs) / 1000, 0, std::numeric_limits<qint32>::max()));
        const bool pairedWithBytes = request.pairDelta != 0 && m_rows[size_t(i + request.pairDelta)].length > 0;
        if (request.pairDelta == 0 || (!pairedWithBytes && answer.length > 0))
            request.pairDelta = quint32(index - i);
        return;
    }
}

qsizetype TrafficStore::pairedRow(qsizetype index) const
{
    const Row &r = row(index);
    if (r.pairDelta == 0)
        return -1;
    const qsizetype other = r.direction == TrafficDirection::In ? index - qsizetype(r.pairDelta) : index + qsizetype(r.pairDelta);
    return other >= 0 && other < size() ? other : -1;
}

qint64 TrafficStore::latencyNs(qsizetype index) const
{
    const qint32 us = row(index).latencyUs;
    return us < 0 ? -1 : qint64(us) * 1000;
}

void TrafficStore::clear()
{
    std::vector<Row>().swap(m_rows);
    m_chunks.clear();
    m_chunkBase = 0;
}

void TrafficStore::removeFront(qsizetype count)
{
    count = std::clamp<qsizetype>(count, 0, size());
    if (count == 0)
        return;
    m_rows.erase(m_rows.begin(), m_rows.begin() + count);
    // Chunks are filled in row order: those before the first kept row's chunk hold only dropped
    // bytes. A kept row without bytes points nowhere, so it does not hold a chunk.
    quint64 keepFrom = m_chunkBase + m_chunks.size();
    for (const Row &r : m_rows) {
        if (r.length > 0) {
            keepFrom = r.byteOffset >> 32;
            break;
        }
    }
    const auto drop = qsizetype(keepFrom - m_chunkBase);
    m_chunks.erase(m_chunks.begin(), m_chunks.begin() + std::min<qsizetype>(drop, qsizetype(m_chunks.size())));
    m_chunkBase = keepFrom;
}

std::size_t TrafficStore::memoryBytes() const
{
    std::size_t bytes = m_rows.capacity() * sizeof(Row) + m_chunks.capacity() * sizeof(QByteArray);
    for (const QByteArray &chunk : m_chunks)
        bytes += std::size_t(chunk.capacity());
    for (const QString &name : m_linkNames)
        bytes += std::size_t(name.capacity()) * sizeof(QChar);
    return bytes + m_linkFramings.capacity() + m_linkDelimited.capacity() / 8;
}

} // namespace mbscope
