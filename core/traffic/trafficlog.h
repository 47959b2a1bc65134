#pragma once

#include "exchange/trafficentry.h"
#include "journalendpoints.h"
#include "trafficjournal.h"

#include <QtCore/QHash>

#include <QtCore/QList>
#include <QtCore/QMutex>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <functional>
#include <memory>
#include <vector>

namespace mbscope {

// Every frame in and out of the engine, in order: in memory up to a bound (the oldest frames are
// dropped first, and counted), and journaled to disk in batches (trafficjournal.h) so that a
// crash loses at most the batch not yet written.
//
// Memory: frames live in 64 KiB chunks, each filled from the front with 24-byte records and from
// the back with the frames' bytes, so a logged 8-byte frame costs 32 bytes plus its share of a
// chunk's unused middle (measured: about 32 bytes per frame, tst_trafficlog and
// bench_trafficlog). append() makes no system call and, once the log is full and recycling its
// oldest chunk, no allocation: a chunk is allocated per ~2,000 small frames while the log grows.
//
// Threads: the engine's thread owns the log and calls append(); nothing else may touch it while
// it does. Views (TrafficEntry) are valid until the next append; copy() makes owning frames to
// hand to another thread. A log shared by several engines (setShared: the links of one watch
// run or scan, one journal for all of them) takes a lock in the calls its writers make.
class TrafficLog
{
public:
    struct Limits {
        quint64 maxEntries = 1'000'000;
        // Bytes of records and frames kept: 24 + frame size per entry. The allocation is this
        // plus at most one chunk's slack (64 KiB).
        quint64 maxBytes = quint64(256) << 20;
    };

    TrafficLog();
    explicit TrafficLog(const Limits &limits);
    ~TrafficLog();
    TrafficLog(const TrafficLog &) = delete;
    TrafficLog &operator=(const TrafficLog &) = delete;

    // Several writers in threads of their own (engines: EngineRecorder), one journal: append,
    // addLink, addConnection, setEndpoints, annotate, flush, flushIfDue and closeJournal then lock, so that
    // frames from each thread go in whole and in turn. Set before any writer has the log. The
    // reading calls (at, visit, copy, links) stay unlocked: for when no writer writes.
    void setShared(bool shared);
    [[nodiscard]] bool isShared() const { return m_lock != nullptr; }

    // Smaller limits drop the oldest entries at once.
    void setLimits(const Limits &limits);
    [[nodiscard]] const Limits &limits() const { return m_limits; }

    // Starts journaling every frame appended from now on (see TrafficJournalWriter::open), with
    // the links named so far.
    bool openJournal(const QString &path, const TrafficJournalWriter::Options &options = {},
                     bool overwrite = false, QString *error = nullptr);
    void closeJournal(); // writes the pending batch
    // Journal parts: once the journal holds maxBytes, it is closed and the next frame goes to a
    // new one at next(closedPath) (the link names are written again). 0 or no function: one
    // journal, whatever its size. next returns an empty path to stop journaling.
    void setJournalRotation(qint64 maxBytes, std::function<QString(const QString &closedPath)> next);
    // Why journaling stopped at a rotation (the next part could not be created), or empty.
    [[nodiscard]] const QString &rotationError() const { return m_rotationError; }
    // Called once when journaling stops on its own while frames still come: a rotation whose next
    // part cannot be made (rotationError), or the journal's first write error (a full disk). In
    // the thread that appended or flushed (an engine's), under the log's lock: the handler only
    // hands the problem over (a queued call), and must not call the log.
    void setJournalStopped(std::function<void(const QString &problem)> handler);
    [[nodiscard]] const TrafficJournalWriter &journal() const { return m_journal; }

    // A short id for a link's name ("tcp://192.168.1.10:502"); the same name gives the same id.
    [[nodiscard]] quint16 addLink(const QString &name);
    // A new id for one connection to name, even when the log has that name already: each
    // engine numbers its transactions from 1, so in a shared log every engine's link is an id
    // of its own and a transaction is told by its link and its id (the journal's readers pair
    // by both).
    [[nodiscard]] quint16 addConnection(const QString &name);
    [[nodiscard]] QString linkName(quint16 link) const;
    [[nodiscard]] const QStringList &links() const { return m_links; }

    // A note on a transaction for the journal only (trafficjournal.h, record kind 4): nothing is
    // kept in memory, and without a journal it goes nowhere.
    void annotate(quint16 link, quint64 transactionId, qint64 tNs, QByteArrayView json);

    // The endpoints of a link's connection from now on (journalendpoints.h), as a note in the
    // journal; kept, and written again at the start of every journal opened later (a recording
    // started while connected, the next part of a rotating journal), as link names are.
    void setEndpoints(quint16 link, qint64 tNs, quint64 transactionId, const JournalEndpoints &endpoints);

    // Logs one frame; returns its sequence number.
    quint64 append(qint64 tNs, TrafficDirection direction, quint16 link, TrafficVerdict verdict,
                   quint64 transactionId, QByteArrayView bytes);
    // The engine calls this from a timer so a quiet link's last frames reach the disk within the
    // batch time.
    void flushIfDue(qint64 nowNs);
    void flush();

    [[nodiscard]] quint64 size() const { return m_size; }                       // entries in memory
    [[nodiscard]] quint64 appended() const { return m_next; }                   // ever logged
    [[nodiscard]] quint64 dropped() const { return m_next - m_size; }           // evicted from memory
    [[nodiscard]] quint64 firstSequence() const { return m_next - m_size; }     // oldest in memory
    [[nodiscard]] quint64 retainedBytes() const { return m_retainedBytes; }
    // firstSequence() <= sequence < appended(); otherwise an entry with no bytes and the given
    // sequence, verdict Garbage.
    [[nodiscard]] TrafficEntry at(quint64 sequence) const;
    // Calls visitor with the entries in memory from sequence from on (forward) or back to the
    // oldest (backward), one by one, until it returns false; from outside what is in memory:
    // nothing. Cheaper per entry than at(): no search.
    void visit(quint64 from, bool forward, const std::function<bool(const TrafficEntry &)> &visitor) const;
    // Drops the oldest count entries (all, when fewer) from memory; a journal keeps them.
    void dropOldest(quint64 count);
    // Up to maxCount entries from fromSequence (clamped to what is in memory), as owning frames.
    [[nodiscard]] QList<TrafficFrame> copy(quint64 fromSequence, qsizetype maxCount) const;

    // Bytes this log holds on the heap: chunks (capacity), their index, the spare chunk, the
    // journal's batch buffer and the link names.
    [[nodiscard]] std::size_t memoryBytes() const;

    static constexpr std::size_t kChunkBytes = 64 * 1024;

private:
    struct Record;
    struct Chunk;

    [[nodiscard]] Chunk *chunkFor(std::size_t bytes);
    void evictOldest();
    [[nodiscard]] TrafficEntry entryAt(const Chunk &chunk, quint32 index) const;
    void rotateJournal();
    // The journal stopped (rotationError, or its write error): says so, once, to the handler.
    void sayIfStopped();
    quint16 appendLink(const QString &name);

    Limits m_limits;
    std::vector<std::unique_ptr<Chunk>> m_chunks; // oldest first
    std::unique_ptr<Chunk> m_spare;
    quint32 m_headSkip = 0; // entries of the first chunk already dropped
    quint64 m_size = 0;
    quint64 m_next = 0;
    quint64 m_retainedBytes = 0;
    QStringList m_links;
    QHash<quint16, QByteArray> m_endpoints; // the last endpoints note of each link
    TrafficJournalWriter m_journal;
    TrafficJournalWriter::Options m_journalOptions;
    qint64 m_rotateBytes = 0;
    std::function<QString(const QString &)> m_nextJournal;
    QString m_rotationError;
    std::function<void(const QString &)> m_journalStopped;
    bool m_stopSaid = false;
    std::unique_ptr<QMutex> m_lock; // shared logs only
};

} // namespace mbscope
