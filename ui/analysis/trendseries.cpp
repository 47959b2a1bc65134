#include "trendseries.h"

#include "profile/scaledvalue.h"

#include <QtCore/QCoreApplication>

#include <span>

namespace mbscope {

namespace {

ModbusTable modbusTableOf(SimTable table)
{
    switch (table) {
    case SimTable::Coils: return ModbusTable::Coils;
    case SimTable::DiscreteInputs: return ModbusTable::DiscreteInputs;
    case SimTable::InputRegisters: return ModbusTable::InputRegisters;
    case SimTable::HoldingRegisters: return ModbusTable::HoldingRegisters;
    }
    return ModbusTable::HoldingRegisters;
}

bool isBits(ModbusTable table)
{
    return table == ModbusTable::Coils || table == ModbusTable::DiscreteInputs;
}

} // namespace

QString TrendSeries::label() const
{
    if (isWatchValue()) {
        const QString what = name.isEmpty()
            ? QCoreApplication::translate("mbscope::TrendSeries", "address %1").arg(ReadAnswer::addressText(address))
            : name;
        if (unit.isEmpty())
            return QCoreApplication::translate("mbscope::TrendSeries", "%1 \u203a %2").arg(watchName, what);
        return QCoreApplication::translate("mbscope::TrendSeries", "%1 \u203a %2 (%3)").arg(watchName, what, unit);
    }
    const QString reference = ReadAnswer::referenceText(ModiconReference(table, quint16(address)));
    if (name.isEmpty())
        return QCoreApplication::translate("mbscope::TrendSeries", "%1 (%2)").arg(reference, isBits(table) ? QCoreApplication::translate("mbscope::TrendSeries", "bit") : format.name());
    if (unit.isEmpty())
        return QCoreApplication::translate("mbscope::TrendSeries", "%1, %2").arg(name, reference);
    return QCoreApplication::translate("mbscope::TrendSeries", "%1, %2 (%3)").arg(name, reference, unit);
}

QString TrendSeries::description() const
{
    if (isWatchValue())
        return QCoreApplication::translate("mbscope::TrendSeries", "%1: watch %2, address %3, as the watch decodes it")
            .arg(label(), watchName, ReadAnswer::addressText(address));
    const QString where = QCoreApplication::translate("mbscope::TrendSeries", "%1, PDU address %2").arg(label(), ReadAnswer::addressText(address));
    if (isBits(table))
        return where;
    QString text = QCoreApplication::translate("mbscope::TrendSeries", "%1, %2, value = raw × %3 + %4").arg(where, format.name()).arg(scale).arg(offset);
    if (!profileName.isEmpty())
        text = QCoreApplication::translate("mbscope::TrendSeries", "%1 (profile %2)").arg(text, profileName);
    return text;
}

bool TrendSeries::sameRegister(const TrendSeries &other) const
{
    if (isWatchValue() || other.isWatchValue())
        return watchName == other.watchName && address == other.address;
    return unitId == other.unitId && table == other.table && address == other.address && format == other.format;
}

std::optional<double> TrendSeries::valueIn(const ReadAnswer &answer) const
{
    if (answer.table != table)
        return std::nullopt;
    const int index = address - answer.address;
    if (isBits(table)) {
        if (index < 0 || index >= answer.bits.size())
            return std::nullopt;
        return answer.bits.at(index) ? 1.0 : 0.0;
    }
    const int width = format.registerCount();
    if (index < 0 || index + width > answer.registers.size())
        return std::nullopt;
    const std::span<const quint16> words(answer.registers.constData() + index, std::size_t(width));
    return ScaledValue{format, scale, offset}.decode(words);
}

QList<TrendSeries> TrendSeries::fromProfile(const UnitProfile &unit, const QString &profileName)
{
    QList<TrendSeries> out;
    for (const TableEntry &entry : unit.entries) {
        const int width = entry.width();
        for (int i = 0; i < entry.valueCount(); ++i) {
            TrendSeries series;
            series.unitId = unit.id;
            series.table = modbusTableOf(entry.table);
            series.address = entry.address + i * width;
            series.format = entry.format;
            series.scale = entry.scale;
            series.offset = entry.offset;
            series.name = entry.valueCount() > 1 ? QCoreApplication::translate("mbscope::TrendSeries", "%1 [%2]").arg(entry.name).arg(i) : entry.name;
            series.unit = entry.unit;
            series.profileName = profileName;
            out.append(series);
        }
    }
    return out;
}

QJsonObject TrendSeries::toJson() const
{
    const TrendSeries &s = *this;
    return QJsonObject{{QStringLiteral("unitId"), s.unitId},
                       {QStringLiteral("table"), int(s.table)},
                       {QStringLiteral("address"), s.address},
                       {QStringLiteral("format"), s.format.name()},
                       {QStringLiteral("scale"), s.scale},
                       {QStringLiteral("offset"), s.offset},
                       {QStringLiteral("name"), s.name},
                       {QStringLiteral("unit"), s.unit},
                       {QStringLiteral("profile"), s.profileName},
                       {QStringLiteral("watch"), s.watchName}};
}

std::optional<TrendSeries> TrendSeries::fromJson(const QJsonObject &o)
{
    const QString watch = o.value(QStringLiteral("watch")).toString();
    if (!watch.isEmpty()) {
        const int address = o.value(QStringLiteral("address")).toInt(-1);
        if (address < 0 || address > 0xFFFF)
            return std::nullopt;
        TrendSeries s;
        s.watchName = watch;
        s.address = address;
        s.name = o.value(QStringLiteral("name")).toString();
        s.unit = o.value(QStringLiteral("unit")).toString();
        return s;
    }
    const int table = o.value(QStringLiteral("table")).toInt(-1);
    const int address = o.value(QStringLiteral("address")).toInt(-1);
    const RegisterFormatResult format = RegisterFormat::parse(o.value(QStringLiteral("format")).toString());
    if (table < int(ModbusTable::Coils) || table > int(ModbusTable::HoldingRegisters) || address < 0 || address > 0xFFFF
        || !format.ok)
        return std::nullopt;
    TrendSeries s;
    s.unitId = o.value(QStringLiteral("unitId")).toInt(-1);
    s.table = ModbusTable(table);
    s.address = address;
    s.format = format.format;
    s.scale = o.value(QStringLiteral("scale")).toDouble(1);
    s.offset = o.value(QStringLiteral("offset")).toDouble(0);
    s.name = o.value(QStringLiteral("name")).toString();
    s.unit = o.value(QStringLiteral("unit")).toString();
    s.profileName = o.value(QStringLiteral("profile")).toString();
    return s;
}

} // namespace mbscope
