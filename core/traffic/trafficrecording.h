#pragma once

#include "traffic/trafficlog.h"
#include "traffic/trafficmetadata.h"

#include <QtCore/QString>

#include <memory>

namespace mbscope {

// A command's --record FILE: a TrafficLog that journals every frame to FILE, the journal opened
// with the metadata as its first record. Only the journal matters, so the log keeps little in
// memory. Hand log() to TransactionEngine::setTrafficLog or Simulator::setTrafficLog, take it
// back (setTrafficLog(nullptr)) before close(), then print summary().
class TrafficRecording
{
public:
    // A small in-memory window: the views of a command never read the log.
    static constexpr quint64 kMemoryEntries = 4096;
    static constexpr quint64 kMemoryBytes = quint64(1) << 20;

    TrafficRecording();
    ~TrafficRecording(); // closes
    TrafficRecording(const TrafficRecording &) = delete;
    TrafficRecording &operator=(const TrafficRecording &) = delete;

    // Creates the journal and writes the metadata. An existing file is refused unless
    // overwrite (a journal is evidence). False with *error saying what and where.
    bool open(const QString &path, const TrafficMetadata &metadata, bool overwrite, QString *error,
              const TrafficJournalWriter::Options &options = {});
    // Writes the pending batch and closes the journal.
    void close();

    [[nodiscard]] bool isOpen() const { return m_log.journal().isOpen(); }
    [[nodiscard]] TrafficLog *log() { return &m_log; }
    [[nodiscard]] const QString &path() const { return m_path; }
    [[nodiscard]] quint64 frames() const { return m_log.journal().framesWritten(); }
    [[nodiscard]] quint64 transactions() const { return m_log.journal().transactionsWritten(); }
    [[nodiscard]] qint64 bytes() const { return m_log.journal().bytesWritten(); }
    // The journal's write error ("FILE: write failed after 12 batches: No space left on device"), or empty.
    [[nodiscard]] QString error() const { return m_log.journal().error(); }
    // "recorded 1,204 frames (602 transactions) to poll.mbscope.journal", and the write error
    // and the frames it lost when there was one.
    [[nodiscard]] QString summary() const;

private:
    TrafficLog m_log;
    QString m_path;
};

} // namespace mbscope
