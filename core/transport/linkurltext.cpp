// LinkUrl written back as text: the inverse of LinkUrl::parse (linkurl.cpp), options left out
// where they hold their default, so that parse(toString()) gives the same link.
#include "linkurl.h"

#include <QtCore/QStringList>
#include <QtCore/QUrl>

namespace mbscope {

namespace {

QString encode(const QString &text)
{
    return QString::fromUtf8(QUrl::toPercentEncoding(text, QByteArrayLiteral("/:@+,")));
}

QString hexByte(int value)
{
    return QString::number(value, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

} // namespace

QString LinkUrl::toString() const
{
    QString text = schemeName(kind) + QStringLiteral("://");
    QStringList options;
    auto add = [&](const char *key, const QString &value) { options.append(QLatin1String(key) + QLatin1Char('=') + value); };
    if (isSerial()) {
        text += encode(serial.device);
        add("baud", QString::number(serial.baud));
        add("parity", QString(QLatin1Char(serial.parity)));
        add("data", QString::number(serial.dataBits));
        add("stop", QString::number(serial.stopBits));
        auto microseconds = [](int us) {
            return us % 1000 == 0 ? QString::number(us / 1000) + QStringLiteral("ms") : QString::number(us) + QStringLiteral("us");
        };
        if (serial.turnaroundUs > 0)
            add("turnaround", microseconds(serial.turnaroundUs));
        if (serial.rs485.enabled()) {
            add("rts", serial.rs485.sendLevel() ? QStringLiteral("up") : QStringLiteral("down"));
            if (serial.rs485.beforeUs > 0)
                add("rts_before", microseconds(serial.rs485.beforeUs));
            if (serial.rs485.afterUs > 0)
                add("rts_after", microseconds(serial.rs485.afterUs));
            if (serial.rs485.kernel)
                add("rs485", QStringLiteral("kernel"));
        }
    } else {
        text += address();
        if (!tls.certificate.isEmpty())
            add("cert", encode(tls.certificate));
        if (!tls.privateKey.isEmpty())
            add("key", encode(tls.privateKey));
        if (!tls.caCertificates.isEmpty())
            add("ca", encode(tls.caCertificates));
        if (connectTimeoutMs != LinkUrl{}.connectTimeoutMs)
            add("connect_timeout", QString::number(connectTimeoutMs) + QStringLiteral("ms"));
        if (listen)
            add("mode", QStringLiteral("listen"));
        if (listen && busy != BusyPolicy::Replace)
            add("busy", busyPolicyName(busy));
    }
    if (responseTimeoutMs >= 0)
        add("timeout", QString::number(responseTimeoutMs) + QStringLiteral("ms"));
    if (gap.count() > 0)
        add("gap", QString::number(gap.count()) + QStringLiteral("ms"));
    if (warmUp.count() > 0)
        add("warmup", QString::number(warmUp.count()) + QStringLiteral("ms"));
    if (closeAfterAnswer)
        add("close", QStringLiteral("each"));
    if (delimited.enabled) {
        add("framing", QStringLiteral("delimited"));
        auto hexList = [](const QByteArray &bytes) {
            QStringList parts;
            for (char c : bytes)
                parts << hexByte(int(quint8(c)));
            return parts.join(QLatin1Char(','));
        };
        if (!delimited.startBytes.isEmpty())
            add("start", hexList(delimited.startBytes));
        add("end", hexList(delimited.endBytes));
        if (delimited.checksum != DelimitedChecksum::None)
            add("checksum", DelimitedFramer::checksumName(delimited.checksum));
        if (!delimited.textDisplay)
            add("display", QStringLiteral("hex"));
    }
    if (!options.isEmpty())
        text += QLatin1Char('?') + options.join(QLatin1Char('&'));
    return text;
}

} // namespace mbscope
