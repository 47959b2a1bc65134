#include "session/fieldexpectation.h"

#include "protocol/fieldtree.h"

#include <QtCore/QRegularExpression>

namespace mbscope {

bool FieldExpectation::parseSelector(const QString &text, FieldExpectation *out, QString *error)
{
    static const QRegularExpression pattern(
        QStringLiteral("^([a-z][a-z0-9_]*(?:\\.[a-z0-9_]+)+)(?:@(0[xX][0-9A-Fa-f]+|[0-9]+)|\\[([0-9]+)\\])?$"));
    const QRegularExpressionMatch m = pattern.match(text);
    if (!m.hasMatch()) {
        *error = QStringLiteral("'%1' is not a field selector: expected a dissector key such as modbus.register_value, "
                                "optionally followed by @ADDRESS (@0x0079 or @121) or [INDEX] ([0] is the first)")
                     .arg(text);
        return false;
    }
    out->selector = text;
    out->key = m.captured(1);
    out->address = -1;
    out->occurrence = -1;
    if (m.hasCaptured(2) && !m.captured(2).isEmpty()) {
        const QString a = m.captured(2);
        bool ok = false;
        const qint64 value = a.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? a.mid(2).toLongLong(&ok, 16)
                                                                                     : a.toLongLong(&ok, 10);
        if (!ok || value > 65535) {
            *error = QStringLiteral("'%1': address %2 is beyond 65535").arg(text, a);
            return false;
        }
        out->address = int(value);
    } else if (m.hasCaptured(3) && !m.captured(3).isEmpty()) {
        bool ok = false;
        const int index = m.captured(3).toInt(&ok);
        if (!ok || index > 65535) {
            *error = QStringLiteral("'%1': index %2 is beyond 65535").arg(text, m.captured(3));
            return false;
        }
        out->occurrence = index;
    }
    return true;
}

int FieldExpectation::find(const FieldTree &tree) const
{
    const QByteArray k = key.toLatin1();
    int seen = 0;
    for (int i = 0; i < tree.size(); ++i) {
        const Field &f = tree.at(i);
        if (qstrcmp(f.key, k.constData()) != 0)
            continue;
        if (address >= 0 && f.address != address)
            continue;
        if (occurrence >= 0 && seen++ != occurrence)
            continue;
        return i;
    }
    return -1;
}

QString FieldExpectation::expectedText() const
{
    if (equals)
        return QString::number(*equals);
    if (min && max)
        return QStringLiteral("%1 to %2").arg(*min).arg(*max);
    if (min)
        return QStringLiteral("at least %1").arg(*min);
    if (max)
        return QStringLiteral("at most %1").arg(*max);
    return QStringLiteral("any value");
}

bool FieldExpectation::accepts(qint64 value) const
{
    if (equals && value != *equals)
        return false;
    if (min && value < *min)
        return false;
    if (max && value > *max)
        return false;
    return true;
}

} // namespace mbscope
