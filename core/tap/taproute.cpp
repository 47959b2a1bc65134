#include "taproute.h"

#include <QtCore/QStringList>

namespace mbscope {

namespace {

// One unit id 0-255, or nullopt with *error set.
std::optional<int> unitNumber(QStringView text, QString *error)
{
    bool ok = false;
    const int value = text.trimmed().toInt(&ok, 10);
    if (!ok) {
        *error = QStringLiteral("'%1' is not a unit id (0-255)").arg(text);
        return std::nullopt;
    }
    if (value < 0 || value > 255) {
        *error = QStringLiteral("unit %1 is outside 0-255").arg(value);
        return std::nullopt;
    }
    return value;
}

// Takes retries=N off a URL's query (0-100); the URL without it. *error set when N is no count.
QString takeRetries(QStringView url, int *retries, QString *error)
{
    const qsizetype question = url.indexOf(QLatin1Char('?'));
    if (question < 0)
        return url.toString();
    QStringList kept;
    for (const QStringView part : url.sliced(question + 1).split(QLatin1Char('&'))) {
        if (!part.startsWith(QLatin1String("retries="))) {
            kept.append(part.toString());
            continue;
        }
        bool ok = false;
        const int n = part.sliced(8).toInt(&ok, 10);
        if (!ok || n < 0 || n > 100) {
            *error = QStringLiteral("retries '%1' is not a count from 0 to 100 (the further attempts of a read the tap makes)")
                         .arg(part.sliced(8));
            return {};
        }
        *retries = n;
    }
    QString rest = url.first(question).toString();
    if (!kept.isEmpty())
        rest += QLatin1Char('?') + kept.join(QLatin1Char('&'));
    return rest;
}

} // namespace

quint8 TapRoute::deviceUnitFor(int unit) const
{
    return deviceUnit < 0 ? quint8(unit) : quint8(deviceUnit + (unit - firstUnit));
}

QString TapRoute::describe() const
{
    QString units;
    if (firstUnit == 0 && lastUnit == 255)
        units = QStringLiteral("every unit");
    else if (firstUnit == lastUnit)
        units = QStringLiteral("unit %1").arg(firstUnit);
    else
        units = QStringLiteral("units %1-%2").arg(firstUnit).arg(lastUnit);
    if (renumbers()) {
        units += firstUnit == lastUnit ? QStringLiteral(" as %1").arg(deviceUnit)
                                       : QStringLiteral(" as %1-%2").arg(deviceUnit).arg(deviceUnit + lastUnit - firstUnit);
    }
    return units + QStringLiteral(" -> ") + target.toString()
         + (retries >= 0 ? QStringLiteral(" (retries %1)").arg(retries) : QString());
}

TapRoute::Result TapRoute::parseTarget(QStringView url)
{
    Result result;
    TapRoute route;
    QString error;
    const QString rest = takeRetries(url.trimmed(), &route.retries, &error);
    if (!error.isEmpty()) {
        result.error = error;
        return result;
    }
    const LinkUrl::Result parsed = LinkUrl::parse(rest);
    if (!parsed.url) {
        // The link's options are listed there; the tap takes one more of its own.
        result.error = parsed.error.startsWith(QLatin1String("unknown option"))
                           ? parsed.error + QStringLiteral("; and, on the tap's routes and target, retries")
                           : parsed.error;
        return result;
    }
    route.target = *parsed.url;
    if (route.target.delimited.enabled) {
        result.error = QStringLiteral("the tap forwards Modbus; framing=delimited has no unit ids to route");
        return result;
    }
    result.route = route;
    return result;
}

TapRoute::Result TapRoute::parse(QStringView text)
{
    Result result;
    const auto fail = [&](const QString &why) {
        result.error = QStringLiteral("'%1': %2").arg(text, why);
        return result;
    };
    const qsizetype equals = text.indexOf(QLatin1Char('='));
    if (equals <= 0)
        return fail(QStringLiteral("expected UNITS[:DEVICE_UNIT]=URL, e.g. 1-10=rtu-tcp://127.0.0.1:4001 or 1:17=tcp://10.0.0.5:502"));
    QStringView units = text.first(equals).trimmed();
    const QStringView url = text.sliced(equals + 1).trimmed();
    TapRoute route;
    QString error;
    if (const qsizetype colon = units.indexOf(QLatin1Char(':')); colon >= 0) {
        const std::optional<int> device = unitNumber(units.sliced(colon + 1), &error);
        if (!device)
            return fail(QStringLiteral("device unit: ") + error);
        route.deviceUnit = *device;
        units = units.first(colon);
    }
    const qsizetype dash = units.indexOf(QLatin1Char('-'));
    const std::optional<int> first = unitNumber(dash < 0 ? units : units.first(dash), &error);
    if (!first)
        return fail(error);
    const std::optional<int> last = dash < 0 ? first : unitNumber(units.sliced(dash + 1), &error);
    if (!last)
        return fail(error);
    if (*last < *first)
        return fail(QStringLiteral("the range %1-%2 runs backwards").arg(*first).arg(*last));
    route.firstUnit = *first;
    route.lastUnit = *last;
    if (route.deviceUnit >= 0 && route.deviceUnit + (route.lastUnit - route.firstUnit) > 255)
        return fail(QStringLiteral("units %1-%2 renumbered from %3 run past 255").arg(*first).arg(*last).arg(route.deviceUnit));
    const Result target = parseTarget(url);
    if (!target.route)
        return fail(target.error);
    route.target = target.route->target;
    route.retries = target.route->retries;
    result.route = route;
    return result;
}

} // namespace mbscope
