#include "conformancesettings.h"

#include "profile/deviceprofile.h"
#include "profile/simtable.h"
#include "sim/simunit.h"

namespace mbscope {

namespace {

std::optional<int> address(QStringView text)
{
    bool ok = false;
    const int value = text.startsWith(u"0x") || text.startsWith(u"0X") ? text.mid(2).toInt(&ok, 16) : text.toInt(&ok, 10);
    if (!ok || value < 0 || value > 0xFFFF)
        return std::nullopt;
    return value;
}

} // namespace

std::optional<TableRange> TableRange::parse(const QString &text, QString *error)
{
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    const auto fail = [&](const QString &why) -> std::optional<TableRange> {
        *error = QStringLiteral("'%1': %2 (expected TABLE:ADDRESS or TABLE:FIRST-LAST, TABLE one of coils, discrete, "
                                "input, holding; e.g. holding:0-9)")
                     .arg(text, why);
        return std::nullopt;
    };
    if (colon < 0)
        return fail(QStringLiteral("no ':' between the table and the address"));
    const std::optional<SimTable> table = simTableFromKey(QStringView(text).left(colon));
    if (!table)
        return fail(QStringLiteral("'%1' is not a table").arg(text.left(colon)));
    const QStringView rest = QStringView(text).mid(colon + 1);
    const qsizetype dash = rest.indexOf(QLatin1Char('-'));
    const std::optional<int> first = address(dash < 0 ? rest : rest.left(dash));
    const std::optional<int> last = dash < 0 ? first : address(rest.mid(dash + 1));
    if (!first)
        return fail(QStringLiteral("'%1' is not an address 0-65535").arg(dash < 0 ? rest : rest.left(dash)));
    if (!last)
        return fail(QStringLiteral("'%1' is not an address 0-65535").arg(rest.mid(dash + 1)));
    if (*last < *first)
        return fail(QStringLiteral("the last address %1 is before the first %2").arg(*last).arg(*first));
    return TableRange{*table, *first, *last};
}

QString TableRange::toString() const
{
    const QString key = QLatin1String(simTableKey(table));
    return first == last ? QStringLiteral("%1:%2").arg(key).arg(first) : QStringLiteral("%1:%2-%3").arg(key).arg(first).arg(last);
}

bool ConformanceSettings::applyProfile(const DeviceProfile &profile, QString *error)
{
    const UnitProfile *unitProfile = profile.unit(unit);
    if (!unitProfile) {
        *error = QStringLiteral("profile %1 has no unit %2").arg(profile.name).arg(unit);
        return false;
    }
    for (int t = 0; t < SimTableCount; ++t) {
        const QList<TableEntry> entries = unitProfile->entriesOf(SimTable(t));
        if (entries.isEmpty())
            continue;
        if (readable[t] < 0)
            readable[t] = entries.constFirst().address;
        if (missing[t] < 0) {
            // The first address after the first block of adjacent entries.
            int end = entries.constFirst().end();
            for (const TableEntry &e : entries) {
                if (e.address == end)
                    end = e.end();
            }
            if (end <= 0xFFFF)
                missing[t] = end;
        }
    }
    promised = true;
    promisedFunctions = unitProfile->functions.isEmpty() ? SimUnit::implementedFunctions() : unitProfile->functions;
    promiseSource = QStringLiteral("profile %1 (unit %2)").arg(profile.name).arg(unitProfile->id);
    return true;
}

const TableRange *ConformanceSettings::writableIn(SimTable table) const
{
    for (const TableRange &r : writable) {
        if (r.table == table)
            return &r;
    }
    return nullptr;
}

bool ConformanceSettings::selected(const QString &checkId) const
{
    if (only.isEmpty())
        return true;
    for (const QString &prefix : only) {
        if (checkId.startsWith(prefix))
            return true;
    }
    return false;
}

} // namespace mbscope
