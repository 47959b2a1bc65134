#include "trafficformat.h"

#include <QtCore/QFileInfo>

namespace mbscope::trafficformat {

QString name(TrafficFormat format)
{
    switch (format) {
    case TrafficFormat::Journal: return QStringLiteral("journal");
    case TrafficFormat::Pcapng: return QStringLiteral("pcapng");
    case TrafficFormat::Pcap: return QStringLiteral("pcap");
    case TrafficFormat::Csv: return QStringLiteral("csv");
    case TrafficFormat::JsonLines: return QStringLiteral("jsonl");
    case TrafficFormat::Unknown: break;
    }
    return QStringLiteral("unknown");
}

QString suffix(TrafficFormat format)
{
    switch (format) {
    case TrafficFormat::Journal: return QStringLiteral(".mbscope.journal");
    case TrafficFormat::Pcapng: return QStringLiteral(".pcapng");
    case TrafficFormat::Pcap: return QStringLiteral(".pcap");
    case TrafficFormat::Csv: return QStringLiteral(".csv");
    case TrafficFormat::JsonLines: return QStringLiteral(".jsonl");
    case TrafficFormat::Unknown: break;
    }
    return {};
}

std::optional<TrafficFormat> ofEnding(const QString &path)
{
    const QString file = QFileInfo(path).fileName().toLower();
    if (file.endsWith(QLatin1String(".json")))
        return TrafficFormat::JsonLines;
    for (TrafficFormat format : {TrafficFormat::Journal, TrafficFormat::Pcapng, TrafficFormat::Pcap, TrafficFormat::Csv,
                                 TrafficFormat::JsonLines}) {
        if (file.endsWith(suffix(format)))
            return format;
    }
    return std::nullopt;
}

} // namespace mbscope::trafficformat
