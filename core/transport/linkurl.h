#pragma once

#include "protocol/framing.h"

#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>

namespace mbscope {

// Which link a target URL names. The framing on the wire follows from it (LinkUrl::framing).
enum class LinkKind : quint8 {
    Tcp,      // tcp://host:502                 MBAP over TCP
    RtuTcp,   // rtu-tcp://host:4001            RTU frames over a TCP stream (serial device servers)
    AsciiTcp, // ascii-tcp://host:port          ASCII frames over a TCP stream
    Udp,      // udp://host:502                 MBAP, one frame per datagram
    RtuUdp,   // rtu-udp://host:port            RTU frames, one per datagram
    Rtu,      // rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1
    Ascii,    // ascii:///dev/ttyUSB0?...
    Tls,      // tls://host:802?cert=...&key=...&ca=...  (MODBUS/TCP Security, mutual TLS)
};

// Checksum after the end byte of a delimited frame (?framing=delimited&checksum=...).
enum class DelimitedChecksum : quint8 { None, Sum, Xor };

// A non-Modbus framing on any stream or serial link: frames run from a start byte to an end byte,
// optionally followed by one checksum byte (LG Master-K: ENQ ... EOT + BCC; home-made ASCII
// protocols: '$' ... '#').
struct DelimitedFraming {
    bool enabled = false;
    int startByte = -1; // -1: no start byte, frames run from the previous end
    int endByte = 0x0A;
    DelimitedChecksum checksum = DelimitedChecksum::None;
    bool textDisplay = true; // show frames as text (true) or hex
};

struct SerialSettings {
    QString device;     // /dev/ttyUSB0
    int baud = 9600;
    char parity = 'E';  // 'N', 'E', 'O' (the serial-line spec's default is even)
    int dataBits = 8;
    int stopBits = 1;
    int turnaroundUs = 0; // RS485: wait this long after sending before expecting the answer
};

struct TlsSettings {
    QString certificate; // PEM file: our certificate (client or server)
    QString privateKey;  // PEM file
    QString caCertificates; // PEM file: the peer's CA
};

// A parsed target URL. parse() never throws: it returns the URL or an error that names the part
// at fault and what was expected ("rtu:///dev/ttyUSB0?baud=96OO: baud '96OO' is not a number").
class LinkUrl
{
public:
    struct Result;

    [[nodiscard]] static Result parse(QStringView text);

    LinkKind kind = LinkKind::Tcp;
    QString host;   // network links
    quint16 port = 502;
    SerialSettings serial;
    TlsSettings tls;
    DelimitedFraming delimited;
    int connectTimeoutMs = 3000;

    [[nodiscard]] bool isSerial() const { return kind == LinkKind::Rtu || kind == LinkKind::Ascii; }
    [[nodiscard]] bool isDatagram() const { return kind == LinkKind::Udp || kind == LinkKind::RtuUdp; }
    // The Modbus framing the link carries (Rtu for rtu-tcp, rtu-udp and rtu://; Tcp for tcp and tls).
    [[nodiscard]] Framing framing() const;
    // Canonical text, parseable again: "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1".
    [[nodiscard]] QString toString() const;
};

struct LinkUrl::Result {
    std::optional<LinkUrl> url;
    QString error; // empty when url is set
};

} // namespace mbscope
