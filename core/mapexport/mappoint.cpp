#include "mappoint.h"

#include "profile/simtable.h"
#include "profile/scaledvalue.h"
#include "protocol/registervalue.h"

#include <QtCore/QSet>

#include <algorithm>
#include <cmath>

namespace mbscope {

quint8 MapPoint::readFunction() const
{
    switch (table) {
    case SimTable::Coils: return 0x01;
    case SimTable::DiscreteInputs: return 0x02;
    case SimTable::HoldingRegisters: return 0x03;
    case SimTable::InputRegisters: return 0x04;
    }
    return 0x03;
}

QString MapPoint::tableKey() const
{
    return QLatin1String(simTableKey(table));
}

bool MapPoint::isNotImplemented(std::span<const quint16> words) const
{
    if (isBit() || isString() || int(words.size()) < registers || (!notImplemented && !notImplementedNaN))
        return false;
    const RegisterValueResult v = RegisterValue::fromRegisters(words, format);
    if (!v.ok)
        return false;
    return (notImplementedNaN && v.value.isNaN()) || (notImplemented && v.value.bits() == *notImplemented);
}

std::optional<double> MapPoint::decode(std::span<const quint16> words) const
{
    if (words.empty() || isString())
        return std::nullopt;
    if (isBit())
        return words[0] ? 1.0 : 0.0;
    if (int(words.size()) < registers || isNotImplemented(words))
        return std::nullopt;
    return ScaledValue{format, scale, offset}.decode(words.first(size_t(registers)));
}

QString MapPoint::decodeText(std::span<const quint16> words) const
{
    QString text = RegisterValue::asciiText(words.first(std::min<size_t>(words.size(), size_t(registers))),
                                            format.isByteSwapped());
    text.truncate(stringLength);
    while (!text.isEmpty() && (text.endsWith(QChar(0)) || (spacePadded && text.endsWith(QLatin1Char(' ')))))
        text.chop(1);
    return text;
}

QString MapPoint::slug(const QString &text)
{
    QString out;
    for (const QChar c : text.toLower()) {
        if ((c >= u'a' && c <= u'z') || (c >= u'0' && c <= u'9'))
            out.append(c);
        else if (!out.isEmpty() && !out.endsWith(QLatin1Char('_')))
            out.append(QLatin1Char('_'));
    }
    while (out.endsWith(QLatin1Char('_')))
        out.chop(1);
    if (!out.isEmpty() && out.at(0).isDigit())
        out.prepend(QLatin1Char('v'));
    return out;
}

QList<MapPoint> MapPoint::fromProfile(const DeviceProfile &profile, std::optional<quint8> unitId)
{
    QList<MapPoint> points;
    QSet<QString> taken;
    const bool severalUnits = !unitId && profile.units.size() > 1;
    for (const UnitProfile &unit : profile.units) {
        if (unitId && unit.id != *unitId)
            continue;
        for (const TableEntry &e : unit.entries) {
            if (e.kind == ValueKind::Reserved)
                continue;
            const int width = e.isString() ? e.count : e.width();
            const int n = e.isString() ? 1 : e.valueCount();
            for (int i = 0; i < n; ++i) {
                MapPoint p;
                p.unitId = unit.id;
                p.table = e.table;
                p.address = quint16(e.address + i * width);
                p.registers = width;
                p.format = e.format;
                p.description = e.description;
                p.unit = e.unit;
                p.scale = e.scale;
                p.offset = e.offset;
                p.kind = e.kind;
                p.writable = e.writable && (e.table == SimTable::Coils || e.table == SimTable::HoldingRegisters);
                p.min = e.min;
                p.max = e.max;
                // An ascii entry without a length is two characters a register, each its own value.
                p.stringLength = e.isString() ? e.stringLength : (e.format.type() == RegisterType::Ascii ? 2 : 0);
                p.spacePadded = e.spacePadded;
                p.bitNames = e.bitNames;
                p.enumNames = e.enumNames;
                p.notImplemented = e.notImplemented;
                p.notImplementedNaN = e.notImplementedNaN;
                p.scaleRegister = e.scaleRegister;
                const QString base = e.name.isEmpty() ? QStringLiteral("%1 %2").arg(p.tableKey()).arg(e.address) : e.name;
                p.label = n > 1 ? QStringLiteral("%1 %2").arg(base).arg(i + 1) : base;
                QString name = slug(p.label);
                if (name.isEmpty())
                    name = slug(QStringLiteral("%1 %2").arg(p.tableKey()).arg(p.address));
                if (severalUnits)
                    name = QStringLiteral("u%1_%2").arg(unit.id).arg(name);
                QString unique = name;
                for (int k = 2; taken.contains(unique); ++k)
                    unique = QStringLiteral("%1_%2").arg(name).arg(k);
                taken.insert(unique);
                p.name = unique;
                points.append(p);
            }
        }
    }
    return points;
}

QString MapPoint::numberType() const
{
    switch (format.type()) {
    case RegisterType::Int16: return QStringLiteral("int16");
    case RegisterType::UInt32: return QStringLiteral("uint32");
    case RegisterType::Int32: return QStringLiteral("int32");
    case RegisterType::UInt64: return QStringLiteral("uint64");
    case RegisterType::Int64: return QStringLiteral("int64");
    case RegisterType::Float32: return QStringLiteral("float32");
    case RegisterType::Float64: return QStringLiteral("float64");
    default: return QStringLiteral("uint16");
    }
}

QString MapPoint::yamlQuoted(const QString &s)
{
    QString q = s;
    q.replace(QLatin1String("\\"), QLatin1String("\\\\")).replace(QLatin1String("\""), QLatin1String("\\\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

} // namespace mbscope
