#pragma once

#include <QtCore/QByteArrayView>
#include <QtCore/QString>

#include <array>

namespace mbscope {

// An IP address as it came in a packet: 4 bytes for IPv4 (the rest zero), 16 for IPv6.
struct IpAddress {
    std::array<quint8, 16> bytes{};
    bool v6 = false;

    [[nodiscard]] QString toString() const; // "192.168.1.10", "::1"
    friend bool operator==(const IpAddress &, const IpAddress &) = default;
};

// What PacketDecoder found in one captured packet: the TCP segment or UDP datagram it carries,
// or why it carries none mbscope can use.
struct DecodedPacket {
    enum class Outcome : quint8 {
        Tcp,
        Udp,
        NotIp,          // ARP, LLDP, another link type...: not counted as a problem
        OtherProtocol,  // IP, but neither TCP nor UDP (ICMP...)
        Fragment,       // an IP fragment: fragments are not reassembled
        Malformed,      // headers that contradict themselves or the packet's length (problem says how)
        UnknownLinkType,
    };
    Outcome outcome = Outcome::NotIp;
    IpAddress source;
    IpAddress destination;
    quint16 sourcePort = 0;
    quint16 destinationPort = 0;
    quint32 sequence = 0;  // TCP
    quint32 acknowledgement = 0; // TCP, meaningful with the ACK flag: the peer's next byte expected
    quint8 tcpFlags = 0;   // TCP: FIN 0x01, SYN 0x02, RST 0x04, PSH 0x08, ACK 0x10
    // The transport payload present in the capture. truncated: the packet was cut by the snap
    // length before its payload ended, so payload holds only the first bytes.
    QByteArrayView payload;
    quint32 payloadLength = 0; // on the wire (from the IP and TCP or UDP headers)
    bool truncated = false;
    const char *problem = nullptr; // Malformed: what is wrong, e.g. "IPv4 header length below 20"

    static constexpr quint8 kFin = 0x01;
    static constexpr quint8 kSyn = 0x02;
    static constexpr quint8 kRst = 0x04;
    static constexpr quint8 kAck = 0x10;
};

} // namespace mbscope
