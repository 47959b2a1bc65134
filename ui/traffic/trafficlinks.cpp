#include "trafficlinks.h"

#include "transport/linkurl.h"

namespace mbscope {

namespace {

// MBAP (MODBUS Messaging on TCP/IP V1.0b, 3.1.3): protocol id 0 and a length that counts the
// unit id and the PDU, the bytes after the six-byte header.
bool looksLikeMbap(QByteArrayView bytes)
{
    return bytes.size() >= 8 && bytes[2] == 0 && bytes[3] == 0
        && ((quint8(bytes[4]) << 8) | quint8(bytes[5])) == bytes.size() - 6;
}

} // namespace

void TrafficLinks::setName(quint16 link, const QString &url)
{
    if (link >= m_names.size()) {
        while (m_names.size() <= link)
            m_names.append(QString());
        m_framings.resize(std::size_t(link) + 1, Framing::Auto);
        m_delimited.resize(std::size_t(link) + 1, false);
    }
    m_names[link] = url;
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    m_framings[link] = parsed.url ? parsed.url->framing() : Framing::Auto;
    m_delimited[link] = parsed.url && parsed.url->delimited.enabled;
}

quint16 TrafficLinks::idOf(const QString &url)
{
    const qsizetype found = m_names.indexOf(url);
    if (found >= 0)
        return quint16(found);
    const auto id = quint16(m_names.size());
    setName(id, url);
    return id;
}

QString TrafficLinks::name(quint16 link) const
{
    return link < m_names.size() ? m_names.at(link) : QString();
}

Framing TrafficLinks::framing(quint16 link) const
{
    return link < m_framings.size() ? m_framings[link] : Framing::Auto;
}

FrameKeys TrafficLinks::keysOf(const TrafficEntry &entry) const
{
    if (entry.link < m_delimited.size() && m_delimited[entry.link])
        return {};
    Framing f = framing(entry.link);
    if (f == Framing::Auto)
        f = looksLikeMbap(entry.bytes) ? Framing::Tcp
            : (!entry.bytes.isEmpty() && entry.bytes[0] == ':') ? Framing::Ascii
                                                                 : Framing::Rtu;
    return ResponseMatcher::keysOf(entry.bytes, f);
}

std::size_t TrafficLinks::memoryBytes() const
{
    std::size_t bytes = std::size_t(m_names.capacity()) * sizeof(QString) + m_framings.capacity() * sizeof(Framing)
        + m_delimited.capacity() / 8;
    for (const QString &name : m_names)
        bytes += std::size_t(name.capacity()) * sizeof(QChar);
    return bytes;
}

} // namespace mbscope
