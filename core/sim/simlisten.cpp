#include "sim/simlisten.h"

namespace mbscope {

std::optional<QHostAddress> listenAddress(const QString &host, QString *error)
{
    if (host.compare(QLatin1String("localhost"), Qt::CaseInsensitive) == 0)
        return QHostAddress(QHostAddress::LocalHost);
    QHostAddress address;
    if (!address.setAddress(host)) {
        *error = QStringLiteral("cannot listen on '%1': give an IP address of this machine (127.0.0.1, 0.0.0.0 for every "
                                "interface, [::1]) or localhost")
                     .arg(host);
        return std::nullopt;
    }
    return address;
}

} // namespace mbscope
