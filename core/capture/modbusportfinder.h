#pragma once

#include "protocol/framing.h"

#include <QtCore/QByteArrayView>
#include <QtCore/QString>

#include <unordered_map>
#include <vector>

namespace mbscope {

struct DecodedPacket;

// Modbus on ports nobody named: a capture's TCP segments and UDP datagrams on other ports are
// looked at for payloads that are whole Modbus frames, so that `analyze` can say where the Modbus
// is instead of printing nothing. A payload is MBAP when it is one or more frames whose headers
// have protocol id 0, a length of 2..254 that ends exactly at a frame or at the payload's end and
// a function code 01..7F or 81..FF (Messaging on TCP/IP V1.0b, 3.1.3); it is RTU when it is one
// frame of 4..256 bytes with a valid CRC (Serial Line V1.02, 2.5.1). A pair of ports counts when
// at least two of its payloads and at least half of them since the first look like Modbus; its
// lower port is taken as the server's (clients use ephemeral ports, RFC 6335 6). Memory stays
// bounded: at most kMaxFlows pairs of ports are remembered.
class ModbusPortFinder
{
public:
    struct Found {
        bool udp = false;
        quint16 port = 0;               // the server's
        Framing framing = Framing::Tcp; // Tcp or Udp (MBAP), or Rtu
        quint64 packets = 0;            // that look like Modbus
        // "Modbus/TCP on port 1502", "RTU over TCP on port 4001", "Modbus/UDP on port 1502"
        [[nodiscard]] QString description() const;
    };
    static constexpr std::size_t kMaxFlows = 4096;

    // A TCP or UDP packet on ports that are not Modbus ports.
    void add(const DecodedPacket &packet);
    // The server ports where Modbus was found, the most packets first.
    [[nodiscard]] std::vector<Found> found() const;

    [[nodiscard]] static bool isMbapPayload(QByteArrayView payload);
    [[nodiscard]] static bool isRtuPayload(QByteArrayView payload);

private:
    struct Tally {
        quint64 mbap = 0;
        quint64 rtu = 0;
        quint64 other = 0; // payloads since the first Modbus-looking one that are not
    };
    std::unordered_map<quint64, Tally> m_flows; // by transport and the two ports, lower first
};

} // namespace mbscope
