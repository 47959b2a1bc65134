#include "common/listenaddress.h"

namespace mbscope::app {

QString ListenAddress::hostText() const
{
    if (address == QHostAddress::Any || address == QHostAddress::AnyIPv4)
        return QStringLiteral("0.0.0.0");
    if (address.protocol() == QAbstractSocket::IPv6Protocol)
        return QLatin1Char('[') + address.toString() + QLatin1Char(']');
    return address.toString();
}

std::optional<ListenAddress> ListenAddress::parse(const QString &text, QString *error)
{
    const QString t = text.trimmed();
    QString host = QStringLiteral("localhost");
    QString portText = t;
    if (t.startsWith(QLatin1Char('['))) {
        const qsizetype close = t.indexOf(QLatin1String("]:"));
        if (close < 0) {
            *error = QStringLiteral("'%1': an IPv6 address is written [ADDRESS]:PORT").arg(text);
            return std::nullopt;
        }
        host = t.mid(1, close - 1);
        portText = t.mid(close + 2);
    } else if (const qsizetype colon = t.lastIndexOf(QLatin1Char(':')); colon >= 0) {
        host = t.left(colon);
        portText = t.mid(colon + 1);
    }
    bool ok = false;
    const uint port = portText.toUInt(&ok);
    if (!ok || port > 65535) {
        *error = QStringLiteral("'%1': the port '%2' is not a number from 0 to 65535 (HOST:PORT, or a port alone for the loopback interface)")
                     .arg(text, portText);
        return std::nullopt;
    }
    ListenAddress result;
    result.port = quint16(port);
    if (host.isEmpty() || host == QLatin1String("localhost")) {
        result.address = QHostAddress(QHostAddress::LocalHost);
    } else if (host == QLatin1String("*")) {
        result.address = QHostAddress(QHostAddress::Any);
    } else if (!result.address.setAddress(host)) {
        *error = QStringLiteral("'%1': the host '%2' is not an IP address, 'localhost' or '*' (every interface)").arg(text, host);
        return std::nullopt;
    }
    return result;
}

} // namespace mbscope::app
