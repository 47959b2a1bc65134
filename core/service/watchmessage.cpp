#include "watchmessage.h"

#include <QtCore/QDateTime>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

namespace mbscope {

QString WatchMessage::addressKey(quint16 address)
{
    return QStringLiteral("0x") + QStringLiteral("%1").arg(address, 4, 16, QLatin1Char('0')).toUpper();
}

QString WatchMessage::timeText(qint64 msSinceEpoch)
{
    return QDateTime::fromMSecsSinceEpoch(msSinceEpoch, Qt::UTC).toString(Qt::ISODateWithMs);
}

QString WatchMessage::topicLevel(const QString &name)
{
    QString level = name;
    for (QChar &c : level) {
        if (c == QLatin1Char('/') || c == QLatin1Char('+') || c == QLatin1Char('#') || c.isNull())
            c = QLatin1Char('_');
    }
    return level;
}

QByteArray WatchMessage::sample(const WatchDefinition &watch, const WatchSample &s)
{
    QJsonObject o;
    o.insert(QStringLiteral("watch"), watch.name);
    o.insert(QStringLiteral("target"), watch.target);
    o.insert(QStringLiteral("unit"), int(watch.unit));
    o.insert(QStringLiteral("poll"), double(s.poll));
    o.insert(QStringLiteral("time"), timeText(s.timeMs));
    o.insert(QStringLiteral("status"), watchSampleStatusName(s.status));
    if (s.latencyNs >= 0)
        o.insert(QStringLiteral("latency_seconds"), double(s.latencyNs) / 1e9);
    if (!s.isOk()) {
        o.insert(QStringLiteral("error"), s.error);
        if (s.status == WatchSample::Status::Exception)
            o.insert(QStringLiteral("exception_code"), int(s.exceptionCode));
        return QJsonDocument(o).toJson(QJsonDocument::Compact);
    }
    QJsonObject values;
    QJsonObject units;
    QJsonObject bits;
    for (const WatchPointValue &v : s.values) {
        const QString key = v.name.isEmpty() ? addressKey(v.address) : v.name;
        values.insert(key, v.value);
        if (!v.unit.isEmpty())
            units.insert(key, v.unit);
        if (v.bitFields.isEmpty())
            continue;
        QJsonObject fields;
        for (const WatchBitFieldValue &f : v.bitFields)
            fields.insert(f.name, f.state.isEmpty() ? QJsonValue(double(f.value)) : QJsonValue(f.state));
        bits.insert(key, fields);
    }
    o.insert(QStringLiteral("values"), values);
    if (!units.isEmpty())
        o.insert(QStringLiteral("units"), units);
    if (!bits.isEmpty())
        o.insert(QStringLiteral("bits"), bits);
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QByteArray WatchMessage::ruleEvent(const WatchRuleEvent &e)
{
    QJsonObject o;
    o.insert(QStringLiteral("watch"), e.watchName);
    o.insert(QStringLiteral("rule"), e.rule);
    o.insert(QStringLiteral("fired"), e.fired);
    o.insert(QStringLiteral("severity"), watchSeverityName(e.severity));
    o.insert(QStringLiteral("point"), e.point);
    o.insert(QStringLiteral("value"), e.value);
    o.insert(QStringLiteral("message"), e.message);
    o.insert(QStringLiteral("time"), timeText(e.timeMs));
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

} // namespace mbscope
