#pragma once

#include <QtCore/QCommandLineOption>
#include <QtCore/QString>

class QCommandLineParser;

namespace mbscope::app {

// A target given as mbpoll gives it: a host name or address ("192.168.1.10", "plc.local:5020")
// or a serial device ("/dev/ttyUSB0"), with the link's pieces in options of their own:
//   -m, --mode MODE       tcp (a host's default), udp, tls, rtu (a device's default), ascii;
//                         rtu and ascii to a host are RTU or ASCII frames over TCP (rtu-tcp://),
//                         and rtu-tcp, ascii-tcp, rtu-udp are taken as they are (modpoll's
//                         enc: rtu-tcp)
//   -p, --port N          network port (default 502, as mbpoll's); with a device, modpoll's
//                         parity words (-p none|even|odd) are the parity
//   -b, --baud N          serial: baud rate
//   -P, --parity P        serial: none, even, odd (or N, E, O)
//   -d, --data-bits N     serial: 7 or 8
//   -s, --stop-bits N     serial: 1 or 2
// compose() makes the URL LinkUrl reads ("tcp://192.168.1.10:502", "rtu:///dev/ttyUSB0?baud=19200");
// a piece the target's kind has no use for (a baud rate for a host) is an error, and so is any
// piece given with a whole URL (the URL says it: write it there).
class TargetPieces
{
public:
    TargetPieces();

    void addTo(QCommandLineParser &parser) const;
    // Whether any piece option is given.
    [[nodiscard]] bool anySet(const QCommandLineParser &parser) const;
    // The first piece option given, as typed for a message ("-p/--port"); empty when none.
    [[nodiscard]] QString firstSet(const QCommandLineParser &parser) const;
    // The URL of a bare target with the pieces; false with a message that names the option at
    // fault (no "mbscope COMMAND:" prefix).
    [[nodiscard]] bool compose(const QCommandLineParser &parser, const QString &target, QString &url, QString &error) const;

    // A target typed without a scheme: a host or a device, not a URL.
    [[nodiscard]] static bool isBare(const QString &target);

private:
    QCommandLineOption m_mode;
    QCommandLineOption m_port;
    QCommandLineOption m_baud;
    QCommandLineOption m_parity;
    QCommandLineOption m_dataBits;
    QCommandLineOption m_stopBits;
};

} // namespace mbscope::app
