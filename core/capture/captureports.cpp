#include "capture/captureports.h"

#include <QtCore/QStringList>

namespace mbscope {

bool CapturePorts::parse(const QString &text, QList<quint16> *ports, QString *error)
{
    QList<quint16> parsed;
    for (const QString &item : text.split(QLatin1Char(','))) {
        bool ok = false;
        const uint port = item.trimmed().toUInt(&ok);
        if (!ok || port == 0 || port > 65535) {
            *error = QStringLiteral("'%1' is not a port: expected a number from 1 to 65535").arg(item.trimmed());
            return false;
        }
        if (!parsed.contains(quint16(port)))
            parsed.append(quint16(port));
    }
    *ports = parsed;
    return true;
}

QString CapturePorts::format(const QList<quint16> &ports)
{
    QStringList items;
    for (quint16 port : ports)
        items.append(QString::number(port));
    return items.join(QStringLiteral(", "));
}

} // namespace mbscope
