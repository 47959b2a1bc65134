#include "common/targetoptions.h"

#include "time/duration.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QTextStream>

namespace mbscope::app {

namespace {

constexpr int kDefaultTimeoutMs = 1000;
// A timeout longer than this is a typo (an hour): QTimer counts milliseconds in an int anyway.
constexpr qint64 kMaxTimeoutNs = 3'600'000'000'000LL;

} // namespace

TargetOptions::TargetOptions(bool withRetries)
    : m_target(QStringLiteral("target"),
               QStringLiteral("The device: tcp://host:502, rtu-tcp://host:4001, ascii-tcp://host:port, udp://host:502, "
                              "rtu-udp://host:port, rtu:///dev/ttyUSB0?baud=9600&parity=E, ascii:///dev/ttyUSB0?..., "
                              "tls://host:802?cert=...&key=...&ca=...; any stream or serial link also takes "
                              "?framing=delimited&start=24&end=23. A device that connects to you (cellular units, "
                              "some gateways): tcp://0.0.0.0:5020?mode=listen (also rtu-tcp, ascii-tcp, tls) waits up "
                              "to connect_timeout= for it and uses its connection; a second connection while one is "
                              "in use replaces it (busy=replace, the default), waits for it to end (busy=queue) or "
                              "is closed at once (busy=refuse). A device that needs time: ?gap=50ms (between "
                              "requests), &warmup=500ms (after connecting), &close=each (a new connection per request). "
                              "Or, as mbpoll takes it, a host (192.168.1.10) or a "
                              "serial device (/dev/ttyUSB0) with -m, -p, -b, -P, -d, -s; the target may also be given "
                              "without --target, as the last argument."),
               QStringLiteral("url"))
    , m_timeout(QStringLiteral("timeout"),
                QStringLiteral("How long to wait for each answer: 1000ms, 2s... (default: the URL's timeout=, else 1000 ms)."),
                QStringLiteral("duration"))
    , m_timeoutSeconds(QStringList{QStringLiteral("o"), QStringLiteral("timeout-s")},
                       QStringLiteral("The same timeout in seconds, as mbpoll's -o: 0.5, 2 (a unit may follow: 500ms)."),
                       QStringLiteral("seconds"))
    , m_retries(QStringLiteral("retries"),
                QStringLiteral("Further attempts after a timeout or an unusable answer (default 0)."), QStringLiteral("n"),
                QStringLiteral("0"))
    , m_withRetries(withRetries)
{
}

void TargetOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({m_target, m_timeout, m_timeoutSeconds});
    if (m_withRetries)
        parser.addOption(m_retries);
    m_pieces.addTo(parser);
    parser.addPositionalArgument(QStringLiteral("target"),
                                 QStringLiteral("The device, as --target gives it (a URL, a host or a serial device)."),
                                 QStringLiteral("[target]"));
}

bool TargetOptions::read(const QCommandLineParser &parser, const QString &command, TargetSettings &out,
                         QTextStream &err, const QString &positionalHint) const
{
    const QString prefix = QStringLiteral("mbscope %1: ").arg(command);
    const QStringList positional = parser.positionalArguments();
    const qsizetype allowed = parser.isSet(m_target) ? 0 : 1;
    if (positional.size() > allowed) {
        err << prefix << "unexpected argument '" << positional.at(allowed) << "': "
            << (positionalHint.isEmpty() ? QStringLiteral("every setting is an option (see mbscope %1 --help)").arg(command)
                                         : positionalHint)
            << '\n';
        return false;
    }
    if (positional.isEmpty() && !parser.isSet(m_target)) {
        err << prefix << "--target is required: the device's URL, e.g. --target tcp://192.168.1.10:502 "
            << "(schemes: " << LinkUrl::knownSchemes() << "), or a host or serial device as the last argument "
            << "(mbscope " << command << " -p 502 192.168.1.10)\n";
        return false;
    }
    const QString typed = positional.isEmpty() ? parser.value(m_target) : positional.constFirst();
    const QString where = positional.isEmpty() ? QStringLiteral("--target") : QStringLiteral("target '%1'").arg(typed);
    QString text = typed;
    if (TargetPieces::isBare(typed)) {
        QString error;
        if (!m_pieces.compose(parser, typed, text, error)) {
            err << prefix << error << '\n';
            return false;
        }
    } else if (m_pieces.anySet(parser)) {
        err << prefix << m_pieces.firstSet(parser) << " applies to a target given as a host or a serial device; the URL "
            << typed << " says the link's settings itself: write them there (see mbscope " << command << " --help)\n";
        return false;
    }
    const LinkUrl::Result url = LinkUrl::parse(text);
    if (!url.url) {
        err << prefix << where << (text == typed ? QString() : QStringLiteral(" (as %1)").arg(text)) << ": " << url.error
            << '\n';
        return false;
    }
    out.url = *url.url;

    out.timeoutMs = out.url.responseTimeoutMs >= 0 ? out.url.responseTimeoutMs : kDefaultTimeoutMs;
    if (parser.isSet(m_timeout) && parser.isSet(m_timeoutSeconds)) {
        err << prefix << "--timeout and -o/--timeout-s both set the response timeout: give one\n";
        return false;
    }
    const bool seconds = parser.isSet(m_timeoutSeconds);
    if (seconds || parser.isSet(m_timeout)) {
        const QString name = seconds ? QStringLiteral("-o/--timeout-s") : QStringLiteral("--timeout");
        const QString value = parser.value(seconds ? m_timeoutSeconds : m_timeout);
        const DurationResult d = parseDuration(value, seconds ? Duration::Second : Duration::Millisecond);
        if (!d.ok()) {
            err << prefix << name << ": " << d.error << '\n';
            return false;
        }
        if (d.ns < 1'000'000 || d.ns > kMaxTimeoutNs) {
            err << prefix << name << " " << value << " is out of range: expected 1ms to 1h (whole milliseconds)\n";
            return false;
        }
        out.timeoutMs = int(d.ns / 1'000'000);
    }

    if (!m_withRetries)
        return true;
    const IntegerResult retries = parseInteger(QStringLiteral("--retries"), parser.value(m_retries), 0, 100);
    if (!retries.ok) {
        err << prefix << retries.error << '\n';
        return false;
    }
    out.retries = int(retries.value);
    return true;
}

} // namespace mbscope::app
