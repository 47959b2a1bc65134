#include "profiledraft.h"

#include "profile/simtable.h"
#include "protocol/functionspec.h"

#include <QtCore/QDateTime>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

#include <algorithm>

namespace mbscope {

namespace {

QString hexCode(int code)
{
    return QStringLiteral("0x%1").arg(code, 2, 16, QLatin1Char('0')).toUpper().replace(QLatin1String("0X"), QLatin1String("0x"));
}

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
        codes.append(hexCode(f));

    QJsonObject unit{{QStringLiteral("id"), int(map.unit)},
                     {QStringLiteral("name"), QStringLiteral("unit %1").arg(map.unit)},
                     {QStringLiteral("functions"), codes},
                     {QStringLiteral("tables"), tables}};
    if (map.exceptionStatus >= 0)
        unit.insert(QStringLiteral("exceptionStatus"), map.exceptionStatus);

    // The device's limits the scan measured: a read function that took fewer than the
    // specification allows (exception 03 above it) is recorded, so that what polls the clone or
    // exports its map (export-map's blocks) asks no more.
    QJsonObject maxQuantity;
    for (const TableMap &t : map.tables) {
        if (t.supported && t.maxQuantity > 0 && t.maxQuantity < QuantityLimits::maxQuantity(t.function))
            maxQuantity.insert(hexCode(t.function), t.maxQuantity);
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

} // namespace mbscope
