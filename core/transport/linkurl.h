#pragma once

#include "protocol/delimitedframer.h"
#include "protocol/framing.h"
#include "rs485settings.h"

#include <QtCore/QString>
#include <QtCore/QStringView>

#include <chrono>
#include <optional>

namespace mbscope {

// What a URL is parsed for. Listen (the simulator's endpoints) also accepts port 0 (the OS
// chooses a free port) and an empty host (tcp://:502), which means 127.0.0.1: a server binds
// the loopback interface unless its URL names another one.
enum class LinkUse : quint8 {
    Connect,
    Listen,
};

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

// What a listening link (mode=listen) does with a connection that comes while one is in use
// (busy=...): Replace (the default) closes the one in use, fails what was in flight on it and
// uses the new one from the next request, so a device that dials again after a silent loss (a
// cellular unit's half-open connection) is back at once; Queue keeps the new one waiting (at
// most 8) until the one in use ends; Refuse closes the new one at once.
enum class BusyPolicy : quint8 {
    Replace,
    Queue,
    Refuse,
};

struct SerialSettings {
    QString device;     // /dev/ttyUSB0 (or a name such as COM3)
    int baud = 9600;
    char parity = 'E';  // 'N', 'E', 'O' (the serial-line spec's default is even, V1.02 2.5.1)
    int dataBits = 8;   // 5..8; RTU needs 8; ASCII defaults to 7 (Serial Line V1.02, 2.5.2)
    int stopBits = 1;   // 1 or 2
    int turnaroundUs = 0; // RS485: wait this long after sending before expecting the answer
    Rs485Settings rs485;  // RS-485 direction control by RTS (none by default)

    friend bool operator==(const SerialSettings &, const SerialSettings &) = default;
};

struct TlsSettings {
    QString certificate; // PEM file: our certificate (client or server)
    QString privateKey;  // PEM file (RSA or EC, without a passphrase)
    QString caCertificates; // PEM file: the peer's CA (empty: the system's CAs)

    friend bool operator==(const TlsSettings &, const TlsSettings &) = default;
};

// A parsed target URL. parse() never throws: it returns the URL or an error that names the part
// at fault and what was expected ("rtu:///dev/ttyUSB0?baud=96OO: baud '96OO' is not a number").
//
// Syntax: scheme://host[:port][?options] for network links (IPv6 addresses in brackets:
// tcp://[::1]:502), scheme://device[?options] for serial links (rtu:///dev/ttyUSB0: the device
// path follows the two slashes). Default ports: 502 for tcp and udp (Messaging on TCP/IP V1.0b,
// 4.1), 802 for tls (MODBUS/TCP Security, 5.1); rtu-tcp, ascii-tcp and rtu-udp need a port (serial
// device servers listen on ports of their own). Scheme and option names are case-insensitive.
//
// Options (unknown, repeated or misplaced options are errors, never ignored):
//   serial:  baud=9600  parity=N|E|O (or none|even|odd)  data=5..8  stop=1|2
//            turnaround=10ms (units ns, us, ms, s; a bare number is ms) or turnaround_us=10000
//            rts=up|down (RS-485: the RTS level while sending, switched by mbscope)
//            rts_before=DURATION  rts_after=DURATION (RTS at that level so long before the first
//            byte and after the last; need rts= or rs485=)  rs485=kernel (the driver switches
//            RTS, TIOCSRS485; rts= defaults to up; the delays in whole milliseconds)
//   tls:     cert=FILE  key=FILE (both or neither)  ca=FILE
//   network: connect_timeout=3000ms (bare number: ms; default 3000)
//   stream (tcp, rtu-tcp, ascii-tcp, tls):
//            mode=connect|listen  listen: a reverse connection. mbscope listens on host:port (an
//            address of this machine: 0.0.0.0 for every IPv4 interface) and, as master, uses the
//            connection the device opens (cellular units and gateways that dial out to a
//            server); the connect timeout bounds the wait for it. See TcpLink.
//            busy=replace|queue|refuse  (needs mode=listen) a second connection while one is in
//            use: see BusyPolicy. tls with mode=listen needs cert= and key= (mbscope is the TLS
//            server then).
//   any:     timeout=1000ms  the response timeout for requests on this link (the engine's
//            default when absent)
//            framing=delimited  start=HH  end=HH  checksum=none|sum|xor  display=text|hex
//            Bytes are two hex digits (an optional 0x is accepted): start=24 is 0x24 '$',
//            end=23 is 0x23 '#', start=05&end=04 are ENQ and EOT. end defaults to 0A (LF); no
//            start byte by default. See DelimitedFramer.
// Values may be percent-encoded (%20, %26 for '&'); toString() encodes what needs it.
class LinkUrl
{
public:
    struct Result;

    [[nodiscard]] static Result parse(QStringView text);
    [[nodiscard]] static Result parse(QStringView text, LinkUse use);
    // "tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, rtu, ascii, tls"
    [[nodiscard]] static QString knownSchemes();
    [[nodiscard]] static QString schemeName(LinkKind kind); // "rtu-tcp"

    LinkKind kind = LinkKind::Tcp;
    QString host;   // network links; an IPv6 address without brackets
    quint16 port = 502;
    SerialSettings serial;
    TlsSettings tls;
    DelimitedFraming delimited;
    int connectTimeoutMs = 3000;
    int responseTimeoutMs = -1; // -1: not given (the engine's default applies)
    bool listen = false;        // mode=listen: wait for the device to connect to host:port
    BusyPolicy busy = BusyPolicy::Replace;
    // The device's pace (docs/guide/connecting.md, "A device that needs time"), which every engine
    // on the link holds at least (EngineOptions::withPaceOf): gap= no request sooner than this after
    // the one before it, warmup= none sooner than this after the link opens, close=each a new
    // connection for each request (a device that hangs up after each answer). Zero, false: none.
    std::chrono::milliseconds gap{0};
    std::chrono::milliseconds warmUp{0};
    bool closeAfterAnswer = false;
    [[nodiscard]] bool hasPace() const { return gap.count() > 0 || warmUp.count() > 0 || closeAfterAnswer; }

    [[nodiscard]] bool isSerial() const { return kind == LinkKind::Rtu || kind == LinkKind::Ascii; }
    [[nodiscard]] bool isDatagram() const { return kind == LinkKind::Udp || kind == LinkKind::RtuUdp; }
    // "replace", "queue", "refuse"
    [[nodiscard]] static QString busyPolicyName(BusyPolicy policy);
    // The Modbus framing the link carries (Rtu for rtu-tcp, rtu-udp and rtu://; Tcp for tcp and tls;
    // Udp for udp). With delimited.enabled the link carries delimited frames instead and this is
    // only what the scheme would have carried.
    [[nodiscard]] Framing framing() const;
    // Canonical text, parseable again: "rtu:///dev/ttyUSB0?baud=9600&parity=E&data=8&stop=1".
    // Network links always show the port; options at their defaults are left out, except the
    // serial settings, which are always written in full.
    [[nodiscard]] QString toString() const;
    // Where the link goes, for messages: "127.0.0.1:502", "[::1]:502", "/dev/ttyUSB0".
    [[nodiscard]] QString address() const;

    friend bool operator==(const LinkUrl &, const LinkUrl &) = default;
};

struct LinkUrl::Result {
    std::optional<LinkUrl> url;
    QString error; // empty when url is set
};

} // namespace mbscope
