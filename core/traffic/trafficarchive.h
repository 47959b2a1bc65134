#pragma once

#include "trafficjournal.h"

#include <QtCore/QFile>
#include <QtCore/QString>

#include <functional>
#include <memory>
#include <vector>

namespace mbscope {

// The older part of a list of frames, on disk: frames a bounded memory log lets go of (oldest
// first, numbered on from 0 without gaps) are written to a traffic journal of the archive's own
// (trafficjournal.h, batches of kBatchFrames frames) and read back by sequence when asked for,
// a few batches kept decoded. The window's traffic list keeps its recent frames in memory and
// the rest here, so that it can still show and search its first frame after a day of polling
// with memory that does not grow (issue 31); its recording journal is no substitute, since it
// rotates, is trimmed to a quota, may be off, and holds the watches' and scans' frames too.
//
// The journal is a file in the folder given to open(), opened for writing and reading and then
// unlinked (Unix): it takes disk space while the archive lives and none after, even when the
// process is killed. Threads: one, the owner's.
class TrafficArchive
{
public:
    static constexpr int kBatchFrames = 1024;
    static constexpr int kCachedBatches = 8;

    TrafficArchive();
    ~TrafficArchive();
    TrafficArchive(const TrafficArchive &) = delete;
    TrafficArchive &operator=(const TrafficArchive &) = delete;

    // Creates the journal in folder (made if missing); false with *error saying why.
    bool open(const QString &folder, QString *error = nullptr);
    [[nodiscard]] bool isOpen() const { return m_writer.isOpen(); }
    // The name the journal had in the folder (gone once open, on Unix).
    [[nodiscard]] QString path() const { return m_path; }
    // Closes and removes the journal; open() starts a new one.
    void clear();

    // Appends a frame: its sequence must be size() (the archive holds 0 .. size()-1). False
    // when it is not, or the journal could not be written (error()). Frames are written a
    // whole batch at a time; the last, partial batch is kept in memory meanwhile.
    bool append(const TrafficEntry &entry);
    [[nodiscard]] quint64 size() const { return m_size; }
    [[nodiscard]] const QString &error() const;

    // The frame numbered sequence (< size()); an entry with no bytes, verdict Garbage, when
    // it cannot be read. Valid until kCachedBatches other batches have been read since.
    [[nodiscard]] TrafficEntry at(quint64 sequence) const;
    // As TrafficLog::visit: from sequence from on (forward) or back to 0, until visitor returns
    // false; from at or past size(): nothing.
    void visit(quint64 from, bool forward, const std::function<bool(const TrafficEntry &)> &visitor) const;

    // Bytes held in memory: the batch index, the pending frames and the decoded batches.
    [[nodiscard]] std::size_t memoryBytes() const;
    // Bytes of the journal on disk.
    [[nodiscard]] qint64 diskBytes() const { return m_writer.bytesWritten(); }

private:
    struct Batch {
        quint64 first = 0;
        std::vector<TrafficFrame> frames;
        quint64 used = 0; // when it was last read (m_clock)
    };
    [[nodiscard]] const Batch *batch(std::size_t index) const;

    QString m_path;
    TrafficJournalWriter m_writer;
    std::vector<qint64> m_offsets; // where batch k (frames k*kBatchFrames ...) starts
    quint64 m_size = 0;
    std::vector<TrafficFrame> m_pending; // the frames after the last whole batch written
    mutable QFile m_reader;
    mutable std::vector<std::unique_ptr<Batch>> m_cache;
    mutable std::vector<std::size_t> m_cacheIndex; // the batch index of each cache slot
    mutable quint64 m_clock = 0;
    mutable QString m_readError;
};

} // namespace mbscope
