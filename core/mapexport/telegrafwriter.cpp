#include "telegrafwriter.h"

#include <QtCore/QLocale>
#include <QtCore/QMap>
#include <QtCore/QStringList>

#include <tuple>

namespace mbscope {

namespace {

QString tomlString(const QString &s)
{
    QString q = s;
    q.replace(QLatin1String("\\"), QLatin1String("\\\\")).replace(QLatin1String("\""), QLatin1String("\\\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

QString fieldType(const MapPoint &p)
{
    if (p.isString())
        return QStringLiteral("STRING");
    switch (p.format.type()) {
    case RegisterType::Int16: return QStringLiteral("INT16");
    case RegisterType::UInt32: return QStringLiteral("UINT32");
    case RegisterType::Int32: return QStringLiteral("INT32");
    case RegisterType::UInt64: return QStringLiteral("UINT64");
    case RegisterType::Int64: return QStringLiteral("INT64");
    case RegisterType::Float32: return QStringLiteral("FLOAT32");
    case RegisterType::Float64: return QStringLiteral("FLOAT64");
    default: return QStringLiteral("UINT16");
    }
}

QString registerName(SimTable table)
{
    switch (table) {
    case SimTable::Coils: return QStringLiteral("coil");
    case SimTable::DiscreteInputs: return QStringLiteral("discrete");
    case SimTable::InputRegisters: return QStringLiteral("input");
    case SimTable::HoldingRegisters: return QStringLiteral("holding");
    }
    return QStringLiteral("holding");
}

// Telegraf names the order of all four bytes; a 16-bit value uses its first two (AB or BA).
QString byteOrder(const MapPoint &p)
{
    if (p.isBit())
        return QStringLiteral("ABCD");
    switch (p.format.order()) {
    case RegisterOrder::ABCD: return QStringLiteral("ABCD");
    case RegisterOrder::CDAB: return QStringLiteral("CDAB");
    case RegisterOrder::BADC: return QStringLiteral("BADC");
    case RegisterOrder::DCBA: return QStringLiteral("DCBA");
    }
    return QStringLiteral("ABCD");
}

} // namespace

QString TelegrafWriter::write(const MapExportInput &input)
{
    QString out;
    out += QStringLiteral("# Telegraf Modbus input for %1, written by mbscope export-map from %2\n")
               .arg(input.name, input.source);
    out += QStringLiteral("[[inputs.modbus]]\n");
    out += QStringLiteral("  name = %1\n").arg(tomlString(input.name));
    out += QStringLiteral("  timeout = \"%1ms\"\n").arg(input.timeoutMs);
    const LinkUrl &e = input.endpoint;
    if (e.isSerial()) {
        out += QStringLiteral("  controller = %1\n").arg(tomlString(QStringLiteral("file://") + e.serial.device));
        out += QStringLiteral("  baud_rate = %1\n  data_bits = %2\n  parity = \"%3\"\n  stop_bits = %4\n")
                   .arg(e.serial.baud).arg(e.serial.dataBits).arg(QChar::fromLatin1(e.serial.parity))
                   .arg(e.serial.stopBits);
        out += QStringLiteral("  transmission_mode = \"RTU\"\n");
    } else {
        out += QStringLiteral("  controller = \"tcp://%1:%2\"\n").arg(e.host).arg(e.port);
        out += QStringLiteral("  transmission_mode = \"%1\"\n")
                   .arg(e.kind == LinkKind::RtuTcp ? QStringLiteral("RTUoverTCP") : QStringLiteral("TCP"));
    }
    out += QStringLiteral("  configuration_type = \"request\"\n");

    // One request per block and byte order, in the order of the points: Telegraf groups the fields
    // of one request into reads of up to 125 registers (2000 bits) of its own, never those of two
    // requests, so a block (within the device's limits.maxQuantity) is never read in a larger one.
    struct Key {
        qsizetype block;
        QString order;
        bool operator<(const Key &o) const { return std::tie(block, order) < std::tie(o.block, o.order); }
    };
    QList<qsizetype> blockOf(input.points.size(), 0);
    for (qsizetype b = 0; b < input.blocks.size(); ++b) {
        for (qsizetype i : input.blocks.at(b).points)
            blockOf[i] = b;
    }
    QList<Key> order;
    QMap<Key, QStringList> fields;
    for (qsizetype i = 0; i < input.points.size(); ++i) {
        const MapPoint &p = input.points.at(i);
        const Key k{blockOf.at(i), byteOrder(p)};
        if (!fields.contains(k))
            order.append(k);
        QString f = QStringLiteral("{ address=%1, name=%2").arg(p.address).arg(tomlString(p.name));
        if (!p.isBit()) {
            f += QStringLiteral(", type=\"%1\"").arg(fieldType(p));
            if (p.isString())
                f += QStringLiteral(", length=%1").arg(p.registers);
            else if (p.scale != 1)
                f += QStringLiteral(", scale=%1").arg(QString::number(p.scale, 'g', QLocale::FloatingPointShortest));
        }
        f += QStringLiteral(" },");
        if (p.offset != 0)
            f += QStringLiteral("  # offset %1 is not applied: Telegraf has none").arg(QString::number(p.offset, 'g', QLocale::FloatingPointShortest));
        else if (p.notImplemented || p.notImplementedNaN)
            f += QStringLiteral("  # the device reports \"not implemented\" as a sentinel value");
        fields[k].append(f);
    }
    for (const Key &k : order) {
        const MapPoint &first = input.points.at(input.blocks.at(k.block).points.constFirst());
        out += QStringLiteral("\n  [[inputs.modbus.request]]\n");
        out += QStringLiteral("    slave_id = %1\n").arg(int(first.unitId));
        out += QStringLiteral("    byte_order = \"%1\"\n").arg(k.order);
        out += QStringLiteral("    register = \"%1\"\n").arg(registerName(first.table));
        out += QStringLiteral("    fields = [\n");
        for (const QString &f : fields.value(k))
            out += QStringLiteral("      ") + f + QLatin1Char('\n');
        out += QStringLiteral("    ]\n");
    }
    // The device's pace (profile limits): a pause between requests and after a connection opens
    // (Telegraf 1.25 and later for the second).
    if (input.minGapMs > 0 || input.warmUpMs > 0) {
        out += QStringLiteral("\n  [inputs.modbus.workarounds]\n");
        if (input.minGapMs > 0)
            out += QStringLiteral("    pause_between_requests = \"%1ms\"\n").arg(input.minGapMs);
        if (input.warmUpMs > 0)
            out += QStringLiteral("    pause_after_connect = \"%1ms\"\n").arg(input.warmUpMs);
    }
    return out;
}

} // namespace mbscope
