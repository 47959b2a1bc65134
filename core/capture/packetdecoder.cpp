#include "packetdecoder.h"

#include <QtCore/QtEndian>

namespace mbscope {

namespace {

constexpr quint16 kEtherIpv4 = 0x0800;
constexpr quint16 kEtherIpv6 = 0x86dd;
constexpr quint16 kEtherVlan = 0x8100;
constexpr quint16 kEtherQinQ = 0x88a8;
constexpr quint8 kIpTcp = 6;
constexpr quint8 kIpUdp = 17;

const uchar *bytesOf(QByteArrayView v)
{
    return reinterpret_cast<const uchar *>(v.data());
}

DecodedPacket malformed(const char *problem)
{
    DecodedPacket p;
    p.outcome = DecodedPacket::Outcome::Malformed;
    p.problem = problem;
    return p;
}

DecodedPacket withOutcome(DecodedPacket::Outcome outcome)
{
    DecodedPacket p;
    p.outcome = outcome;
    return p;
}

// An EtherType (or the SLL protocol field) to the IP bytes after it.
DecodedPacket byEtherType(quint16 type, QByteArrayView rest, quint32 originalRest)
{
    if (type == kEtherIpv4 || type == kEtherIpv6)
        return PacketDecoder::decodeIp(rest, originalRest);
    return withOutcome(DecodedPacket::Outcome::NotIp);
}

// TCP or UDP from the transport header on; wireLength is its length on the wire.
void decodeTransport(DecodedPacket &p, quint8 protocol, QByteArrayView t, quint32 wireLength)
{
    const uchar *b = bytesOf(t);
    if (protocol == kIpTcp) {
        if (t.size() < 20) {
            p = malformed(wireLength < 20 ? "TCP header shorter than 20 bytes" : "TCP header cut by the snap length");
            return;
        }
        const quint32 headerLength = quint32(b[12] >> 4) * 4;
        if (headerLength < 20 || headerLength > wireLength) {
            p = malformed("TCP data offset outside the segment");
            return;
        }
        p.outcome = DecodedPacket::Outcome::Tcp;
        p.sourcePort = qFromBigEndian<quint16>(b);
        p.destinationPort = qFromBigEndian<quint16>(b + 2);
        p.sequence = qFromBigEndian<quint32>(b + 4);
        p.acknowledgement = qFromBigEndian<quint32>(b + 8);
        p.tcpFlags = b[13];
        p.payloadLength = wireLength - headerLength;
        const qsizetype present = std::max<qsizetype>(0, std::min<qsizetype>(t.size(), wireLength) - headerLength);
        p.payload = t.sliced(std::min<qsizetype>(headerLength, t.size()), present);
        p.truncated = present < qsizetype(p.payloadLength);
        return;
    }
    if (protocol == kIpUdp) {
        if (t.size() < 8) {
            p = malformed(wireLength < 8 ? "UDP header shorter than 8 bytes" : "UDP header cut by the snap length");
            return;
        }
        const quint16 udpLength = qFromBigEndian<quint16>(b + 4);
        if (udpLength < 8 || udpLength > wireLength) {
            p = malformed("UDP length outside the IP packet");
            return;
        }
        p.outcome = DecodedPacket::Outcome::Udp;
        p.sourcePort = qFromBigEndian<quint16>(b);
        p.destinationPort = qFromBigEndian<quint16>(b + 2);
        p.payloadLength = udpLength - 8u;
        const qsizetype present = std::min<qsizetype>(t.size(), udpLength) - 8;
        p.payload = t.sliced(8, present);
        p.truncated = present < qsizetype(p.payloadLength);
        return;
    }
    p.outcome = DecodedPacket::Outcome::OtherProtocol;
}

} // namespace

QString IpAddress::toString() const
{
    if (!v6)
        return QStringLiteral("%1.%2.%3.%4").arg(bytes[0]).arg(bytes[1]).arg(bytes[2]).arg(bytes[3]);
    // RFC 5952: lower-case hex groups, the longest run of two or more zero groups as "::".
    quint16 groups[8];
    for (int i = 0; i < 8; ++i)
        groups[i] = quint16(bytes[std::size_t(2 * i)] << 8 | bytes[std::size_t(2 * i + 1)]);
    int bestStart = -1;
    int bestLength = 1;
    for (int i = 0; i < 8;) {
        int j = i;
        while (j < 8 && groups[j] == 0)
            ++j;
        if (j - i > bestLength) {
            bestStart = i;
            bestLength = j - i;
        }
        i = j == i ? i + 1 : j;
    }
    QString text;
    for (int i = 0; i < 8; ++i) {
        if (i == bestStart) {
            text += QStringLiteral("::");
            i += bestLength - 1;
            continue;
        }
        if (!text.isEmpty() && !text.endsWith(QLatin1Char(':')))
            text += QLatin1Char(':');
        text += QString::number(groups[i], 16);
    }
    return text;
}

DecodedPacket PacketDecoder::decode(const CapturePacket &packet)
{
    const QByteArrayView d = packet.data;
    const uchar *b = bytesOf(d);
    const quint32 original = std::max<quint32>(packet.originalLength, quint32(d.size()));
    switch (LinkType(packet.linkType)) {
    case LinkType::Ethernet: {
        qsizetype at = 12;
        if (d.size() < 14)
            return malformed("Ethernet header cut short");
        quint16 type = qFromBigEndian<quint16>(b + at);
        // 802.1Q and 802.1ad tags: 4 bytes each before the real EtherType.
        while ((type == kEtherVlan || type == kEtherQinQ) && d.size() >= at + 6) {
            at += 4;
            type = qFromBigEndian<quint16>(b + at);
        }
        at += 2;
        return byEtherType(type, d.sliced(at), original - quint32(at));
    }
    case LinkType::LinuxSll:
        if (d.size() < 16)
            return malformed("Linux cooked (SLL) header cut short");
        return byEtherType(qFromBigEndian<quint16>(b + 14), d.sliced(16), original - 16);
    case LinkType::LinuxSll2:
        if (d.size() < 20)
            return malformed("Linux cooked v2 (SLL2) header cut short");
        return byEtherType(qFromBigEndian<quint16>(b), d.sliced(20), original - 20);
    case LinkType::Null:
    case LinkType::Loop: {
        if (d.size() < 4)
            return malformed("loopback header cut short");
        // The address family is in the capturing host's byte order for Null: either order is
        // tried. 2 is AF_INET everywhere; 24, 28 and 30 are AF_INET6 on the BSDs and macOS.
        const quint32 le = qFromLittleEndian<quint32>(b);
        const quint32 be = qFromBigEndian<quint32>(b);
        const quint32 family = LinkType(packet.linkType) == LinkType::Loop ? be : (le < 256 ? le : be);
        if (family != 2 && family != 10 && family != 24 && family != 28 && family != 30)
            return withOutcome(DecodedPacket::Outcome::NotIp);
        return decodeIp(d.sliced(4), original - 4);
    }
    case LinkType::Raw:
    case LinkType::Ipv4:
    case LinkType::Ipv6:
        return decodeIp(d, original);
    }
    return withOutcome(DecodedPacket::Outcome::UnknownLinkType);
}

DecodedPacket PacketDecoder::decodeIp(QByteArrayView ip, quint32 originalIpLength)
{
    DecodedPacket p;
    if (ip.isEmpty())
        return malformed("IP header missing");
    const uchar *b = bytesOf(ip);
    const int version = b[0] >> 4;
    if (version == 4) {
        if (ip.size() < 20)
            return malformed("IPv4 header cut short");
        const quint32 headerLength = quint32(b[0] & 0x0f) * 4;
        const quint32 totalLength = qFromBigEndian<quint16>(b + 2);
        if (headerLength < 20)
            return malformed("IPv4 header length below 20");
        // TCP segmentation offload: a capture on the sending host may show a total length of 0
        // for a segment larger than the MTU; the captured length is the best there is then.
        const quint32 wire = totalLength == 0 ? originalIpLength : totalLength;
        if (wire < headerLength || qsizetype(headerLength) > ip.size())
            return malformed("IPv4 total length shorter than its header");
        const quint16 fragment = qFromBigEndian<quint16>(b + 6);
        if ((fragment & 0x2000) || (fragment & 0x1fff))
            return withOutcome(DecodedPacket::Outcome::Fragment);
        p.source.bytes = {};
        std::copy(b + 12, b + 16, p.source.bytes.begin());
        std::copy(b + 16, b + 20, p.destination.bytes.begin());
        const QByteArrayView transport = ip.sliced(headerLength, std::min<qsizetype>(ip.size(), wire) - headerLength);
        decodeTransport(p, b[9], transport, wire - headerLength);
        return p;
    }
    if (version == 6) {
        if (ip.size() < 40)
            return malformed("IPv6 header cut short");
        const quint32 payloadLength = qFromBigEndian<quint16>(b + 4);
        const quint32 wire = payloadLength == 0 ? originalIpLength - 40 : payloadLength; // 0: a jumbogram
        p.source.v6 = p.destination.v6 = true;
        std::copy(b + 8, b + 24, p.source.bytes.begin());
        std::copy(b + 24, b + 40, p.destination.bytes.begin());
        quint8 next = b[6];
        qsizetype at = 40;
        const qsizetype end = std::min<qsizetype>(ip.size(), 40 + qsizetype(wire));
        // Extension headers: hop-by-hop (0), routing (43), destination options (60) are
        // skipped; a fragment header (44) means a fragment.
        while (next == 0 || next == 43 || next == 60 || next == 44) {
            if (next == 44)
                return withOutcome(DecodedPacket::Outcome::Fragment);
            if (at + 2 > end)
                return malformed("IPv6 extension header cut short");
            const qsizetype length = (qsizetype(b[at + 1]) + 1) * 8;
            next = b[at];
            at += length;
        }
        if (at > 40 + qsizetype(wire))
            return malformed("IPv6 extension headers longer than the packet");
        const QByteArrayView transport = ip.sliced(std::min(at, end), std::max<qsizetype>(0, end - at));
        decodeTransport(p, next, transport, quint32(40 + qsizetype(wire) - at));
        return p;
    }
    return withOutcome(DecodedPacket::Outcome::NotIp);
}

} // namespace mbscope
