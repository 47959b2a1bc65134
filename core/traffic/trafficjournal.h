#pragma once

#include "exchange/trafficentry.h"

#include <QtCore/QFile>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <functional>
#include <memory>

namespace mbscope {

// The traffic journal: an append-only file of batches of logged frames, written so that a crash
// or kill -9 loses at most the batch not yet written, and a reader recovers every complete batch
// exactly and says where the file stops making sense.
//
// Why binary and not JSON lines: frames are bytes, and hex in text doubles their size and costs
// a parse per byte; a torn JSON line is easy to spot but a torn line that still parses (cut after
// a digit) is not, so text would need a checksum per line anyway. A length + CRC-32 per batch
// makes recovery exact and costs one 28-byte header per frame and 32 bytes per batch.
//
// Format, version 1. All integers little-endian; CRC-32 is CRC-32/ISO-HDLC (zlib's crc32:
// reflected polynomial 0xEDB88320, initial and final XOR 0xFFFFFFFF, check "123456789" = 0xCBF43926).
//
//   file header, 40 bytes:
//     0  8  magic "MBSCTLOG"
//     8  4  version (1)
//    12  4  header size (40)
//    16  8  wall clock when the journal was opened, ms since 1970-01-01 UTC
//    24  8  monotonicNowNs() at the same moment: t_wall = wall + (tNs - monotonic) / 1e6
//    32  4  reserved (0)
//    36  4  CRC-32 of bytes 0-35
//   then batches, back to back:
//     0  4  magic "BTCH"
//     4  4  payload size in bytes
//     8  4  frames in the batch
//    12  4  records in the batch (frames + link names)
//    16  8  sequence number of the batch's first frame (TrafficEntry::sequence)
//    24  4  CRC-32 of the payload
//    28  4  CRC-32 of bytes 0-27 of this header
//    32     payload: records back to back, each
//              0  1  kind: 1 frame, 2 link name
//              1  1  direction (TrafficDirection)      } frames only,
//              2  1  verdict (TrafficVerdict)          } 0 for link names
//              3  1  reserved (0)
//              4  2  link id
//              6  2  reserved (0)
//              8  4  length of the bytes that follow
//             12  8  tNs (monotonic ns; 0 for link names)
//             20  8  transaction id (0 for link names)
//             28  n  the frame's bytes, or the link's name in UTF-8
//   A link name record comes before the first frame that uses its id.
//
// Each batch is written with one write(2) (QFile unbuffered) when it holds batchEntries frames or
// its first frame is batchNs old, whichever comes first (or it reaches 256 MiB), and on close. That reaches the kernel's
// page cache, which survives the process being killed; sync makes it fdatasync as well, to
// survive a power cut, at the cost of a disk round trip per batch.
class TrafficJournalWriter
{
public:
    struct Options {
        int batchEntries = 1024;
        qint64 batchNs = 100'000'000; // 100 ms
        bool sync = false;
    };

    TrafficJournalWriter();
    ~TrafficJournalWriter(); // writes the pending batch
    TrafficJournalWriter(const TrafficJournalWriter &) = delete;
    TrafficJournalWriter &operator=(const TrafficJournalWriter &) = delete;

    // Creates the journal and writes its header. An existing file is an error unless overwrite
    // (a journal is evidence: never clobbered by accident). False with *error saying why.
    bool open(const QString &path, const Options &options, bool overwrite = false, QString *error = nullptr);
    void close(); // writes the pending batch and closes
    [[nodiscard]] bool isOpen() const { return m_file.isOpen(); }
    [[nodiscard]] QString path() const { return m_file.fileName(); }

    void addLink(quint16 link, QStringView name);
    // Copies the entry into the pending batch (no system call, no allocation once the batch
    // buffer has grown to a batch's size); writes the batch when it is full or old enough.
    void addFrame(const TrafficEntry &entry);
    // Writes the pending batch if its first frame is at least batchNs older than nowNs.
    void flushIfDue(qint64 nowNs);
    void flush(); // writes the pending batch now (nothing when empty)

    // The first write error ("...: write failed after 12 batches: No space left on device"), or
    // empty. After an error nothing more is written; frames are counted as lost instead.
    [[nodiscard]] const QString &error() const { return m_error; }
    [[nodiscard]] quint64 batchesWritten() const { return m_batches; }
    [[nodiscard]] quint64 framesWritten() const { return m_frames; }
    [[nodiscard]] quint64 framesLost() const { return m_lost; }
    [[nodiscard]] quint64 framesPending() const { return m_batchFrames; }
    [[nodiscard]] qint64 bytesWritten() const { return m_bytes; }
    [[nodiscard]] std::size_t memoryBytes() const { return m_capacity; }

    [[nodiscard]] static quint32 crc32(const void *data, std::size_t size);

private:
    char *reserve(std::size_t bytes);
    void startBatch();

    QFile m_file;
    Options m_options;
    std::unique_ptr<char[]> m_buffer; // the pending batch, header space first
    std::size_t m_size = 0;
    std::size_t m_capacity = 0;
    quint32 m_batchFrames = 0;
    quint32 m_batchRecords = 0;
    quint64 m_batchFirstSequence = 0;
    qint64 m_batchFirstNs = 0;
    quint64 m_batches = 0;
    quint64 m_frames = 0;
    quint64 m_lost = 0;
    qint64 m_bytes = 0;
    QString m_error;
};

// What a read of a journal found.
struct TrafficJournalRecovery {
    enum class Ending : quint8 {
        Clean,       // the file ends where a complete batch ends
        CutShort,    // the last batch is incomplete (a crash while it was written): dropped
        Corrupt,     // a complete-looking batch fails its checks: it and what follows are dropped
        NotAJournal, // no valid header: nothing recovered
        Unreadable,  // could not be opened
    };
    Ending ending = Ending::Unreadable;
    quint64 frames = 0;
    quint64 batches = 0;
    qint64 goodBytes = 0;   // where the last complete batch ends
    qint64 fileBytes = 0;
    qint64 wallClockMs = 0; // from the header
    qint64 monotonicNs = 0;
    QStringList links;      // by link id; empty names for ids never named
    // "recovered 12,000 frames in 120 batches; the last batch was cut short at byte 480,123 and
    // is dropped (it began at byte 470,040)"
    QString message;

    [[nodiscard]] bool isClean() const { return ending == Ending::Clean; }
};

class TrafficJournalReader
{
public:
    using Sink = std::function<void(const TrafficEntry &)>;
    // Reads every frame of every complete, checked batch, in order, into sink (which may be
    // empty to only count). A batch is delivered only once all of it has been checked.
    [[nodiscard]] static TrafficJournalRecovery read(const QString &path, const Sink &sink);
    [[nodiscard]] static TrafficJournalRecovery readAll(const QString &path, QList<TrafficFrame> *frames);
};

} // namespace mbscope
