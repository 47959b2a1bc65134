#pragma once

#include <QtCore/QByteArrayView>
#include <QtCore/QtGlobal>

namespace mbscope {

// Link-layer header types of pcap and pcapng (tcpdump.org/linktypes.html): the ones whose
// packets mbscope takes apart. Others are counted and skipped.
enum class LinkType : quint32 {
    Null = 0,         // BSD loopback: 4-byte address family in the writer's byte order
    Ethernet = 1,     // tshark -i lo on Linux writes this
    Raw = 101,        // a bare IPv4 or IPv6 packet
    Loop = 108,       // OpenBSD loopback: 4-byte address family, network byte order
    LinuxSll = 113,   // Linux cooked capture v1 (tcpdump -i any)
    Ipv4 = 228,
    Ipv6 = 229,
    LinuxSll2 = 276,  // Linux cooked capture v2 (tcpdump -i any since libpcap 1.10)
};

// One packet as a capture file holds it. The bytes are a view into the reader's buffer: valid
// only during the callback that receives it.
struct CapturePacket {
    quint64 number = 0;     // 1 for the file's first packet, as Wireshark numbers them
    qint64 fileOffset = 0;  // where the packet's record (pcap) or block (pcapng) starts
    qint64 timeNs = 0;      // capture time, ns since 1970-01-01 UTC
    quint32 linkType = 0;   // LinkType value (other values are possible)
    quint32 originalLength = 0; // the packet's length on the wire; more than data.size() when cut by the snap length
    QByteArrayView data;
};

} // namespace mbscope
