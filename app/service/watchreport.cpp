#include "service/watchreport.h"

#include "time/duration.h"

#include <QtCore/QDateTime>
#include <QtCore/QJsonArray>
#include <QtCore/QStringList>

namespace mbscope::app {

namespace {

QString hex4(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

QString valueText(const WatchPointValue &v)
{
    QString text = (v.name.isEmpty() ? hex4(v.address) : v.name) + QLatin1Char(' ') + v.text;
    if (!v.unit.isEmpty())
        text += QLatin1Char(' ') + v.unit;
    if (!v.bitFields.isEmpty()) {
        QStringList fields;
        for (const WatchBitFieldValue &b : v.bitFields)
            fields.append(b.name + QLatin1Char('=') + (b.state.isEmpty() ? QString::number(b.value) : b.state));
        text += QStringLiteral(" (%1)").arg(fields.join(QLatin1String(", ")));
    }
    return text;
}

double ms(qint64 ns)
{
    return double(ns) / 1e6;
}

} // namespace

QString WatchReport::timeText(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("HH:mm:ss.zzz"));
}

QString WatchReport::isoTime(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

QString WatchReport::sampleLine(const WatchSample &s)
{
    QStringList parts;
    parts.append(QStringLiteral("%1 %2 #%3 %4 %5")
                     .arg(timeText(s.timeMs), s.watchName)
                     .arg(s.poll)
                     .arg(watchSampleStatusName(s.status), s.latencyNs >= 0 ? formatDuration(s.latencyNs) : QStringLiteral("-")));
    for (const WatchPointValue &v : s.values)
        parts.append(valueText(v));
    return parts.join(QLatin1String(" | "));
}

QString WatchReport::errorLine(const WatchSample &s)
{
    return QStringLiteral("%1 %2 #%3: %4: %5").arg(timeText(s.timeMs), s.watchName).arg(s.poll).arg(watchSampleStatusName(s.status), s.error);
}

QString WatchReport::ruleLine(const WatchRuleEvent &e)
{
    return QStringLiteral("%1 %2 %3 %4: %5 (%6)")
        .arg(timeText(e.timeMs), e.watchName, watchSeverityName(e.severity).toUpper(),
             e.fired ? QStringLiteral("fired") : QStringLiteral("cleared"), e.message, QString::number(e.value, 'g', 10));
}

QString WatchReport::countersLine(const WatchCounters &c)
{
    QString text = QStringLiteral("%1: %2 polls, %3 ok, %4 exceptions, %5 timeouts, %6 CRC errors, %7 other errors, "
                                  "%8 link errors, %9 reconnects")
                       .arg(c.watchName)
                       .arg(c.polls)
                       .arg(c.ok)
                       .arg(c.exceptions)
                       .arg(c.timeouts)
                       .arg(c.crcErrors)
                       .arg(c.otherErrors)
                       .arg(c.linkErrors)
                       .arg(c.reconnects);
    text += QStringLiteral(", %1 rule firings, %2 overruns").arg(c.ruleFirings).arg(c.overruns);
    if (c.latencyCount > 0)
        text += QStringLiteral("; latency min %1, mean %2, max %3")
                    .arg(formatDuration(c.minLatencyNs), formatDuration(qint64(c.meanLatencyNs)), formatDuration(c.maxLatencyNs));
    if (!c.lastError.isEmpty())
        text += QStringLiteral("; last error at %1: %2").arg(timeText(c.lastErrorMs), c.lastError);
    return text;
}

QJsonObject WatchReport::sampleJson(const WatchSample &s)
{
    QJsonObject o;
    o.insert(QLatin1String("type"), QStringLiteral("sample"));
    o.insert(QLatin1String("time"), isoTime(s.timeMs));
    o.insert(QLatin1String("watch"), s.watchName);
    o.insert(QLatin1String("poll"), double(s.poll));
    o.insert(QLatin1String("status"), watchSampleStatusName(s.status));
    if (s.latencyNs >= 0)
        o.insert(QLatin1String("latency_ms"), ms(s.latencyNs));
    if (s.status == WatchSample::Status::Exception)
        o.insert(QLatin1String("exception_code"), s.exceptionCode);
    if (!s.error.isEmpty())
        o.insert(QLatin1String("error"), s.error);
    if (s.isOk()) {
        QJsonArray values;
        for (const WatchPointValue &v : s.values) {
            QJsonObject value;
            value.insert(QLatin1String("address"), v.address);
            if (!v.name.isEmpty())
                value.insert(QLatin1String("name"), v.name);
            value.insert(QLatin1String("value"), v.value);
            value.insert(QLatin1String("text"), v.text);
            if (!v.unit.isEmpty())
                value.insert(QLatin1String("unit"), v.unit);
            if (!v.bitFields.isEmpty()) {
                QJsonObject fields;
                for (const WatchBitFieldValue &b : v.bitFields)
                    fields.insert(b.name, b.state.isEmpty() ? QJsonValue(double(b.value)) : QJsonValue(b.state));
                value.insert(QLatin1String("bit_fields"), fields);
            }
            values.append(value);
        }
        o.insert(QLatin1String("values"), values);
    }
    return o;
}

QJsonObject WatchReport::ruleJson(const WatchRuleEvent &e)
{
    QJsonObject o;
    o.insert(QLatin1String("type"), QStringLiteral("rule"));
    o.insert(QLatin1String("time"), isoTime(e.timeMs));
    o.insert(QLatin1String("watch"), e.watchName);
    o.insert(QLatin1String("rule"), e.rule);
    o.insert(QLatin1String("event"), e.fired ? QStringLiteral("fired") : QStringLiteral("cleared"));
    o.insert(QLatin1String("severity"), watchSeverityName(e.severity));
    if (!e.colour.isEmpty())
        o.insert(QLatin1String("colour"), e.colour);
    o.insert(QLatin1String("point"), e.point);
    o.insert(QLatin1String("value"), e.value);
    o.insert(QLatin1String("message"), e.message);
    o.insert(QLatin1String("fired_count"), double(e.firedCount));
    return o;
}

QJsonObject WatchReport::linkJson(const WatchLinkState &s)
{
    QJsonObject o;
    o.insert(QLatin1String("type"), QStringLiteral("link"));
    o.insert(QLatin1String("time"), isoTime(s.timeMs));
    o.insert(QLatin1String("target"), s.target);
    o.insert(QLatin1String("state"), watchLinkStateName(s.state));
    if (!s.message.isEmpty())
        o.insert(QLatin1String("message"), s.message);
    if (s.state == WatchLinkState::State::Backoff)
        o.insert(QLatin1String("retry_in_ms"), s.retryInMs);
    o.insert(QLatin1String("reconnects"), double(s.reconnects));
    o.insert(QLatin1String("failures"), double(s.failures));
    return o;
}

QJsonObject WatchReport::countersJson(const WatchCounters &c)
{
    QJsonObject o;
    o.insert(QLatin1String("watch"), c.watchName);
    o.insert(QLatin1String("polls"), double(c.polls));
    o.insert(QLatin1String("ok"), double(c.ok));
    o.insert(QLatin1String("exceptions"), double(c.exceptions));
    QJsonObject byCode;
    for (auto it = c.exceptionsByCode.cbegin(); it != c.exceptionsByCode.cend(); ++it)
        byCode.insert(QString::number(it.key()), double(it.value()));
    o.insert(QLatin1String("exceptions_by_code"), byCode);
    o.insert(QLatin1String("timeouts"), double(c.timeouts));
    o.insert(QLatin1String("crc_errors"), double(c.crcErrors));
    o.insert(QLatin1String("other_errors"), double(c.otherErrors));
    o.insert(QLatin1String("link_errors"), double(c.linkErrors));
    o.insert(QLatin1String("reconnects"), double(c.reconnects));
    o.insert(QLatin1String("rule_firings"), double(c.ruleFirings));
    o.insert(QLatin1String("overruns"), double(c.overruns));
    if (!c.lastError.isEmpty()) {
        o.insert(QLatin1String("last_error"), c.lastError);
        o.insert(QLatin1String("last_error_time"), isoTime(c.lastErrorMs));
    }
    if (c.lastOkMs > 0)
        o.insert(QLatin1String("last_ok_time"), isoTime(c.lastOkMs));
    if (c.latencyCount > 0) {
        o.insert(QLatin1String("latency_min_ms"), ms(c.minLatencyNs));
        o.insert(QLatin1String("latency_mean_ms"), c.meanLatencyNs / 1e6);
        o.insert(QLatin1String("latency_max_ms"), ms(c.maxLatencyNs));
    }
    return o;
}

} // namespace mbscope::app
