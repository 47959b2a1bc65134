#pragma once

#include "capture/trafficformat.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <optional>

namespace mbscope {

class TrafficModel;

// The traffic list written to a file ("Save Traffic As"): all of its frames, or the rows the
// filter shows, as a traffic journal (what `mbscope analyze`, `export` and `replay` read), or
// through one as `mbscope export` writes it: pcapng or pcap (Wireshark decodes MBAP on its own,
// RTU with the option decodeOptions names), CSV or JSON lines (one row per transaction).
class TrafficSaver
{
    Q_DECLARE_TR_FUNCTIONS(TrafficSaver)

public:
    struct Result {
        bool ok = false;
        QString error;
        quint64 frames = 0;   // frames saved (or put through the journal)
        quint64 written = 0;  // transactions (CSV, JSON lines), packets (captures), frames (journal)
        QStringList decodeOptions; // captures: tshark options for RTU ports
        // One line for the status bar or a message box.
        [[nodiscard]] QString summary(TrafficFormat format, const QString &path) const;
    };

    // By the name's ending (trafficformat::ofEnding), else a journal.
    [[nodiscard]] static TrafficFormat formatFor(const QString &path);
    // The file dialog's filters (journal, pcapng, pcap, CSV, JSON lines), and the format of the
    // one picked (a journal for a filter not in the list).
    [[nodiscard]] static QStringList nameFilters();
    [[nodiscard]] static TrafficFormat formatOfFilter(const QString &filter);

    // Writes what the model holds (shownOnly: the rows shown now, in order) to path, replacing a
    // file there only once the new one is complete. target: the window's link, for the journal's
    // header.
    [[nodiscard]] static Result save(const TrafficModel &model, bool shownOnly, const QString &path, TrafficFormat format,
                                     const QString &target);
};

} // namespace mbscope
