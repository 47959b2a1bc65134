#include "duration.h"

#include <cmath>

namespace mbscope {

namespace {

struct Unit {
    const char16_t *suffix;
    qint64 ns;
};

// Longest suffixes first where one ends another: "ms" must not be read as "s", "min" as "m"
// (a minute too, as systemd and Prometheus spell it).
constexpr Unit kUnits[] = {
    {u"min", Duration::Minute}, {u"ns", Duration::Nanosecond}, {u"us", Duration::Microsecond},
    {u"\u00b5s", Duration::Microsecond}, {u"ms", Duration::Millisecond}, {u"s", Duration::Second},
    {u"m", Duration::Minute}, {u"h", Duration::Hour},
};

QString trimmedDecimals(double value)
{
    QString text = QString::number(value, 'f', 3);
    while (text.contains(QLatin1Char('.')) && (text.endsWith(QLatin1Char('0')) || text.endsWith(QLatin1Char('.'))))
        text.chop(1);
    return text;
}

DurationResult failed(DurationResult::Problem problem, QString error)
{
    DurationResult result;
    result.problem = problem;
    result.error = std::move(error);
    return result;
}

} // namespace

QString durationGrammar(qint64 bareUnitNs)
{
    QString text = QStringLiteral("expected a number with %1 unit ns, us, ms, s, min or h (e.g. 100ms, 1.5s, 2min")
                       .arg(bareUnitNs == Duration::UnitRequired ? QStringLiteral("a") : QStringLiteral("an optional"));
    if (bareUnitNs == Duration::Millisecond)
        text += QStringLiteral("; a bare number is milliseconds");
    else if (bareUnitNs == Duration::Microsecond)
        text += QStringLiteral("; a bare number is microseconds");
    else if (bareUnitNs != Duration::UnitRequired)
        text += QStringLiteral("; a bare number is in units of %1 ns").arg(bareUnitNs);
    return text + QLatin1Char(')');
}

DurationResult parseDuration(QStringView text, qint64 bareUnitNs)
{
    using Problem = DurationResult::Problem;
    const QStringView t = text.trimmed();
    qint64 unit = bareUnitNs;
    QStringView number = t;
    for (const Unit &u : kUnits) {
        if (t.endsWith(QStringView(u.suffix), Qt::CaseInsensitive)) {
            unit = u.ns;
            number = t.chopped(QStringView(u.suffix).size()).trimmed();
            break;
        }
    }
    if (number.startsWith(u'-'))
        return failed(Problem::Negative, QStringLiteral("'%1' is a negative duration: a duration is 0 or more").arg(t));
    // Digits with at most one decimal point: no sign, no exponent, no "inf" or "nan" (which
    // toDouble would take).
    bool digits = false;
    bool bad = false;
    int points = 0;
    for (QChar c : number) {
        if (c >= u'0' && c <= u'9')
            digits = true;
        else if (c == u'.')
            ++points;
        else
            bad = true;
    }
    if (!digits || bad || points > 1)
        return failed(Problem::Syntax, QStringLiteral("'%1' is not a duration: %2").arg(t, durationGrammar(bareUnitNs)));
    if (unit == Duration::UnitRequired)
        return failed(Problem::UnitMissing,
                      QStringLiteral("'%1' has no unit: expected ns, us, ms, s, min or h after the number").arg(t));
    const double value = number.toDouble() * double(unit);
    if (!std::isfinite(value) || value > double(Duration::Year))
        return failed(Problem::TooLong, QStringLiteral("'%1' is too long: at most a year").arg(t));
    DurationResult result;
    result.ns = qint64(std::llround(value));
    result.problem = Problem::None;
    return result;
}

DurationListResult parseDurationList(QStringView text, qint64 bareUnitNs)
{
    DurationListResult result;
    const QList<QStringView> items = text.split(u',');
    for (qsizetype i = 0; i < items.size(); ++i) {
        const DurationResult d = parseDuration(items.at(i), bareUnitNs);
        if (!d.ok()) {
            result.error = items.at(i).trimmed().isEmpty()
                               ? QStringLiteral("item %1 of '%2' is empty: expected durations separated by commas "
                                                "(e.g. 100,200,300ms)")
                                     .arg(i + 1)
                                     .arg(text)
                               : QStringLiteral("item %1: %2").arg(i + 1).arg(d.error);
            result.ns.clear();
            return result;
        }
        result.ns.append(d.ns);
    }
    result.ok = true;
    return result;
}

QString formatDuration(qint64 ns)
{
    if (ns == 0)
        return QStringLiteral("0 ms");
    const double v = double(ns);
    if (ns < Duration::Microsecond)
        return QStringLiteral("%1 ns").arg(ns);
    if (ns < Duration::Millisecond)
        return trimmedDecimals(v / 1e3) + QStringLiteral(" µs");
    if (ns < Duration::Second)
        return trimmedDecimals(v / 1e6) + QStringLiteral(" ms");
    if (ns < Duration::Minute)
        return trimmedDecimals(v / 1e9) + QStringLiteral(" s");
    if (ns < Duration::Hour)
        return trimmedDecimals(v / 6e10) + QStringLiteral(" min");
    return trimmedDecimals(v / 3.6e12) + QStringLiteral(" h");
}

} // namespace mbscope
