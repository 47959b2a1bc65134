#include "watchfactory.h"

#include "protocol/adubuilder.h"

#include <QtCore/QRegularExpression>

#include <algorithm>

namespace mbscope {

namespace {

quint8 functionOf(SimTable table)
{
    switch (table) {
    case SimTable::Coils: return 1;
    case SimTable::DiscreteInputs: return 2;
    case SimTable::InputRegisters: return 4;
    case SimTable::HoldingRegisters: break;
    }
    return 3;
}

QString tableWord(quint8 function)
{
    switch (function) {
    case 1: return QStringLiteral("coils");
    case 2: return QStringLiteral("inputs");
    case 4: return QStringLiteral("input");
    case 0x18: return QStringLiteral("fifo");
    default: break;
    }
    return QStringLiteral("holding");
}

// The name of an entry's value i: an entry named as a range of the device's own names
// ("%MW0-%MW7999" or "T1-8", one name per value) names each value ("%MW17", "T3"); any other name of several
// values is indexed ("results[3]").
QString valueName(const TableEntry &entry, int i)
{
    const int values = entry.valueCount();
    if (values == 1)
        return entry.name;
    static const QRegularExpression range(QStringLiteral("^(.*?)(\\d+)\\s*-\\s*(.*?)(\\d+)$"));
    const QRegularExpressionMatch m = range.match(entry.name);
    if (m.hasMatch() && (m.captured(3).isEmpty() || m.captured(1) == m.captured(3))) {
        const qint64 first = m.captured(2).toLongLong();
        const qint64 last = m.captured(4).toLongLong();
        if (last - first + 1 == values)
            return m.captured(1) + QString::number(first + i);
    }
    return QStringLiteral("%1[%2]").arg(entry.name).arg(i);
}

// The points of values first..first+count-1 of entry.
QList<WatchPoint> pointsOf(const TableEntry &entry, int first, int count)
{
    QList<WatchPoint> points;
    const int width = entry.width();
    for (int i = first; i < first + count; ++i) {
        WatchPoint point;
        point.address = quint16(entry.address + i * width);
        point.name = valueName(entry, i);
        point.description = entry.description;
        point.format = entry.format;
        point.scale = entry.scale;
        point.offset = entry.offset;
        point.unit = entry.unit;
        point.writable = entry.writable
            && (entry.table == SimTable::Coils || entry.table == SimTable::HoldingRegisters);
        points.append(point);
    }
    return points;
}

} // namespace

QString WatchFactory::describeBlock(quint8 function, quint16 address, quint16 quantity)
{
    return QStringLiteral("%1 0x%2 x%3").arg(tableWord(function), QString::number(address, 16).rightJustified(4, QLatin1Char('0')).toUpper()).arg(quantity);
}

QString WatchFactory::uniqueName(const QString &base, const QStringList &taken)
{
    const QString stem = base.trimmed().isEmpty() ? QStringLiteral("watch") : base.trimmed();
    if (!taken.contains(stem))
        return stem;
    for (int n = 2;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(stem).arg(n);
        if (!taken.contains(candidate))
            return candidate;
    }
}

WatchFromRequest WatchFactory::fromRequest(const QByteArray &adu, Framing framing, const QString &target,
                                           qint64 intervalMs, const QStringList &taken)
{
    WatchFromRequest result;
    if (adu.isEmpty()) {
        result.error = tr("The composer holds no request: build a read (01-04) first.");
        return result;
    }
    const AduParts parts = AduBuilder::parse(adu, framing);
    if (!parts.error.isEmpty() || parts.pdu.isEmpty()) {
        result.error = tr("The composer's request cannot be read: %1").arg(parts.error);
        return result;
    }
    const QByteArray &pdu = parts.pdu;
    const quint8 function = quint8(pdu.at(0));
    const bool read = function >= 1 && function <= 4;
    if (!read && function != 0x18) {
        result.error = tr("The composer's request is function 0x%1: a watch reads (01-04, or the FIFO 18).")
                           .arg(QString::number(function, 16).rightJustified(2, QLatin1Char('0')).toUpper());
        return result;
    }
    if (pdu.size() < (read ? 5 : 3)) {
        result.error = tr("The composer's request is %1 bytes long: a read needs its address and quantity.").arg(pdu.size());
        return result;
    }
    WatchDefinition &watch = result.watch;
    watch.target = target;
    // A PDU alone names no unit: the bar's unit is what the composer would send it to.
    watch.unit = parts.unitId == 0 && framing == Framing::Pdu ? 1 : parts.unitId;
    watch.function = function;
    watch.address = quint16((quint8(pdu.at(1)) << 8) | quint8(pdu.at(2)));
    watch.quantity = read ? quint16((quint8(pdu.at(3)) << 8) | quint8(pdu.at(4))) : 31;
    const int limit = function <= 2 ? kMaxBits : kMaxRegisters;
    if (watch.quantity < 1 || watch.quantity > limit) {
        result.error = tr("The composer's request reads %1 values: a watch reads 1 to %2.").arg(watch.quantity).arg(limit);
        return result;
    }
    watch.intervalMs = intervalMs;
    watch.name = uniqueName(QStringLiteral("unit %1 %2").arg(watch.unit).arg(describeBlock(function, watch.address, watch.quantity)),
                            taken);
    return result;
}

QList<WatchDefinition> WatchFactory::fromProfile(const DeviceProfile &profile, quint8 unitId, const QString &target,
                                                 qint64 intervalMs, const QStringList &taken)
{
    QList<WatchDefinition> watches;
    const UnitProfile *unit = profile.unit(unitId);
    if (!unit)
        return watches;
    QStringList names = taken;
    for (SimTable table : {SimTable::HoldingRegisters, SimTable::InputRegisters, SimTable::Coils, SimTable::DiscreteInputs}) {
        QList<TableEntry> entries = unit->entriesOf(table);
        std::sort(entries.begin(), entries.end(), [](const TableEntry &a, const TableEntry &b) { return a.address < b.address; });
        // The device's own largest read (the profile's limits.maxQuantity, as the map or timing
        // scan records it) when it takes fewer than a request can hold: no watch asks more.
        int limit = isBitTable(table) ? kMaxBits : kMaxRegisters;
        if (const int device = profile.limits.maxQuantity.value(functionOf(table), 0); device > 0)
            limit = qMin(limit, device);
        WatchDefinition current;
        auto flush = [&] {
            if (current.points.isEmpty())
                return;
            current.quantity = quint16(current.quantity);
            current.name = uniqueName(QStringLiteral("%1 %2").arg(profile.name, describeBlock(current.function, current.address,
                                                                                             current.quantity)),
                                      names);
            current.profileBlock = QStringLiteral("%1/unit %2/%3").arg(profile.name).arg(unitId).arg(
                describeBlock(current.function, current.address, current.quantity));
            names.append(current.name);
            watches.append(current);
            current = WatchDefinition();
        };
        for (const TableEntry &entry : entries) {
            // An entry longer than a read (the M221's 8000 %MW) becomes consecutive watches, each
            // one read; its values keep their names whichever watch they land in.
            const int width = entry.width();
            const int perPiece = qMax(1, limit / width); // a value wider than the device's limit is still read whole
            for (int first = 0; first < entry.valueCount(); first += perPiece) {
                const int count = qMin(perPiece, entry.valueCount() - first);
                const int address = entry.address + first * width;
                const int end = address + count * width;
                const bool fits = !current.points.isEmpty() && address - (current.address + current.quantity) <= kMaxGap
                    && end - current.address <= limit;
                if (!fits) {
                    flush();
                    current.target = target;
                    current.unit = unitId;
                    current.function = functionOf(table);
                    current.address = quint16(address);
                    current.quantity = 0;
                    current.intervalMs = intervalMs;
                }
                current.quantity = quint16(end - current.address);
                current.points.append(pointsOf(entry, first, count));
            }
        }
        flush();
    }
    return watches;
}

} // namespace mbscope
