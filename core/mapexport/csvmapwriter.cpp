#include "csvmapwriter.h"

#include <QtCore/QLocale>
#include <QtCore/QStringList>

namespace mbscope {

namespace {

QString quoted(const QString &field)
{
    if (!field.contains(QLatin1Char(',')) && !field.contains(QLatin1Char('"')) && !field.contains(QLatin1Char('\n')))
        return field;
    QString q = field;
    q.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

QString number(const std::optional<double> &v)
{
    return v ? QString::number(*v, 'g', QLocale::FloatingPointShortest) : QString();
}

} // namespace

QString CsvMapWriter::write(const MapExportInput &input)
{
    QString out = QStringLiteral("unit,table,function,address,registers,name,label,type,order,scale,offset,unit,kind,"
                                 "min,max,writable,length,padding,not_implemented,enum,bits,description\r\n");
    for (const MapPoint &p : input.points) {
        QStringList enums;
        for (auto it = p.enumNames.cbegin(); it != p.enumNames.cend(); ++it)
            enums.append(QStringLiteral("%1=%2").arg(it.key()).arg(it.value()));
        QStringList bits;
        for (auto it = p.bitNames.cbegin(); it != p.bitNames.cend(); ++it)
            bits.append(QStringLiteral("%1=%2").arg(it.key()).arg(it.value()));
        QString sentinel;
        if (p.notImplementedNaN)
            sentinel = QStringLiteral("NaN");
        else if (p.notImplemented)
            sentinel = QStringLiteral("0x%1").arg(*p.notImplemented, p.registers * 4, 16, QLatin1Char('0')).toUpper().replace(QLatin1String("0X"), QLatin1String("0x"));
        const QStringList row{
            QString::number(p.unitId),
            p.tableKey(),
            QStringLiteral("%1").arg(p.readFunction(), 2, 10, QLatin1Char('0')),
            QString::number(p.address),
            QString::number(p.registers),
            p.name,
            p.label,
            p.isBit() ? QStringLiteral("bit") : (p.isString() ? QStringLiteral("string") : p.format.typeName()),
            p.isBit() ? QString() : p.format.orderName(),
            QString::number(p.scale, 'g', QLocale::FloatingPointShortest),
            QString::number(p.offset, 'g', QLocale::FloatingPointShortest),
            p.unit,
            valueKindName(p.kind),
            number(p.min),
            number(p.max),
            p.writable ? QStringLiteral("yes") : QStringLiteral("no"),
            p.isString() ? QString::number(p.stringLength) : QString(),
            p.isString() ? (p.spacePadded ? QStringLiteral("space") : QStringLiteral("nul")) : QString(),
            sentinel,
            enums.join(QLatin1Char(';')),
            bits.join(QLatin1Char(';')),
            p.description,
        };
        QStringList fields;
        for (const QString &f : row)
            fields.append(quoted(f));
        out += fields.join(QLatin1Char(',')) + QStringLiteral("\r\n");
    }
    return out;
}

} // namespace mbscope
