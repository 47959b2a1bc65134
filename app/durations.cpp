#include "durations.h"

#include <cmath>

namespace mbscope::app {

namespace {

struct Unit {
    const char16_t *suffix;
    qint64 ns;
};

// Longest suffixes first: "ms" must not be read as "s", nor "min" as "in" anything.
constexpr Unit kUnits[] = {
    {u"min", 60'000'000'000LL}, {u"ns", 1}, {u"us", 1000}, {u"\u00b5s", 1000}, {u"ms", 1'000'000},
    {u"s", 1'000'000'000LL},    {u"h", 3'600'000'000'000LL},
};

constexpr qint64 kYearNs = 366LL * 24 * 3'600'000'000'000LL;

QString expected()
{
    return QStringLiteral("expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, 1s, 60s; "
                          "a bare number is milliseconds)");
}

QString trimmedDecimals(double value)
{
    QString text = QString::number(value, 'f', 3);
    while (text.contains(QLatin1Char('.')) && (text.endsWith(QLatin1Char('0')) || text.endsWith(QLatin1Char('.'))))
        text.chop(1);
    return text;
}

} // namespace

DurationResult parseDuration(QStringView text)
{
    DurationResult result;
    const QStringView t = text.trimmed();
    qint64 unit = 1'000'000;
    QStringView number = t;
    for (const Unit &u : kUnits) {
        if (t.endsWith(QStringView(u.suffix), Qt::CaseInsensitive)) {
            unit = u.ns;
            number = t.chopped(QStringView(u.suffix).size()).trimmed();
            break;
        }
    }
    if (number.startsWith(u'-')) {
        result.error = QStringLiteral("'%1' is a negative duration: a duration is 0 or more").arg(t);
        return result;
    }
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
    if (!digits || bad || points > 1) {
        result.error = QStringLiteral("'%1' is not a duration: %2").arg(t, expected());
        return result;
    }
    const double value = number.toDouble() * double(unit);
    if (!std::isfinite(value) || value > double(kYearNs)) {
        result.error = QStringLiteral("'%1' is too long: at most a year").arg(t);
        return result;
    }
    result.ns = qint64(std::llround(value));
    result.ok = true;
    return result;
}

DurationListResult parseDurationList(QStringView text)
{
    DurationListResult result;
    const QList<QStringView> items = text.split(u',');
    for (qsizetype i = 0; i < items.size(); ++i) {
        const DurationResult d = parseDuration(items.at(i));
        if (!d.ok) {
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
    if (ns < 1000)
        return QStringLiteral("%1 ns").arg(ns);
    if (ns < 1'000'000)
        return trimmedDecimals(v / 1e3) + QStringLiteral(" µs");
    if (ns < 1'000'000'000LL)
        return trimmedDecimals(v / 1e6) + QStringLiteral(" ms");
    if (ns < 60'000'000'000LL)
        return trimmedDecimals(v / 1e9) + QStringLiteral(" s");
    if (ns < 3'600'000'000'000LL)
        return trimmedDecimals(v / 6e10) + QStringLiteral(" min");
    return trimmedDecimals(v / 3.6e12) + QStringLiteral(" h");
}

} // namespace mbscope::app
