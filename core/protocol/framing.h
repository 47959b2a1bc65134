#pragma once

#include <QtCore/qglobal.h>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// How Modbus PDUs are wrapped on a link. RTU over TCP and RTU over UDP carry RTU frames,
// Modbus UDP carries MBAP frames, so the bytes alone never tell TCP from UDP.
enum class Framing : quint8 {
    Auto, // only as a request to detect it
    Rtu,  // unit, PDU, CRC-16 low byte first (MODBUS over Serial Line v1.02, 2.5.1)
    Ascii, // ':' unit PDU LRC in hex digits, CR LF (Serial Line v1.02, 2.5.2)
    Tcp,  // MBAP header + PDU (MODBUS Messaging on TCP/IP v1.0b, 3.1)
    Udp,  // MBAP header + PDU, one frame per datagram
    Pdu,  // a bare PDU: function code and data
};

enum class Direction : quint8 {
    Auto,     // only as a request to detect it
    Request,  // client (master) to server (slave)
    Response, // server to client
};

[[nodiscard]] QString framingName(Framing framing);   // "rtu", "ascii", "tcp", "udp", "pdu", "auto"
[[nodiscard]] QString directionName(Direction direction); // "request", "response", "auto"
[[nodiscard]] std::optional<Framing> framingFromName(QStringView name);
[[nodiscard]] std::optional<Direction> directionFromName(QStringView name);

} // namespace mbscope
