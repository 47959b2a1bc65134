#include "common/targetpieces.h"

#include "common/integeroption.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QStringList>

namespace mbscope::app {

namespace {

// mbpoll's default port (and Modbus/TCP's, Messaging on TCP/IP V1.0b, 4.1).
constexpr int kDefaultPort = 502;

QString both(const QCommandLineOption &option)
{
    const QStringList names = option.names();
    return names.size() > 1 ? QStringLiteral("-%1/--%2").arg(names.constFirst(), names.constLast())
                            : QStringLiteral("--") + names.constFirst();
}

} // namespace

TargetPieces::TargetPieces()
    : m_mode(QStringList{QStringLiteral("m"), QStringLiteral("mode")},
             QStringLiteral("How to reach a target given as a host or a device (mbpoll's -m): tcp (a host's default), "
                            "udp, tls, rtu (a device's default) or ascii; rtu or ascii to a host sends RTU or ASCII "
                            "frames over TCP (rtu-tcp://), as serial device servers take them (modpoll's enc too)."),
             QStringLiteral("mode"))
    , m_port(QStringList{QStringLiteral("p"), QStringLiteral("port")},
             QStringLiteral("The port of a target given as a host (default 502, as mbpoll's -p); to a serial device, "
                            "modpoll's -p none, even or odd is the parity."),
             QStringLiteral("port"))
    , m_baud(QStringList{QStringLiteral("b"), QStringLiteral("baud")},
             QStringLiteral("The baud rate of a target given as a serial device (default 9600: mbpoll's is 19200)."),
             QStringLiteral("rate"))
    , m_parity(QStringList{QStringLiteral("P"), QStringLiteral("parity")},
               QStringLiteral("The parity of a target given as a serial device: none, even or odd, or N, E, O "
                              "(default even, as mbpoll's -P)."),
               QStringLiteral("parity"))
    , m_dataBits(QStringList{QStringLiteral("d"), QStringLiteral("data-bits")},
                 QStringLiteral("The data bits of a target given as a serial device: 7 or 8 (default 8 for rtu, 7 for "
                                "ascii)."),
                 QStringLiteral("n"))
    , m_stopBits(QStringList{QStringLiteral("s"), QStringLiteral("stop-bits")},
                 QStringLiteral("The stop bits of a target given as a serial device: 1 or 2 (default 1)."),
                 QStringLiteral("n"))
{
}

void TargetPieces::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({m_mode, m_port, m_baud, m_parity, m_dataBits, m_stopBits});
}

bool TargetPieces::anySet(const QCommandLineParser &parser) const
{
    return !firstSet(parser).isEmpty();
}

QString TargetPieces::firstSet(const QCommandLineParser &parser) const
{
    for (const QCommandLineOption *o : {&m_mode, &m_port, &m_baud, &m_parity, &m_dataBits, &m_stopBits}) {
        if (parser.isSet(*o))
            return both(*o);
    }
    return {};
}

bool TargetPieces::isBare(const QString &target)
{
    return !target.contains(QLatin1String("://"));
}

bool TargetPieces::compose(const QCommandLineParser &parser, const QString &target, QString &url, QString &error) const
{
    const QString t = target.trimmed();
    if (t.isEmpty()) {
        error = QStringLiteral("the target is empty: give a host (192.168.1.10), a serial device (/dev/ttyUSB0) or a URL "
                               "(tcp://192.168.1.10:502)");
        return false;
    }
    const bool device = t.startsWith(QLatin1Char('/'));
    QString mode = parser.value(m_mode).trimmed().toLower();
    if (mode.isEmpty())
        mode = device ? QStringLiteral("rtu") : QStringLiteral("tcp");

    QString scheme;
    if (device) {
        if (mode != QLatin1String("rtu") && mode != QLatin1String("ascii")) {
            error = QStringLiteral("%1 %2: %3 is a serial device, which takes rtu or ascii; a host takes tcp, udp, tls, "
                                   "rtu or ascii")
                        .arg(both(m_mode), parser.value(m_mode), t);
            return false;
        }
        scheme = mode;
    } else {
        static const QStringList network{QStringLiteral("tcp"),     QStringLiteral("udp"),       QStringLiteral("tls"),
                                         QStringLiteral("rtu-tcp"), QStringLiteral("ascii-tcp"), QStringLiteral("rtu-udp")};
        if (mode == QLatin1String("rtu") || mode == QLatin1String("ascii")) {
            scheme = mode + QStringLiteral("-tcp");
        } else if (mode == QLatin1String("enc")) {
            scheme = QStringLiteral("rtu-tcp"); // modpoll's "encapsulated Modbus RTU over TCP"
        } else if (network.contains(mode)) {
            scheme = mode;
        } else {
            error = QStringLiteral("%1 '%2' is not a mode: expected tcp, udp, tls, rtu or ascii (rtu-tcp, ascii-tcp, "
                                   "rtu-udp, and modpoll's enc for rtu-tcp, too)")
                        .arg(both(m_mode), parser.value(m_mode));
            return false;
        }
    }

    // The pieces a kind has no use for are said, not ignored.
    const QList<const QCommandLineOption *> serialOnly{&m_baud, &m_parity, &m_dataBits, &m_stopBits};
    // modpoll's -p is the parity of a serial port: "-p none", "-p even", "-p odd".
    static const QStringList parities{QStringLiteral("none"), QStringLiteral("even"), QStringLiteral("odd")};
    const bool portIsParity = device && parser.isSet(m_port) && !parser.isSet(m_parity)
                              && parities.contains(parser.value(m_port).trimmed().toLower());
    if (device) {
        if (parser.isSet(m_port) && !portIsParity) {
            error = QStringLiteral("%1 is the port of a host, but %2 is a serial device (its line settings: -b, -P, -d, -s)")
                        .arg(both(m_port), t);
            return false;
        }
    } else {
        for (const QCommandLineOption *o : serialOnly) {
            if (parser.isSet(*o)) {
                error = QStringLiteral("%1 is a serial line setting, but %2 is a host (a serial device is a path: "
                                       "/dev/ttyUSB0)")
                            .arg(both(*o), t);
                return false;
            }
        }
    }

    if (!device) {
        QString host = t;
        int port = kDefaultPort;
        // "host:5020" and "[::1]:5020" carry their port; a bare IPv6 address ("::1") does not.
        const qsizetype colon = t.lastIndexOf(QLatin1Char(':'));
        const bool bracketed = t.startsWith(QLatin1Char('['));
        const bool hasPort = colon > 0 && (bracketed ? t.at(colon - 1) == QLatin1Char(']') : t.count(QLatin1Char(':')) == 1);
        if (hasPort) {
            const IntegerResult p = parseInteger(QStringLiteral("the port of %1").arg(t), t.mid(colon + 1), 1, 65535);
            if (!p.ok) {
                error = p.error;
                return false;
            }
            if (parser.isSet(m_port)) {
                error = QStringLiteral("%1 %2: %3 names its port already: give it once").arg(both(m_port), parser.value(m_port), t);
                return false;
            }
            host = t.left(colon);
            port = int(p.value);
        } else if (parser.isSet(m_port)) {
            const IntegerResult p = parseInteger(both(m_port), parser.value(m_port), 1, 65535);
            if (!p.ok) {
                error = p.error;
                return false;
            }
            port = int(p.value);
        }
        if (!bracketed && host.contains(QLatin1Char(':')))
            host = QLatin1Char('[') + host + QLatin1Char(']');
        url = QStringLiteral("%1://%2:%3").arg(scheme, host).arg(port);
        return true;
    }

    QStringList query;
    if (parser.isSet(m_baud)) {
        const IntegerResult b = parseInteger(both(m_baud), parser.value(m_baud), 50, 4000000);
        if (!b.ok) {
            error = b.error;
            return false;
        }
        query.append(QStringLiteral("baud=%1").arg(b.value));
    }
    if (parser.isSet(m_parity) || portIsParity) {
        const QString p = parser.value(portIsParity ? m_port : m_parity).trimmed().toLower();
        QChar letter;
        if (p == QLatin1String("none") || p == QLatin1String("n"))
            letter = QLatin1Char('N');
        else if (p == QLatin1String("even") || p == QLatin1String("e"))
            letter = QLatin1Char('E');
        else if (p == QLatin1String("odd") || p == QLatin1String("o"))
            letter = QLatin1Char('O');
        if (letter.isNull()) {
            error = QStringLiteral("%1 '%2' is not a parity: expected none, even or odd (or N, E, O)")
                        .arg(both(m_parity), parser.value(m_parity));
            return false;
        }
        query.append(QStringLiteral("parity=") + letter);
    }
    if (parser.isSet(m_dataBits)) {
        const IntegerResult d = parseInteger(both(m_dataBits), parser.value(m_dataBits), 7, 8);
        if (!d.ok) {
            error = d.error;
            return false;
        }
        query.append(QStringLiteral("data=%1").arg(d.value));
    }
    if (parser.isSet(m_stopBits)) {
        const IntegerResult s = parseInteger(both(m_stopBits), parser.value(m_stopBits), 1, 2);
        if (!s.ok) {
            error = s.error;
            return false;
        }
        query.append(QStringLiteral("stop=%1").arg(s.value));
    }
    url = QStringLiteral("%1://%2").arg(scheme, t);
    if (!query.isEmpty())
        url += QLatin1Char('?') + query.join(QLatin1Char('&'));
    return true;
}

} // namespace mbscope::app
