#pragma once

#include "capture/decodedpacket.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>

namespace mbscope {

// Ethernet frames around payloads, for writing captures that Wireshark reads as if they had
// been on a wire: Ethernet II (locally administered MACs 02:00:00:00:00:01 for the client and
// :02 for the server), IPv4 (RFC 791, header checksum) or IPv6 (RFC 8200), then TCP (RFC 9293)
// or UDP (RFC 768) with the checksum over the pseudo-header (RFC 1071 ones' complement sum).
// Every checksum is correct, so tshark's checksum validation, when enabled, passes.
class PacketSynthesizer
{
public:
    struct Endpoints {
        IpAddress client;
        IpAddress server;
        quint16 clientPort = 0;
        quint16 serverPort = 0;
    };

    static constexpr quint8 kFin = 0x01;
    static constexpr quint8 kSyn = 0x02;
    static constexpr quint8 kPsh = 0x08;
    static constexpr quint8 kAck = 0x10;

    [[nodiscard]] static QByteArray tcp(const Endpoints &endpoints, bool toServer, quint32 sequence, quint32 acknowledgement,
                                        quint8 flags, QByteArrayView payload);
    [[nodiscard]] static QByteArray udp(const Endpoints &endpoints, bool toServer, QByteArrayView payload);

    // RFC 1071: the ones' complement of the ones' complement sum of 16-bit words, starting from
    // a partial sum (the pseudo-header's).
    [[nodiscard]] static quint16 internetChecksum(QByteArrayView bytes, quint32 partialSum = 0);

private:
    [[nodiscard]] static QByteArray frame(const Endpoints &endpoints, bool toServer, quint8 protocol, QByteArrayView transport,
                                          int checksumOffset);
};

} // namespace mbscope
