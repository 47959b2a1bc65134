#include "linkurl.h"

#include "time/duration.h"

#include <QtCore/QList>
#include <QtCore/QSet>
#include <QtCore/QUrl>
#include <QtNetwork/QHostAddress>

namespace mbscope {

namespace {

struct Scheme {
    LinkKind kind;
    const char *name;
};

constexpr Scheme kSchemes[] = {
    {LinkKind::Tcp, "tcp"},       {LinkKind::RtuTcp, "rtu-tcp"}, {LinkKind::AsciiTcp, "ascii-tcp"},
    {LinkKind::Udp, "udp"},       {LinkKind::RtuUdp, "rtu-udp"}, {LinkKind::Rtu, "rtu"},
    {LinkKind::Ascii, "ascii"},   {LinkKind::Tls, "tls"},
};

constexpr int kMaxTimeoutMs = 24 * 3600 * 1000;
constexpr qint64 kMaxTurnaroundUs = 10'000'000;

// Which links an option belongs to, for the message when it is used on another.
enum class Scope : quint8 { Any, Network, Stream, Serial, Tls };

struct Option {
    const char *key;
    Scope scope;
};

constexpr Option kOptions[] = {
    {"baud", Scope::Serial},      {"parity", Scope::Serial},         {"data", Scope::Serial},
    {"stop", Scope::Serial},      {"turnaround", Scope::Serial},     {"turnaround_us", Scope::Serial},
    {"rts", Scope::Serial},       {"rts_before", Scope::Serial},     {"rts_after", Scope::Serial},
    {"rs485", Scope::Serial},
    {"cert", Scope::Tls},         {"key", Scope::Tls},               {"ca", Scope::Tls},
    {"connect_timeout", Scope::Network}, {"timeout", Scope::Any},    {"framing", Scope::Any},
    {"start", Scope::Any},        {"end", Scope::Any},               {"checksum", Scope::Any},
    {"display", Scope::Any},      {"mode", Scope::Stream},           {"busy", Scope::Stream},
    {"gap", Scope::Any},          {"warmup", Scope::Any},            {"close", Scope::Stream},
};

bool inScope(Scope scope, LinkKind kind)
{
    const bool serial = kind == LinkKind::Rtu || kind == LinkKind::Ascii;
    switch (scope) {
    case Scope::Any: return true;
    case Scope::Network: return !serial;
    case Scope::Stream: return kind == LinkKind::Tcp || kind == LinkKind::RtuTcp || kind == LinkKind::AsciiTcp
                            || kind == LinkKind::Tls;
    case Scope::Serial: return serial;
    case Scope::Tls: return kind == LinkKind::Tls;
    }
    return false;
}

QString scopeText(Scope scope)
{
    switch (scope) {
    case Scope::Any: return QStringLiteral("every link");
    case Scope::Network: return QStringLiteral("network links (tcp, rtu-tcp, ascii-tcp, udp, rtu-udp, tls)");
    case Scope::Stream: return QStringLiteral("stream links (tcp, rtu-tcp, ascii-tcp, tls)");
    case Scope::Serial: return QStringLiteral("serial links (rtu, ascii)");
    case Scope::Tls: return QStringLiteral("tls links");
    }
    return {};
}

QString decode(QStringView text)
{
    return QUrl::fromPercentEncoding(text.toUtf8());
}

bool isHostNameCharacter(QChar c)
{
    return (c >= u'a' && c <= u'z') || (c >= u'A' && c <= u'Z') || (c >= u'0' && c <= u'9') || c == u'-' || c == u'.'
        || c == u'_';
}

// A URL's durations in the one grammar (time/duration.h); the key names which one is wrong.
QString durationError(const QString &key, const QString &value, const DurationResult &d, const QString &range)
{
    if (d.problem == DurationResult::Problem::TooLong)
        return QStringLiteral("%1 '%2' is out of range: %3").arg(key, value, range);
    return QStringLiteral("%1 %2").arg(key, d.error);
}

std::optional<int> parseHexByte(QStringView text)
{
    QStringView digits = text;
    if (digits.startsWith(u"0x", Qt::CaseInsensitive))
        digits = digits.mid(2);
    if (digits.isEmpty() || digits.size() > 2)
        return std::nullopt;
    bool ok = false;
    const int value = digits.toInt(&ok, 16);
    if (!ok || value < 0)
        return std::nullopt;
    return value;
}

// Host and port of a network URL; returns an error or an empty string.
QString parseHostPort(QStringView authority, LinkUrl &url, LinkUse use)
{
    const QString scheme = LinkUrl::schemeName(url.kind);
    QStringView rest;
    if (use == LinkUse::Listen && (authority.isEmpty() || authority.startsWith(u':') || authority == u"/")) {
        url.host = QStringLiteral("127.0.0.1"); // a server binds the loopback interface unless told
        rest = authority;
    } else if (authority.isEmpty()) {
        return QStringLiteral("no host: expected %1://host:port").arg(scheme);
    } else if (authority.startsWith(u'[')) {
        const qsizetype close = authority.indexOf(u']');
        if (close < 0)
            return QStringLiteral("'[' without ']' in the host: expected an IPv6 address in brackets, e.g. %1://[::1]:502")
                .arg(scheme);
        const QString address = authority.sliced(1, close - 1).toString();
        if (QHostAddress(address).protocol() != QAbstractSocket::IPv6Protocol)
            return QStringLiteral("'%1' in brackets is not an IPv6 address").arg(address);
        url.host = address;
        rest = authority.sliced(close + 1);
        if (!rest.isEmpty() && !rest.startsWith(u':') && rest != u"/")
            return QStringLiteral("unexpected '%1' after the IPv6 address: expected ':port'").arg(rest.toString());
    } else {
        const qsizetype colon = authority.indexOf(u':');
        if (colon >= 0 && authority.indexOf(u':', colon + 1) >= 0)
            return QStringLiteral("host '%1' looks like an IPv6 address: write it in brackets, e.g. %2://[::1]:502")
                .arg(authority.toString(), scheme);
        const qsizetype hostEnd = colon >= 0 ? colon : authority.size();
        url.host = authority.first(hostEnd).toString();
        rest = authority.sliced(hostEnd);
        const qsizetype slash = url.host.indexOf(u'/');
        if (slash >= 0) {
            rest = authority.sliced(slash);
            url.host.truncate(slash);
        }
        if (url.host.isEmpty())
            return QStringLiteral("no host: expected %1://host:port").arg(scheme);
        for (QChar c : std::as_const(url.host)) {
            if (!isHostNameCharacter(c))
                return QStringLiteral("host '%1' is not a host name or an IPv4 address (letters, digits, '-', '.')")
                    .arg(url.host);
        }
    }
    // Now rest is empty, "/", ":port" or ":port/path".
    QStringView portText;
    bool hasPort = false;
    if (rest.startsWith(u':')) {
        hasPort = true;
        portText = rest.sliced(1);
        const qsizetype slash = portText.indexOf(u'/');
        rest = slash >= 0 ? portText.sliced(slash) : QStringView();
        if (slash >= 0)
            portText = portText.first(slash);
    }
    if (!rest.isEmpty() && rest != u"/")
        return QStringLiteral("unexpected path '%1': %2 links have no path").arg(rest.toString(), scheme);
    if (hasPort) {
        if (portText.isEmpty())
            return QStringLiteral("no port after ':': expected a number 1-65535");
        bool ok = false;
        const qlonglong port = portText.toLongLong(&ok);
        if (!ok || portText.startsWith(u'+') || portText.startsWith(u'-'))
            return QStringLiteral("port '%1' is not a number").arg(portText.toString());
        const int lowest = use == LinkUse::Listen ? 0 : 1; // listening on 0: the OS chooses
        if (port < lowest || port > 65535)
            return QStringLiteral("port %1 is out of range: expected %2-65535").arg(port).arg(lowest);
        url.port = quint16(port);
        return {};
    }
    switch (url.kind) {
    case LinkKind::Tcp:
    case LinkKind::Udp:
        url.port = 502; // Messaging on TCP/IP V1.0b, 4.1: port 502 is reserved for Modbus
        return {};
    case LinkKind::Tls:
        url.port = 802; // MODBUS/TCP Security, 5.1: mbaps listens on 802
        return {};
    default:
        return QStringLiteral("no port: %1 needs one, e.g. %1://%2:4001 (serial device servers listen on ports of their own)")
            .arg(scheme, url.host.contains(u':') ? QLatin1Char('[') + url.host + QLatin1Char(']') : url.host);
    }
}

// Applies one option; returns an error or an empty string.
QString applyOption(const QString &key, const QString &value, LinkUrl &url)
{
    auto number = [&](int low, int high, int *out) -> QString {
        bool ok = false;
        const qlonglong n = value.toLongLong(&ok);
        if (!ok || value.startsWith(u'+'))
            return QStringLiteral("%1 '%2' is not a number").arg(key, value);
        if (n < low || n > high)
            return QStringLiteral("%1 %2 is out of range: expected %3-%4").arg(key).arg(n).arg(low).arg(high);
        *out = int(n);
        return {};
    };
    auto milliseconds = [&](qint64 bareUnitNs, int low, int *out) -> QString {
        const QString range = QStringLiteral("expected %1 ms to 24 h").arg(low);
        const DurationResult d = parseDuration(value, bareUnitNs);
        if (!d.ok())
            return durationError(key, value, d, range);
        if (d.ns % Duration::Millisecond != 0)
            return QStringLiteral("%1 '%2' is not a whole number of milliseconds").arg(key, value);
        if (d.ns / Duration::Millisecond < low || d.ns / Duration::Millisecond > kMaxTimeoutMs)
            return QStringLiteral("%1 '%2' is out of range: %3").arg(key, value, range);
        *out = int(d.ns / Duration::Millisecond);
        return {};
    };
    // The serial line's delays: whole microseconds, at most 10 s.
    auto microseconds = [&](qint64 bareUnitNs, int *out) -> QString {
        const QString range = QStringLiteral("expected at most 10 s");
        const DurationResult d = parseDuration(value, bareUnitNs);
        if (!d.ok())
            return durationError(key, value, d, range);
        if (d.ns % Duration::Microsecond != 0)
            return QStringLiteral("%1 '%2' is not a whole number of microseconds").arg(key, value);
        if (d.ns / Duration::Microsecond > kMaxTurnaroundUs)
            return QStringLiteral("%1 '%2' is out of range: %3").arg(key, value, range);
        *out = int(d.ns / Duration::Microsecond);
        return {};
    };

    if (key == u"baud")
        return number(50, 4000000, &url.serial.baud);
    if (key == u"data")
        return number(5, 8, &url.serial.dataBits);
    if (key == u"stop") {
        if (value != u"1" && value != u"2")
            return QStringLiteral("stop '%1' is not 1 or 2").arg(value);
        url.serial.stopBits = value.toInt();
        return {};
    }
    if (key == u"parity") {
        const QString v = value.toLower();
        if (v == u"n" || v == u"none")
            url.serial.parity = 'N';
        else if (v == u"e" || v == u"even")
            url.serial.parity = 'E';
        else if (v == u"o" || v == u"odd")
            url.serial.parity = 'O';
        else
            return QStringLiteral("parity '%1' is not N, E or O (none, even, odd)").arg(value);
        return {};
    }
    if (key == u"turnaround")
        return microseconds(Duration::Millisecond, &url.serial.turnaroundUs);
    if (key == u"turnaround_us")
        return microseconds(Duration::Microsecond, &url.serial.turnaroundUs);
    if (key == u"rts_before")
        return microseconds(Duration::Millisecond, &url.serial.rs485.beforeUs);
    if (key == u"rts_after")
        return microseconds(Duration::Millisecond, &url.serial.rs485.afterUs);
    if (key == u"rts") {
        const QString v = value.toLower();
        if (v != u"up" && v != u"down")
            return QStringLiteral("rts '%1' is not up or down (the RTS level while sending)").arg(value);
        url.serial.rs485.rts = v == u"up" ? Rs485Settings::Rts::Up : Rs485Settings::Rts::Down;
        return {};
    }
    if (key == u"rs485") {
        if (value.compare(u"kernel", Qt::CaseInsensitive) != 0)
            return QStringLiteral("rs485 '%1' is not known: expected kernel (the driver's RS-485 mode; rts=up or rts=down "
                                  "without it has mbscope switch RTS)")
                .arg(value);
        url.serial.rs485.kernel = true;
        return {};
    }
    if (key == u"connect_timeout")
        return milliseconds(Duration::Millisecond, 1, &url.connectTimeoutMs);
    if (key == u"timeout")
        return milliseconds(Duration::Millisecond, 1, &url.responseTimeoutMs);
    if (key == u"gap" || key == u"warmup") {
        int ms = 0;
        if (const QString error = milliseconds(Duration::Millisecond, 0, &ms); !error.isEmpty())
            return error;
        (key == u"gap" ? url.gap : url.warmUp) = std::chrono::milliseconds(ms);
        return {};
    }
    if (key == u"close") {
        if (value.compare(u"each", Qt::CaseInsensitive) != 0)
            return QStringLiteral("close '%1' is not known: expected each (the device hangs up after each answer: a new "
                                  "connection for each request)")
                .arg(value);
        url.closeAfterAnswer = true;
        return {};
    }
    if (key == u"cert" || key == u"key" || key == u"ca") {
        if (value.isEmpty())
            return QStringLiteral("%1 is empty: expected the path of a PEM file").arg(key);
        (key == u"cert" ? url.tls.certificate : key == u"key" ? url.tls.privateKey : url.tls.caCertificates) = value;
        return {};
    }
    if (key == u"framing") {
        if (value.compare(u"delimited", Qt::CaseInsensitive) != 0)
            return QStringLiteral("framing '%1' is not known: expected delimited (the scheme chooses the Modbus framing)")
                .arg(value);
        url.delimited.enabled = true;
        return {};
    }
    if (key == u"start" || key == u"end") {
        // One byte, or several separated by commas (any of them begins, or ends, a frame).
        QByteArray bytes;
        for (const QStringView part : QStringView(value).split(u',')) {
            const auto byte = parseHexByte(part);
            if (!byte)
                return QStringLiteral("%1 '%2' is not a byte in hex: expected two hex digits, e.g. 24 for '$', 05 for ENQ, "
                                      "or several separated by commas (06,15 for ACK or NAK)")
                    .arg(key, part.isEmpty() ? value : part.toString());
            if (!bytes.contains(char(*byte)))
                bytes.append(char(*byte));
        }
        (key == u"start" ? url.delimited.startBytes : url.delimited.endBytes) = bytes;
        return {};
    }
    if (key == u"checksum") {
        const QString v = value.toLower();
        if (v == u"none")
            url.delimited.checksum = DelimitedChecksum::None;
        else if (v == u"sum" || v == u"bcc")
            url.delimited.checksum = DelimitedChecksum::Sum;
        else if (v == u"xor")
            url.delimited.checksum = DelimitedChecksum::Xor;
        else
            return QStringLiteral("checksum '%1' is not none, sum or xor").arg(value);
        return {};
    }
    if (key == u"mode") {
        const QString v = value.toLower();
        if (v != u"connect" && v != u"listen")
            return QStringLiteral("mode '%1' is not connect or listen (listen: wait for the device to connect to this address)")
                .arg(value);
        url.listen = v == u"listen";
        return {};
    }
    if (key == u"busy") {
        const QString v = value.toLower();
        for (BusyPolicy policy : {BusyPolicy::Replace, BusyPolicy::Queue, BusyPolicy::Refuse}) {
            if (v == LinkUrl::busyPolicyName(policy)) {
                url.busy = policy;
                return {};
            }
        }
        return QStringLiteral("busy '%1' is not replace, queue or refuse").arg(value);
    }
    if (key == u"display") {
        const QString v = value.toLower();
        if (v != u"text" && v != u"hex")
            return QStringLiteral("display '%1' is not text or hex").arg(value);
        url.delimited.textDisplay = v == u"text";
        return {};
    }
    return QStringLiteral("unknown option '%1'").arg(key);
}

// A listening link (mode=listen) binds an address of this machine: a host name is not one.
QString checkListen(const QSet<QString> &seen, const LinkUrl &url, LinkUse use)
{
    if (use == LinkUse::Listen && seen.contains(QStringLiteral("mode")))
        return QStringLiteral("'mode' is an option of --target URLs, not of an address to listen on (this one listens already)");
    if (use == LinkUse::Listen) {
        for (const char *key : {"gap", "warmup", "close"}) {
            if (seen.contains(QLatin1String(key)))
                return QStringLiteral("'%1' is the pace of a device asked (an option of --target URLs), not of an address to "
                                      "listen on")
                    .arg(QLatin1String(key));
        }
    }
    if (!url.listen) {
        if (seen.contains(QStringLiteral("busy")))
            return QStringLiteral("'busy' needs mode=listen");
        return {};
    }
    if (QHostAddress(url.host).isNull())
        return QStringLiteral("mode=listen needs an address of this machine to listen on, not the host name '%1' "
                              "(0.0.0.0 for every IPv4 interface, [::] for every IPv6 interface, 127.0.0.1 for this machine only)")
            .arg(url.host);
    if (url.kind == LinkKind::Tls && url.tls.certificate.isEmpty())
        return QStringLiteral("tls with mode=listen needs cert=FILE and key=FILE: mbscope is the TLS server of the device's "
                              "connection");
    return {};
}

// RS-485 options that only make sense together; the driver's mode takes whole milliseconds.
QString checkRs485(const QSet<QString> &seen, Rs485Settings &rs485)
{
    if (rs485.kernel && rs485.rts == Rs485Settings::Rts::None)
        rs485.rts = Rs485Settings::Rts::Up; // SER_RS485_RTS_ON_SEND, as most transceivers are wired
    for (const char *key : {"rts_before", "rts_after"}) {
        const QLatin1String name(key);
        if (!seen.contains(name))
            continue;
        if (!rs485.enabled())
            return QStringLiteral("'%1' needs rts=up, rts=down or rs485=kernel").arg(name);
        const int us = name == QLatin1String("rts_before") ? rs485.beforeUs : rs485.afterUs;
        if (rs485.kernel && us % 1000 != 0)
            return QStringLiteral("%1 %2us is not a whole number of milliseconds: rs485=kernel hands the driver milliseconds")
                .arg(name)
                .arg(us);
    }
    return {};
}

QString parseOptions(QStringView query, LinkUrl &url, LinkUse use)
{
    QSet<QString> seen;
    const QString scheme = LinkUrl::schemeName(url.kind);
    for (QStringView part : query.split(u'&')) {
        if (part.isEmpty())
            continue;
        const qsizetype eq = part.indexOf(u'=');
        if (eq < 0)
            return QStringLiteral("option '%1' has no value: expected %1=<value>").arg(part.toString());
        const QString key = part.first(eq).toString().toLower();
        const QString value = decode(part.sliced(eq + 1));
        const Option *option = nullptr;
        for (const Option &o : kOptions) {
            if (key == QLatin1String(o.key))
                option = &o;
        }
        if (!option) {
            QStringList known;
            for (const Option &o : kOptions) {
                if (inScope(o.scope, url.kind))
                    known.append(QLatin1String(o.key));
            }
            return QStringLiteral("unknown option '%1': %2 links take %3").arg(key, scheme, known.join(QStringLiteral(", ")));
        }
        if (!inScope(option->scope, url.kind))
            return QStringLiteral("'%1' is an option of %2, not of %3 links").arg(key, scopeText(option->scope), scheme);
        if (seen.contains(key))
            return QStringLiteral("option '%1' is given twice").arg(key);
        seen.insert(key);
        if (const QString error = applyOption(key, value, url); !error.isEmpty())
            return error;
    }
    if (seen.contains(QStringLiteral("turnaround")) && seen.contains(QStringLiteral("turnaround_us")))
        return QStringLiteral("turnaround and turnaround_us are both given: use one");
    if (const QString error = checkRs485(seen, url.serial.rs485); !error.isEmpty())
        return error;
    if (!url.delimited.enabled) {
        for (const char *key : {"start", "end", "checksum", "display"}) {
            if (seen.contains(QLatin1String(key)))
                return QStringLiteral("'%1' needs framing=delimited").arg(QLatin1String(key));
        }
    }
    if (url.tls.certificate.isEmpty() != url.tls.privateKey.isEmpty())
        return url.tls.certificate.isEmpty() ? QStringLiteral("key without cert: mutual TLS needs both cert=FILE and key=FILE")
                                             : QStringLiteral("cert without key: mutual TLS needs both cert=FILE and key=FILE");
    if (const QString error = checkListen(seen, url, use); !error.isEmpty())
        return error;
    // Serial Line V1.02, 2.5.1: every RTU character carries 8 data bits; ASCII needs at least 7.
    if (url.kind == LinkKind::Rtu && url.serial.dataBits != 8 && !url.delimited.enabled)
        return QStringLiteral("data=%1 cannot carry RTU frames: RTU needs data=8 (Serial Line V1.02, 2.5.1)")
            .arg(url.serial.dataBits);
    if (url.kind == LinkKind::Ascii && url.serial.dataBits < 7 && !url.delimited.enabled)
        return QStringLiteral("data=%1 cannot carry ASCII frames: expected data=7 or 8").arg(url.serial.dataBits);
    return {};
}

} // namespace

QString LinkUrl::knownSchemes()
{
    QStringList names;
    for (const Scheme &s : kSchemes)
        names.append(QLatin1String(s.name));
    return names.join(QStringLiteral(", "));
}

QString LinkUrl::busyPolicyName(BusyPolicy policy)
{
    switch (policy) {
    case BusyPolicy::Replace: return QStringLiteral("replace");
    case BusyPolicy::Queue: return QStringLiteral("queue");
    case BusyPolicy::Refuse: return QStringLiteral("refuse");
    }
    return QStringLiteral("replace");
}

QString LinkUrl::schemeName(LinkKind kind)
{
    for (const Scheme &s : kSchemes) {
        if (s.kind == kind)
            return QLatin1String(s.name);
    }
    return QStringLiteral("tcp");
}

LinkUrl::Result LinkUrl::parse(QStringView input)
{
    return parse(input, LinkUse::Connect);
}

LinkUrl::Result LinkUrl::parse(QStringView input, LinkUse use)
{
    const QStringView text = input.trimmed();
    auto fail = [&](const QString &what) { return Result{std::nullopt, text.toString() + QStringLiteral(": ") + what}; };
    const qsizetype separator = text.indexOf(u"://");
    if (separator <= 0)
        return fail(QStringLiteral("no scheme: expected scheme://..., with a scheme among %1 (e.g. tcp://192.168.1.10:502)")
                        .arg(knownSchemes()));
    const QString scheme = text.first(separator).toString().toLower();
    LinkUrl url;
    bool known = false;
    for (const Scheme &s : kSchemes) {
        if (scheme == QLatin1String(s.name)) {
            url.kind = s.kind;
            known = true;
        }
    }
    if (!known)
        return fail(QStringLiteral("unknown scheme '%1': expected one of %2").arg(scheme, knownSchemes()));

    const QStringView rest = text.sliced(separator + 3);
    const qsizetype question = rest.indexOf(u'?');
    const QStringView authority = question < 0 ? rest : rest.first(question);
    const QStringView query = question < 0 ? QStringView() : rest.sliced(question + 1);

    if (url.isSerial()) {
        url.serial.device = decode(authority);
        if (url.serial.device.isEmpty())
            return fail(QStringLiteral("no serial device: expected e.g. %1:///dev/ttyUSB0").arg(scheme));
        if (url.kind == LinkKind::Ascii)
            url.serial.dataBits = 7; // Serial Line V1.02, 2.5.2: ASCII characters carry 7 data bits
    } else if (const QString error = parseHostPort(authority, url, use); !error.isEmpty()) {
        return fail(error);
    }
    if (const QString error = parseOptions(query, url, use); !error.isEmpty())
        return fail(error);
    return Result{url, {}};
}

Framing LinkUrl::framing() const
{
    switch (kind) {
    case LinkKind::Tcp:
    case LinkKind::Tls: return Framing::Tcp;
    case LinkKind::Udp: return Framing::Udp;
    case LinkKind::RtuTcp:
    case LinkKind::RtuUdp:
    case LinkKind::Rtu: return Framing::Rtu;
    case LinkKind::AsciiTcp:
    case LinkKind::Ascii: return Framing::Ascii;
    }
    return Framing::Tcp;
}

QString LinkUrl::address() const
{
    if (isSerial())
        return serial.device;
    const QString h = host.contains(u':') ? QLatin1Char('[') + host + QLatin1Char(']') : host;
    return h + QLatin1Char(':') + QString::number(port);
}

} // namespace mbscope
