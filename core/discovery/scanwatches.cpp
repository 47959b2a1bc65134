#include "scanwatches.h"

#include "registermap.h"
#include "unitscansettings.h"

#include "profile/simtable.h"
#include "protocol/functionspec.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

namespace mbscope {

namespace {

WatchDefinition watch(const QString &target, quint8 unit, quint8 function, quint16 address, quint16 quantity)
{
    WatchDefinition w;
    w.name = QStringLiteral("unit%1-%2-%3").arg(unit).arg(QLatin1String(simTableKey(readTable(function)))).arg(address);
    w.target = target;
    w.unit = unit;
    w.function = function;
    w.address = address;
    w.quantity = quantity;
    w.profileBlock = QStringLiteral("scan/unit %1/%2 %3").arg(unit).arg(QLatin1String(simTableKey(readTable(function)))).arg(address);
    return w;
}

} // namespace

QList<WatchDefinition> ScanWatches::fromProbe(const UnitScanSettings &settings, const UnitProbe &probe)
{
    if (probe.kind != UnitProbeKind::Answers)
        return {};
    return {watch(settings.url.toString(), probe.unit, settings.function, settings.address, settings.quantity)};
}

QList<WatchDefinition> ScanWatches::fromMap(const QString &target, const RegisterMap &map)
{
    QList<WatchDefinition> out;
    for (const TableMap &t : map.tables) {
        const int most = qMax(1, t.maxQuantity > 0 ? t.maxQuantity : QuantityLimits::maxQuantity(quint8(t.function)));
        for (const MapBlock &b : t.blocks) {
            for (int at = 0; at < b.count(); at += most)
                out.append(watch(target, map.unit, t.function, quint16(b.address + at), quint16(qMin(most, b.count() - at))));
        }
    }
    return out;
}

QByteArray ScanWatches::toJson(const QList<WatchDefinition> &watches)
{
    QJsonArray array;
    for (const WatchDefinition &w : watches) {
        array.append(QJsonObject{
            {QStringLiteral("name"), w.name},
            {QStringLiteral("target"), w.target},
            {QStringLiteral("unit"), int(w.unit)},
            {QStringLiteral("function"), int(w.function)},
            {QStringLiteral("address"), int(w.address)},
            {QStringLiteral("quantity"), int(w.quantity)},
            {QStringLiteral("intervalMs"), double(w.intervalMs)},
            {QStringLiteral("profileBlock"), w.profileBlock},
        });
    }
    return QJsonDocument(array).toJson(QJsonDocument::Indented);
}

} // namespace mbscope
