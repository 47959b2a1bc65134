#include "packetsynthesizer.h"

#include <QtCore/QtEndian>

namespace mbscope {

namespace {

constexpr quint8 kProtocolTcp = 6;
constexpr quint8 kProtocolUdp = 17;

void put16(QByteArray &b, qsizetype at, quint16 v)
{
    qToBigEndian<quint16>(v, b.data() + at);
}

void put32(QByteArray &b, qsizetype at, quint32 v)
{
    qToBigEndian<quint32>(v, b.data() + at);
}

quint32 sumWords(QByteArrayView bytes, quint32 sum)
{
    const auto *p = reinterpret_cast<const quint8 *>(bytes.data());
    const qsizetype n = bytes.size();
    for (qsizetype i = 0; i + 1 < n; i += 2)
        sum += quint32(p[i] << 8 | p[i + 1]);
    if (n % 2)
        sum += quint32(p[n - 1] << 8);
    return sum;
}

} // namespace

quint16 PacketSynthesizer::internetChecksum(QByteArrayView bytes, quint32 partialSum)
{
    quint64 sum = sumWords(bytes, 0) + quint64(partialSum);
    while (sum >> 16)
        sum = (sum & 0xffff) + (sum >> 16);
    return quint16(~sum & 0xffff);
}

QByteArray PacketSynthesizer::frame(const Endpoints &e, bool toServer, quint8 protocol, QByteArrayView transport, int checksumOffset)
{
    const IpAddress &source = toServer ? e.client : e.server;
    const IpAddress &destination = toServer ? e.server : e.client;
    const bool v6 = e.client.v6 || e.server.v6;
    const qsizetype ipHeader = v6 ? 40 : 20;
    QByteArray out(14 + ipHeader + transport.size(), '\0');
    // Ethernet II
    const char clientMac[6] = {0x02, 0, 0, 0, 0, 0x01};
    const char serverMac[6] = {0x02, 0, 0, 0, 0, 0x02};
    std::copy(toServer ? serverMac : clientMac, (toServer ? serverMac : clientMac) + 6, out.data());
    std::copy(toServer ? clientMac : serverMac, (toServer ? clientMac : serverMac) + 6, out.data() + 6);
    put16(out, 12, v6 ? 0x86dd : 0x0800);
    const qsizetype ip = 14;
    quint32 pseudo = 0;
    if (v6) {
        out[ip] = char(0x60);
        put16(out, ip + 4, quint16(transport.size()));
        out[ip + 6] = char(protocol);
        out[ip + 7] = char(64); // hop limit
        std::copy(source.bytes.begin(), source.bytes.end(), out.data() + ip + 8);
        std::copy(destination.bytes.begin(), destination.bytes.end(), out.data() + ip + 24);
        pseudo = sumWords(QByteArrayView(out).sliced(ip + 8, 32), 0) + quint32(transport.size()) + protocol;
    } else {
        out[ip] = char(0x45);
        put16(out, ip + 2, quint16(20 + transport.size()));
        put16(out, ip + 6, 0x4000); // don't fragment
        out[ip + 8] = char(64);     // time to live
        out[ip + 9] = char(protocol);
        std::copy(source.bytes.begin(), source.bytes.begin() + 4, out.data() + ip + 12);
        std::copy(destination.bytes.begin(), destination.bytes.begin() + 4, out.data() + ip + 16);
        put16(out, ip + 10, internetChecksum(QByteArrayView(out).sliced(ip, 20)));
        pseudo = sumWords(QByteArrayView(out).sliced(ip + 12, 8), 0) + quint32(transport.size()) + protocol;
    }
    const qsizetype t = ip + ipHeader;
    std::copy(transport.begin(), transport.end(), out.data() + t);
    quint16 checksum = internetChecksum(QByteArrayView(out).sliced(t), pseudo);
    if (protocol == kProtocolUdp && checksum == 0)
        checksum = 0xffff; // RFC 768: a computed 0 is sent as all ones (0 means "no checksum")
    put16(out, t + checksumOffset, checksum);
    return out;
}

QByteArray PacketSynthesizer::tcp(const Endpoints &e, bool toServer, quint32 sequence, quint32 acknowledgement, quint8 flags,
                                  QByteArrayView payload)
{
    QByteArray segment(20 + payload.size(), '\0');
    put16(segment, 0, toServer ? e.clientPort : e.serverPort);
    put16(segment, 2, toServer ? e.serverPort : e.clientPort);
    put32(segment, 4, sequence);
    put32(segment, 8, (flags & kAck) ? acknowledgement : 0);
    segment[12] = char(5 << 4); // 20-byte header, no options
    segment[13] = char(flags);
    put16(segment, 14, 65535); // window
    std::copy(payload.begin(), payload.end(), segment.data() + 20);
    return frame(e, toServer, kProtocolTcp, segment, 16);
}

QByteArray PacketSynthesizer::udp(const Endpoints &e, bool toServer, QByteArrayView payload)
{
    QByteArray datagram(8 + payload.size(), '\0');
    put16(datagram, 0, toServer ? e.clientPort : e.serverPort);
    put16(datagram, 2, toServer ? e.serverPort : e.clientPort);
    put16(datagram, 4, quint16(8 + payload.size()));
    std::copy(payload.begin(), payload.end(), datagram.data() + 8);
    return frame(e, toServer, kProtocolUdp, datagram, 6);
}

} // namespace mbscope
