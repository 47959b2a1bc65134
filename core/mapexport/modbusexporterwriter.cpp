#include "modbusexporterwriter.h"

#include <QtCore/QLocale>
#include <QtCore/QStringList>

namespace mbscope {

namespace {

QString dataType(const MapPoint &p)
{
    if (p.isBit())
        return QStringLiteral("bool");
    return p.numberType();
}

// modbus_exporter's endianness of the bytes 1 2 3 4: big (1 2 3 4), little (4 3 2 1),
// mixed (2 1 4 3), yolo (3 4 1 2).
QString endianness(const MapPoint &p)
{
    switch (p.format.order()) {
    case RegisterOrder::ABCD: return QStringLiteral("big");
    case RegisterOrder::DCBA: return QStringLiteral("little");
    case RegisterOrder::BADC: return p.registers == 1 ? QStringLiteral("little") : QStringLiteral("mixed");
    case RegisterOrder::CDAB: return QStringLiteral("yolo");
    }
    return QStringLiteral("big");
}

} // namespace

QString ModbusExporterWriter::write(const MapExportInput &input)
{
    QString out;
    out += QStringLiteral("# modbus_exporter module for %1, written by mbscope export-map from %2\n"
                          "# Prometheus passes the target (%3:%4) and the unit as sub_target.\n")
               .arg(input.name, input.source, input.endpoint.host)
               .arg(input.endpoint.port);
    // The device's pace (profile limits): said, since a module has no setting for it.
    QStringList pace;
    if (input.minGapMs > 0)
        pace.append(QStringLiteral("%1 ms between requests").arg(input.minGapMs));
    if (input.warmUpMs > 0)
        pace.append(QStringLiteral("%1 ms after a connection opens").arg(input.warmUpMs));
    if (!pace.isEmpty())
        out += QStringLiteral("# The device needs %1: modbus_exporter has no setting for %2.\n")
                   .arg(pace.join(QStringLiteral(" and ")), pace.size() == 1 ? QStringLiteral("it") : QStringLiteral("either"));
    out += QStringLiteral("modules:\n  - name: %1\n    protocol: \"tcp/ip\"\n    metrics:\n")
               .arg(MapPoint::yamlQuoted(MapPoint::slug(input.name)));
    for (const MapPoint &p : input.points) {
        if (p.isString()) {
            out += QStringLiteral("      # %1 (%2 %3): a string, which modbus_exporter cannot read\n")
                       .arg(p.name, p.tableKey()).arg(p.address);
            continue;
        }
        out += QStringLiteral("      - name: %1\n").arg(MapPoint::yamlQuoted(p.name));
        out += QStringLiteral("        help: %1\n")
                   .arg(MapPoint::yamlQuoted(p.description.isEmpty() ? p.label + (p.unit.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(p.unit))
                                                           : p.description));
        if (input.points.constFirst().unitId != p.unitId || p.unitId != 1)
            out += QStringLiteral("        # unit %1: scrape with sub_target=%1\n").arg(int(p.unitId));
        out += QStringLiteral("        address: %1%2\n").arg(int(p.readFunction())).arg(p.address, 5, 10, QLatin1Char('0'));
        out += QStringLiteral("        dataType: %1\n").arg(dataType(p));
        if (p.isBit())
            out += QStringLiteral("        bitOffset: 0\n");
        else
            out += QStringLiteral("        endianness: %1\n").arg(endianness(p));
        // modbus_exporter's counter adds each reading to the metric: a device's total is a gauge.
        out += QStringLiteral("        metricType: gauge\n");
        if (!p.isBit() && p.scale != 1)
            out += QStringLiteral("        factor: %1\n").arg(QString::number(p.scale, 'g', QLocale::FloatingPointShortest));
        if (p.offset != 0)
            out += QStringLiteral("        # offset %1 is not applied: modbus_exporter has none\n")
                       .arg(QString::number(p.offset, 'g', QLocale::FloatingPointShortest));
        // Named bits of a one-register value: a bool metric each (bitOffset counts from the
        // register's least significant bit, the register read high byte first).
        if (p.registers == 1 && !p.isBit() && !p.format.isByteSwapped()) {
            for (auto it = p.bitNames.cbegin(); it != p.bitNames.cend(); ++it) {
                const QString bit = MapPoint::slug(it.value()).isEmpty() ? QString::number(it.key()) : MapPoint::slug(it.value());
                out += QStringLiteral("      - name: %1\n        help: %2\n        address: %3%4\n        dataType: bool\n"
                                      "        bitOffset: %5\n        metricType: gauge\n")
                           .arg(MapPoint::yamlQuoted(p.name + QLatin1Char('_') + bit),
                                MapPoint::yamlQuoted(QStringLiteral("%1, bit %2: %3").arg(p.label).arg(it.key()).arg(it.value())))
                           .arg(int(p.readFunction()))
                           .arg(p.address, 5, 10, QLatin1Char('0'))
                           .arg(it.key());
            }
        }
    }
    return out;
}

} // namespace mbscope
