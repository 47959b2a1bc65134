#pragma once

#include "exchange/trafficentry.h"
#include "traffic/trafficjournal.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

struct SessionDocument;

// What reopening a session's captured traffic gave: the frames of every complete batch of its
// journal (a journal cut by a crash or kill -9 loses only the batch being written) and a message
// for the user that says how much was recovered and whether anything was dropped.
struct RecoveredCapture {
    QString journalPath;             // absolute
    TrafficJournalRecovery recovery; // its message: "recovered 12,000 frames in 120 batches; ..."
    QList<TrafficFrame> frames;
    [[nodiscard]] bool ok() const { return recovery.ending == TrafficJournalRecovery::Ending::Clean
                                           || recovery.ending == TrafficJournalRecovery::Ending::NotClosed
                                           || recovery.ending == TrafficJournalRecovery::Ending::CutShort
                                           || recovery.ending == TrafficJournalRecovery::Ending::Corrupt; }
    // "capture bench.mbscope.journal: recovered ... (the journal was cut short: a crash or a kill
    // while capturing; everything up to the last complete batch is kept)"
    [[nodiscard]] QString summary() const;
};

class CaptureRecovery
{
public:
    // The journal a document names, resolved beside documentPath. A document without a capture
    // gives an empty path.
    [[nodiscard]] static QString journalPath(const SessionDocument &document, const QString &documentPath);
    // Reads the capture of document (opened from documentPath). keepFrames false only counts.
    [[nodiscard]] static RecoveredCapture open(const SessionDocument &document, const QString &documentPath,
                                               bool keepFrames = true);
};

} // namespace mbscope
