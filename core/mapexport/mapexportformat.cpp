#include "mapexportformat.h"

#include "csvmapwriter.h"
#include "homeassistantwriter.h"
#include "modbusexporterwriter.h"
#include "noderedwriter.h"
#include "telegrafwriter.h"

namespace mbscope {

namespace {

struct FormatName {
    MapExportFormat format;
    const char *name;
};

constexpr FormatName kNames[] = {
    {MapExportFormat::NodeRed, "nodered"},
    {MapExportFormat::Telegraf, "telegraf"},
    {MapExportFormat::HomeAssistant, "homeassistant"},
    {MapExportFormat::ModbusExporter, "modbus_exporter"},
    {MapExportFormat::Csv, "csv"},
};

} // namespace

QString MapExporter::formatName(MapExportFormat format)
{
    for (const FormatName &f : kNames) {
        if (f.format == format)
            return QString::fromLatin1(f.name);
    }
    return QString();
}

std::optional<MapExportFormat> MapExporter::formatFromName(QStringView name)
{
    for (const FormatName &f : kNames) {
        if (name.compare(QLatin1String(f.name), Qt::CaseInsensitive) == 0)
            return f.format;
    }
    return std::nullopt;
}

QString MapExporter::formatNames()
{
    return QStringLiteral("nodered, telegraf, homeassistant, modbus_exporter or csv");
}

QString MapExporter::unsupportedEndpoint(MapExportFormat format, const LinkUrl &endpoint)
{
    const LinkKind k = endpoint.kind;
    switch (format) {
    case MapExportFormat::Csv:
        return QString();
    case MapExportFormat::ModbusExporter:
        return k == LinkKind::Tcp ? QString()
                                  : QStringLiteral("modbus_exporter reads Modbus/TCP only (the target is given by "
                                                   "Prometheus as host:port): expected a tcp:// endpoint");
    case MapExportFormat::NodeRed:
    case MapExportFormat::Telegraf:
    case MapExportFormat::HomeAssistant:
        return (k == LinkKind::Tcp || k == LinkKind::RtuTcp || k == LinkKind::Rtu)
                   ? QString()
                   : QStringLiteral("%1 takes tcp://, rtu-tcp:// or rtu:// endpoints, not %2://")
                         .arg(formatName(format), LinkUrl::schemeName(k));
    }
    return QString();
}

QString MapExporter::write(MapExportFormat format, const MapExportInput &input)
{
    switch (format) {
    case MapExportFormat::NodeRed: return NodeRedWriter::write(input);
    case MapExportFormat::Telegraf: return TelegrafWriter::write(input);
    case MapExportFormat::HomeAssistant: return HomeAssistantWriter::write(input);
    case MapExportFormat::ModbusExporter: return ModbusExporterWriter::write(input);
    case MapExportFormat::Csv: return CsvMapWriter::write(input);
    }
    return QString();
}

LinkUrl MapExporter::defaultEndpoint(const DeviceProfile &profile, MapExportFormat format)
{
    for (const QString &text : profile.endpoints) {
        const LinkUrl::Result parsed = LinkUrl::parse(text);
        if (parsed.url && unsupportedEndpoint(format, *parsed.url).isEmpty())
            return *parsed.url;
    }
    return *LinkUrl::parse(u"tcp://127.0.0.1:502").url;
}

} // namespace mbscope
