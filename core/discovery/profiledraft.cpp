#include "profiledraft.h"

#include "profile/simtable.h"
#include "profile/devicelimits.h"
#include "protocol/functionspec.h"

#include <QtCore/QDateTime>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QSet>
#include <QtCore/QJsonObject>

#include <algorithm>

#include <optional>

namespace mbscope {

namespace {

// Functions the simulator implements (docs/profiles.md, units: functions): a draft names no other.
bool simulatorImplements(quint8 f)
{
    return (f >= 0x01 && f <= 0x08) || f == 0x0B || f == 0x0C || (f >= 0x0F && f <= 0x11)
        || (f >= 0x14 && f <= 0x18) || f == 0x2B;
}

} // namespace

QByteArray ProfileDraft::toJson(const RegisterMap &map, const QString &name, const QString &source)
{
    QList<int> functions;
    QJsonObject tables;
    for (const TableMap &t : map.tables) {
        if (!t.supported)
            continue;
        functions.append(t.function);
        QJsonArray entries;
        const bool bits = t.function <= 2;
        for (const MapBlock &b : t.blocks) {
            QJsonArray values;
            for (const quint16 v : b.values)
                values.append(bits ? QJsonValue(v != 0) : QJsonValue(int(v)));
            QJsonObject entry{{QStringLiteral("address"), int(b.address)},
                              {QStringLiteral("count"), b.count()},
                              {QStringLiteral("values"), values}};
            entries.append(entry);
        }
        if (!entries.isEmpty())
            tables.insert(QLatin1String(simTableKey(readTable(t.function))), entries);
    }
    for (const FunctionSupport &s : map.functions) {
        if (s.known() && simulatorImplements(s.function) && !functions.contains(s.function))
            functions.append(s.function);
    }
    std::sort(functions.begin(), functions.end());
    QJsonArray codes;
    for (const int f : std::as_const(functions))
        codes.append(DeviceLimits::functionKey(f));

    QJsonObject unit{{QStringLiteral("id"), int(map.unit)},
                     {QStringLiteral("name"), QStringLiteral("unit %1").arg(map.unit)},
                     {QStringLiteral("functions"), codes},
                     {QStringLiteral("tables"), tables}};
    if (map.exceptionStatus >= 0)
        unit.insert(QStringLiteral("exceptionStatus"), map.exceptionStatus);
    // Measured: an address between two blocks was refused with 02. (A device answering zeros
    // there shows one block holding zeros: the scan cannot tell those from registers at 0.)
    if (std::any_of(map.tables.cbegin(), map.tables.cend(), [](const TableMap &t) { return t.refusesGapReads(); }))
        unit.insert(QStringLiteral("gapReads"), QStringLiteral("exception"));

    // The device's limits the scan measured: a read function that took fewer than the
    // specification allows (exception 03 above it) is recorded, so that what polls the clone or
    // exports its map (export-map's blocks) asks no more.
    QJsonObject maxQuantity;
    for (const TableMap &t : map.tables) {
        if (t.supported && t.maxQuantity > 0 && t.maxQuantity < QuantityLimits::maxQuantity(t.function))
            maxQuantity.insert(DeviceLimits::functionKey(t.function), t.maxQuantity);
    }
    QJsonObject profile{
        {QStringLiteral("name"), name},
        {QStringLiteral("description"),
         QStringLiteral("Draft from mbscope scan --map of %1, unit %2, on %3: the addresses found and the values read "
                        "then; names, types and scaling are yours to add.")
             .arg(source)
             .arg(map.unit)
             .arg(QDateTime::currentDateTimeUtc().toString(Qt::ISODate))},
        {QStringLiteral("units"), QJsonArray{unit}},
    };
    if (!maxQuantity.isEmpty())
        profile.insert(QStringLiteral("limits"), QJsonObject{{QStringLiteral("maxQuantity"), maxQuantity}});
    return QJsonDocument(profile).toJson(QJsonDocument::Indented);
}

QString ProfileDraft::describeLimits(const QJsonObject &limits)
{
    QStringList found;
    QStringList none;
    const auto number = [](const QJsonValue &v) { return QString::number(v.toDouble()); };
    for (auto it = limits.begin(); it != limits.end(); ++it) {
        if (it.key() == QLatin1String("maxQuantity")) {
            const QJsonObject q = it.value().toObject();
            for (auto f = q.begin(); f != q.end(); ++f)
                (f.value().isNull() ? none : found)
                    .append(f.value().isNull() ? QStringLiteral("maxQuantity %1").arg(f.key())
                                               : QStringLiteral("maxQuantity %1 %2").arg(f.key(), number(f.value())));
        } else if (it.value().isNull()) {
            none.append(it.key());
        } else {
            found.append(it.value().isBool() ? it.key()
                                             : QStringLiteral("%1 %2").arg(it.key(), it.value().isString() ? it.value().toString() : number(it.value())));
        }
    }
    QString text = found.join(QStringLiteral(", "));
    if (!none.isEmpty())
        text += (text.isEmpty() ? QString() : QStringLiteral("; ")) + QStringLiteral("no limit seen: ") + none.join(QStringLiteral(", "));
    return text.isEmpty() ? QStringLiteral("nothing measured") : text;
}

namespace {

// A profile's text as a JSON object; nullopt with *error saying why not.
std::optional<QJsonObject> profileObject(const QByteArray &profile, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(profile, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *error = QStringLiteral("not JSON: %1 at offset %2").arg(parseError.errorString()).arg(parseError.offset);
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *error = QStringLiteral("not a profile: expected a JSON object");
        return std::nullopt;
    }
    return doc.object();
}

// "1, 3, 5-247": runs of consecutive ids as ranges (a full scan listed 245 ids one by one).
QString idList(const QList<int> &ids)
{
    QStringList out;
    for (qsizetype i = 0; i < ids.size();) {
        qsizetype j = i;
        while (j + 1 < ids.size() && ids.at(j + 1) == ids.at(j) + 1)
            ++j;
        out.append(j - i >= 2 ? QStringLiteral("%1-%2").arg(ids.at(i)).arg(ids.at(j)) : QString::number(ids.at(i)));
        if (j - i == 1)
            out.append(QString::number(ids.at(j)));
        i = j + 1;
    }
    return out.join(QStringLiteral(", "));
}

} // namespace

QByteArray ProfileDraft::mergeUnits(const QByteArray &profile, const QList<UnitProbe> &probes, QString *said, QString *error)
{
    const std::optional<QJsonObject> parsed = profileObject(profile, error);
    if (!parsed)
        return {};
    QJsonObject root = *parsed;
    QJsonArray units = root.value(QLatin1String("units")).toArray();
    QSet<int> known;
    for (const QJsonValue &u : std::as_const(units))
        known.insert(u.toObject().value(QLatin1String("id")).toInt(-1));
    QList<int> present;
    QList<int> absent;
    QSet<int> absentKinds;
    for (const UnitProbe &p : probes) {
        if (p.unit == 0 || p.unit >= 248)
            continue;
        if (p.isPresent()) {
            present.append(p.unit);
        } else {
            absent.append(p.unit);
            absentKinds.insert(int(p.kind));
        }
    }
    QStringList parts;
    if (UnitProbe::oneDeviceIgnoringUnitId(probes)) {
        root.insert(QStringLiteral("unknownUnit"), QStringLiteral("first"));
        parts.append(QStringLiteral("every id asked answered (%1 of 1-247): the device ignores the unit id: unknownUnit first, "
                                    "no unit added").arg(present.size()));
    } else {
        QList<int> added;
        for (const int id : std::as_const(present)) {
            if (!known.contains(id)) {
                units.append(QJsonObject{{QStringLiteral("id"), id}});
                added.append(id);
            }
        }
        parts.append(present.isEmpty() ? QStringLiteral("no unit answered")
                                       : QStringLiteral("units answering: %1 (%2 added)").arg(idList(present)).arg(added.size()));
        bool written = false;
        if (absentKinds.size() == 1) {
            const auto kind = UnitProbeKind(*absentKinds.cbegin());
            const QString policy = kind == UnitProbeKind::Silent                ? QStringLiteral("silent")
                                   : kind == UnitProbeKind::GatewayTargetFailed ? QStringLiteral("exception")
                                                                                : QString();
            if (!policy.isEmpty()) {
                root.insert(QStringLiteral("unknownUnit"), policy);
                parts.append(QStringLiteral("unknownUnit %1 (ids %2: %3)")
                                 .arg(policy, idList(absent), QString::fromLatin1(unitProbeKindName(kind))));
                written = true;
            }
        }
        if (!absent.isEmpty() && !written) {
            const QString why = absentKinds.size() > 1 ? QStringLiteral("the other ids got different answers")
                                                       : QStringLiteral("no profile setting gives what the other ids got");
            const QString kept = root.value(QLatin1String("unknownUnit")).toString();
            parts.append(kept.isEmpty() ? QStringLiteral("unknownUnit not written: %1").arg(why)
                                        : QStringLiteral("unknownUnit left as it was (%1): %2").arg(kept, why));
        }
        if (present.size() == int(probes.size()) && present.size() >= 3)
            parts.append(QStringLiteral("every id asked answered: a wider range tells real units from a device that ignores "
                                        "the unit id"));
    }
    root.insert(QStringLiteral("units"), units);
    *said = parts.join(QStringLiteral("; "));
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QByteArray ProfileDraft::mergeLimits(const QByteArray &profile, const QJsonObject &limits, const QMap<int, int> &answered,
                                     QString *said, QString *error)
{
    const std::optional<QJsonObject> parsed = profileObject(profile, error);
    if (!parsed)
        return {};
    QJsonObject root = *parsed;
    QJsonObject merged = root.value(QLatin1String("limits")).toObject();
    // The member a limit qualifies, gone with it.
    const auto companion = [](const QString &key) {
        return key == QLatin1String("minGapMs") ? QStringLiteral("tooSoon")
             : key == QLatin1String("maxClients") ? QStringLiteral("extraClients")
                                                   : QString();
    };
    // The profile may spell a function's code another way ("3", "0X03"): one key a function.
    const auto removeFunction = [](QJsonObject &quantities, const QString &canonical) {
        for (const QString &key : quantities.keys()) {
            if (const std::optional<int> code = DeviceLimits::parseFunctionKey(key); code && DeviceLimits::functionKey(*code) == canonical)
                quantities.remove(key);
        }
    };
    for (auto it = limits.begin(); it != limits.end(); ++it) {
        if (it.key() == QLatin1String("maxQuantity")) {
            QJsonObject quantities = merged.value(it.key()).toObject();
            const QJsonObject given = it.value().toObject();
            for (auto q = given.begin(); q != given.end(); ++q) {
                removeFunction(quantities, q.key());
                if (!q.value().isNull())
                    quantities.insert(q.key(), q.value());
            }
            if (quantities.isEmpty())
                merged.remove(it.key());
            else
                merged.insert(it.key(), quantities);
        } else if (it.value().isNull()) {
            merged.remove(it.key());
            if (const QString other = companion(it.key()); !other.isEmpty())
                merged.remove(other);
        } else {
            merged.insert(it.key(), it.value());
        }
    }
    QStringList disproved;
    QJsonObject quantities = merged.value(QLatin1String("maxQuantity")).toObject();
    for (auto a = answered.cbegin(); a != answered.cend(); ++a) {
        const QString canonical = DeviceLimits::functionKey(a.key());
        for (const QString &key : quantities.keys()) {
            const std::optional<int> code = DeviceLimits::parseFunctionKey(key);
            const int limit = quantities.value(key).toInt();
            if (code && DeviceLimits::functionKey(*code) == canonical && limit < a.value()) {
                disproved.append(QStringLiteral("maxQuantity %1 %2 removed (%3 were answered at once)").arg(canonical).arg(limit).arg(a.value()));
                removeFunction(quantities, canonical);
            }
        }
    }
    if (quantities.isEmpty())
        merged.remove(QStringLiteral("maxQuantity"));
    else
        merged.insert(QStringLiteral("maxQuantity"), quantities);
    if (merged.isEmpty())
        root.remove(QStringLiteral("limits"));
    else
        root.insert(QStringLiteral("limits"), merged);
    *said = describeLimits(limits);
    if (!disproved.isEmpty())
        *said += QStringLiteral("; ") + disproved.join(QStringLiteral("; "));
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

} // namespace mbscope
