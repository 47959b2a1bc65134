#include "homeassistantwriter.h"

#include <QtCore/QLocale>
#include <QtCore/QStringList>

#include <algorithm>
#include <cmath>

namespace mbscope {

namespace {

// Home Assistant's own unit symbols where a profile spells one in ASCII: its temperature sensors
// know "°C" and "°F", not "degC" (a sensor with an unknown unit gets no conversion or device class).
QString homeAssistantUnit(const QString &unit)
{
    if (unit == QLatin1String("degC"))
        return QStringLiteral("\u00B0C");
    if (unit == QLatin1String("degF"))
        return QStringLiteral("\u00B0F");
    return unit;
}


QString dataType(const MapPoint &p)
{
    if (p.isString())
        return QStringLiteral("string");
    return p.numberType();
}

// Home Assistant's swap: byte (each register's bytes), word (the registers), word_byte (both).
QString swap(const MapPoint &p)
{
    switch (p.format.order()) {
    case RegisterOrder::ABCD: return QStringLiteral("none");
    case RegisterOrder::BADC: return QStringLiteral("byte");
    case RegisterOrder::CDAB: return QStringLiteral("word");
    case RegisterOrder::DCBA: return QStringLiteral("word_byte");
    }
    return QStringLiteral("none");
}

// Decimals that show every step of the scale: 0.1 -> 1, 0.001 -> 3; floats 3.
int precision(const MapPoint &p)
{
    if (p.format.isFloat())
        return 3;
    const double step = std::abs(p.scale);
    if (step >= 1)
        return 0;
    return std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 10);
}

QString number(double v)
{
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

} // namespace

QString HomeAssistantWriter::write(const MapExportInput &input)
{
    const QString hub = MapPoint::slug(input.name).isEmpty() ? QStringLiteral("mbscope") : MapPoint::slug(input.name);
    const int seconds = std::max(1, (input.intervalMs + 999) / 1000);
    QString out;
    out += QStringLiteral("# Home Assistant modbus for %1, written by mbscope export-map from %2\n").arg(input.name, input.source);
    out += QStringLiteral("modbus:\n  - name: %1\n").arg(MapPoint::yamlQuoted(hub));
    const LinkUrl &e = input.endpoint;
    if (e.isSerial()) {
        out += QStringLiteral("    type: serial\n    method: rtu\n    port: %1\n    baudrate: %2\n    bytesize: %3\n"
                              "    parity: %4\n    stopbits: %5\n")
                   .arg(MapPoint::yamlQuoted(e.serial.device)).arg(e.serial.baud).arg(e.serial.dataBits)
                   .arg(QChar::fromLatin1(e.serial.parity)).arg(e.serial.stopBits);
    } else {
        out += QStringLiteral("    type: %1\n    host: %2\n    port: %3\n")
                   .arg(e.kind == LinkKind::RtuTcp ? QStringLiteral("rtuovertcp") : QStringLiteral("tcp"),
                        MapPoint::yamlQuoted(e.host))
                   .arg(e.port);
    }
    out += QStringLiteral("    timeout: %1\n").arg(std::max(1, (input.timeoutMs + 999) / 1000));
    // The device's pace (profile limits): whole seconds to wait after connecting, milliseconds
    // between requests.
    if (input.warmUpMs > 0)
        out += QStringLiteral("    delay: %1\n").arg((input.warmUpMs + 999) / 1000);
    if (input.minGapMs > 0)
        out += QStringLiteral("    message_wait_milliseconds: %1\n").arg(input.minGapMs);

    QString sensors;
    QString binary;
    for (const MapPoint &p : input.points) {
        if (p.isBit()) {
            binary += QStringLiteral("      - name: %1\n        unique_id: %2\n        device_address: %3\n"
                                     "        address: %4\n        input_type: %5\n        scan_interval: %6\n")
                          .arg(MapPoint::yamlQuoted(p.label), MapPoint::yamlQuoted(hub + QLatin1Char('_') + p.name))
                          .arg(int(p.unitId)).arg(p.address)
                          .arg(p.table == SimTable::Coils ? QStringLiteral("coil") : QStringLiteral("discrete_input"))
                          .arg(seconds);
            continue;
        }
        QString s = QStringLiteral("      - name: %1\n        unique_id: %2\n        device_address: %3\n"
                                   "        address: %4\n        input_type: %5\n        data_type: %6\n")
                        .arg(MapPoint::yamlQuoted(p.label), MapPoint::yamlQuoted(hub + QLatin1Char('_') + p.name))
                        .arg(int(p.unitId)).arg(p.address)
                        .arg(p.table == SimTable::HoldingRegisters ? QStringLiteral("holding") : QStringLiteral("input"),
                             dataType(p));
        if (p.isString()) {
            s += QStringLiteral("        count: %1\n").arg(p.registers);
        } else {
            s += QStringLiteral("        swap: %1\n        scale: %2\n        offset: %3\n        precision: %4\n")
                     .arg(swap(p), number(p.scale), number(p.offset)).arg(precision(p));
            if (!p.unit.isEmpty())
                s += QStringLiteral("        unit_of_measurement: %1\n").arg(MapPoint::yamlQuoted(homeAssistantUnit(p.unit)));
            if (p.kind == ValueKind::Counter)
                s += QStringLiteral("        state_class: total_increasing\n");
            else if (p.kind == ValueKind::Measurement)
                s += QStringLiteral("        state_class: measurement\n");
            if (p.min)
                s += QStringLiteral("        min_value: %1\n").arg(number(*p.min));
            if (p.max)
                s += QStringLiteral("        max_value: %1\n").arg(number(*p.max));
            if (p.notImplemented && !p.format.isFloat())
                s += QStringLiteral("        nan_value: 0x%1\n").arg(*p.notImplemented, p.registers * 4, 16, QLatin1Char('0'));
        }
        s += QStringLiteral("        scan_interval: %1\n").arg(seconds);
        sensors += s;
    }
    if (!sensors.isEmpty())
        out += QStringLiteral("    sensors:\n") + sensors;
    if (!binary.isEmpty())
        out += QStringLiteral("    binary_sensors:\n") + binary;
    return out;
}

} // namespace mbscope
