#include "targetoptions.h"

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
                              "?framing=delimited&start=24&end=23."),
               QStringLiteral("url"))
    , m_timeout(QStringLiteral("timeout"),
                QStringLiteral("How long to wait for each answer: 1000ms, 2s... (default: the URL's timeout=, else 1000 ms)."),
                QStringLiteral("duration"))
    , m_retries(QStringLiteral("retries"),
                QStringLiteral("Further attempts after a timeout or an unusable answer (default 0)."), QStringLiteral("n"),
                QStringLiteral("0"))
    , m_withRetries(withRetries)
{
}

void TargetOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({m_target, m_timeout});
    if (m_withRetries)
        parser.addOption(m_retries);
}

bool TargetOptions::read(const QCommandLineParser &parser, const QString &command, TargetSettings &out,
                         QTextStream &err) const
{
    const QString prefix = QStringLiteral("mbscope %1: ").arg(command);
    if (!parser.isSet(m_target)) {
        err << prefix << "--target is required: the device's URL, e.g. --target tcp://192.168.1.10:502 "
            << "(schemes: " << LinkUrl::knownSchemes() << ")\n";
        return false;
    }
    const LinkUrl::Result url = LinkUrl::parse(parser.value(m_target));
    if (!url.url) {
        err << prefix << "--target: " << url.error << '\n';
        return false;
    }
    out.url = *url.url;

    out.timeoutMs = out.url.responseTimeoutMs >= 0 ? out.url.responseTimeoutMs : kDefaultTimeoutMs;
    if (parser.isSet(m_timeout)) {
        const DurationResult d = parseDuration(parser.value(m_timeout));
        if (!d.ok()) {
            err << prefix << "--timeout: " << d.error << '\n';
            return false;
        }
        if (d.ns < 1'000'000 || d.ns > kMaxTimeoutNs) {
            err << prefix << "--timeout " << parser.value(m_timeout)
                << " is out of range: expected 1ms to 1h (whole milliseconds)\n";
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

IntegerResult parseInteger(const QString &option, const QString &text)
{
    IntegerResult result;
    const QString t = text.trimmed();
    bool ok = false;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        result.value = t.mid(2).toLongLong(&ok, 16);
    else if (!t.startsWith(QLatin1Char('+')))
        result.value = t.toLongLong(&ok, 10);
    if (!ok) {
        result.error = QStringLiteral("%1 '%2' is not a number: expected decimal or 0x hex (e.g. 121 or 0x79)")
                           .arg(option, text);
        return result;
    }
    result.ok = true;
    return result;
}

IntegerResult parseInteger(const QString &option, const QString &text, qint64 low, qint64 high, const QString &what)
{
    IntegerResult result = parseInteger(option, text);
    if (result.ok && (result.value < low || result.value > high)) {
        result.ok = false;
        result.error = QStringLiteral("%1 %2 is out of range: expected %3 to %4%5")
                           .arg(option, text.trimmed())
                           .arg(low)
                           .arg(high)
                           .arg(what.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(what));
    }
    return result;
}

} // namespace mbscope::app
