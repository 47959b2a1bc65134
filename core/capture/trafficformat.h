#pragma once

#include <QtCore/QString>

#include <optional>

namespace mbscope {

// The kinds of file traffic is read from or written to, one list for every reader and writer:
// mbscope's own journal, the two captures Wireshark reads (pcapng, classic pcap), and the two
// tables of exchanges (CSV, JSON lines). `mbscope export`, the window's Save Traffic As, the
// capture reader's detection and the capture writer all name formats from this list.
enum class TrafficFormat : quint8 {
    Journal,   // .mbscope.journal (core/traffic: JournalWriter, JournalReader)
    Pcapng,    // .pcapng
    Pcap,      // .pcap
    Csv,       // .csv, a row per exchange
    JsonLines, // .jsonl, an object per exchange
    Unknown,   // none of these (a reader's detection failed)
};

namespace trafficformat {

// "journal", "pcapng", "pcap", "csv", "jsonl", "unknown".
[[nodiscard]] QString name(TrafficFormat format);
// The file name ending that names the format: ".mbscope.journal", ".pcapng"... (empty: Unknown).
[[nodiscard]] QString suffix(TrafficFormat format);
// The format a file name's ending names (".json" too for JSON lines; case ignored), if any.
[[nodiscard]] std::optional<TrafficFormat> ofEnding(const QString &path);
// A capture Wireshark reads (pcap or pcapng).
[[nodiscard]] constexpr bool isCapture(TrafficFormat format)
{
    return format == TrafficFormat::Pcap || format == TrafficFormat::Pcapng;
}

} // namespace trafficformat

} // namespace mbscope
