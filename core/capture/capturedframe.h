#pragma once

#include "capture/decodedpacket.h"
#include "protocol/framing.h"
#include "protocol/streamframe.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// One client/server pair seen in a capture: a TCP connection's two directions (or several
// connections on the same four-tuple, one after the other), or a UDP exchange.
struct CaptureConversation {
    quint32 id = 0; // 0, 1, 2... in the order first seen
    bool udp = false;
    IpAddress client;
    IpAddress server;
    quint16 clientPort = 0;
    quint16 serverPort = 0;
    Framing framing = Framing::Tcp; // Tcp (MBAP over TCP), Udp (MBAP over UDP) or Rtu
    quint64 requests = 0;   // frames from the client
    quint64 responses = 0;  // frames from the server
    // TCP: holes the capture has in each direction (lost packets), and the bytes never captured.
    quint64 requestGaps = 0;
    qint64 requestBytesLost = 0;
    quint64 responseGaps = 0;
    qint64 responseBytesLost = 0;
    bool joinedMidStream = false; // the capture began after the connection did
    // Journals only. A serial line (an rtu:// or ascii:// link) has no addresses: its port
    // ("/dev/ttyUSB0") names it, and client and server are unused. A network link's journal says
    // its client only in an endpoints note (journalendpoints.h), its server in the link's URL
    // (or the note): an end the journal does not give is not known (clientKnown, serverKnown
    // false; serverName then holds the URL's "host:port"), and its address is a stand-in that
    // only the packets of a pcap export carry.
    QString serialPort;
    QString serverName;
    bool clientKnown = true;
    bool serverKnown = true;

    [[nodiscard]] bool isSerial() const { return !serialPort.isEmpty(); }
    // "192.168.1.5:50123", "[::1]:50123"; empty when not known and on a serial line.
    [[nodiscard]] QString clientText() const;
    // "192.168.1.10:502", the serial port "/dev/ttyUSB0", or the URL's "plc.local:502".
    [[nodiscard]] QString serverText() const;
    // "tcp 192.168.1.5:50123 -> 192.168.1.10:502 (Modbus TCP)", "serial /dev/ttyUSB0 (Modbus RTU)",
    // "tcp (client not recorded) -> 192.168.1.10:502 (Modbus TCP)"
    [[nodiscard]] QString description() const;
};

// A Modbus frame cut out of a captured stream or datagram.
struct CapturedFrame {
    qint64 timeNs = 0;     // capture time of the packet that brought the frame's last byte
    quint64 packet = 0;    // that packet's number in the file (1-based)
    quint32 conversation = 0;
    Framing framing = Framing::Tcp;
    Direction direction = Direction::Request; // Request: client to server
    FrameStatus status = FrameStatus::Valid;
    // RTU answers only: bytes the framer skipped (a wrong CRC, cut short) offered as the answer
    // to a waiting request with their unit and function code, as the engine does; when no
    // request takes them they stay skipped bytes, not an unmatched answer.
    bool undelimited = false;
    QByteArray bytes;
};

} // namespace mbscope
