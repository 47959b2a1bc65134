#pragma once

#include "capture/capturepacket.h"
#include "capture/decodedpacket.h"

namespace mbscope {

// Takes a captured packet apart down to its TCP or UDP payload: the link layer (Ethernet with
// 802.1Q/802.1ad tags, Linux cooked v1 and v2, BSD and OpenBSD loopback, raw IP), IPv4 (header
// options, the total length cutting off Ethernet padding) and IPv6 (hop-by-hop, routing and
// destination options headers skipped), then TCP or UDP. Pure and allocation-free: the payload
// is a view into the packet.
class PacketDecoder
{
public:
    [[nodiscard]] static DecodedPacket decode(const CapturePacket &packet);
    // From the IP header on (version in the first nibble).
    [[nodiscard]] static DecodedPacket decodeIp(QByteArrayView ip, quint32 originalIpLength);
};

} // namespace mbscope
