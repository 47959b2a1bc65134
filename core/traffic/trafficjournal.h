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
// Format, version 3 (versions 1 and 2 are read as well: version 2 is version 3 without the end
// record, version 1 is version 2 without metadata and note records). All integers little-endian; CRC-32 is CRC-32/ISO-HDLC (zlib's crc32: reflected
// polynomial 0xEDB88320, initial and final XOR 0xFFFFFFFF, check "123456789" = 0xCBF43926).
//
//   file header, 40 bytes:
//     0  8  magic "MBSCTLOG"
//     8  4  version (3; 2 before the end record, 1 before metadata and notes)
//    12  4  header size (40)
//    16  8  wall clock when the journal was opened, ms since 1970-01-01 UTC
//    24  8  monotonicNowNs() at the same moment: t_wall = wall + (tNs - monotonic) / 1e6
//    32  4  reserved (0)
//    36  4  CRC-32 of bytes 0-35
//   then batches, back to back:
//     0  4  magic "BTCH"
//     4  4  payload size in bytes
//     8  4  frames in the batch
//    12  4  records in the batch (frames, link names, metadata, notes)
//    16  8  sequence number of the batch's first frame (TrafficEntry::sequence); a batch
//           without frames (0 frames) says 0 here and does not count in the sequence check
//    24  4  CRC-32 of the payload
//    28  4  CRC-32 of bytes 0-27 of this header
//    32     payload: records back to back, each
//              0  1  kind: 1 frame, 2 link name, 3 metadata (version 2), 4 note (version 2),
//                        5 end (version 3)
//              1  1  direction (TrafficDirection)      } frames only,
//              2  1  verdict (TrafficVerdict)          } 0 for the other kinds
//              3  1  reserved (0)
//              4  2  link id (frames, link names, notes; 0 for metadata)
//              6  2  reserved (0)
//              8  4  length of the bytes that follow
//             12  8  tNs (monotonic ns; 0 for link names)
//             20  8  transaction id (frames and notes; 0 for link names and metadata)
//             28  n  the frame's bytes, the link's name in UTF-8, or a JSON object in UTF-8
//   A link name record comes before the first frame that uses its id.
//   Metadata (version 2): the first batch of a journal opened with Options::metadata holds only
//   the metadata record, and is written at once, so a journal killed before its first frame
//   still says what it was recording: a JSON object (trafficmetadata.h: the command, target,
//   profile, requests, version, host, start time). A reader keeps the first one.
//   Note (version 2): a JSON object about the transaction with the record's id on the record's
//   link, e.g. the simulator's fault rules that shaped an answer: {"faults": ["slow", ...]}, or
//   the ends of the connection the link's frames go over from here on (journalendpoints.h):
//   {"endpoints": {"client": "127.0.0.1:40312", "server": "127.0.0.1:502"}}. A reader skips
//   the notes it does not know, so new kinds of note keep the format's version.
//   End (version 3): no bytes, tNs when the writer closed the journal; alone in the last batch,
//   written by close(). A version 3 journal without it was not closed by its writer (killed,
//   crashed, a write failed, or still being written): the reader says so (Ending::NotClosed),
//   since a kill between two batches leaves a file that otherwise looks whole.
//
// Each batch is written with one write(2) (QFile unbuffered) when it holds batchEntries frames or
// its first frame is batchNs old, whichever comes first (or it reaches 256 MiB), and on close
// (then the end record's batch). That reaches the kernel's
// page cache, which survives the process being killed; sync makes it fdatasync as well, to
// survive a power cut, at the cost of a disk round trip per batch.
class TrafficJournalWriter
{
public:
    struct Options {
        int batchEntries = 1024;
        qint64 batchNs = 100'000'000; // 100 ms
        bool sync = false;
        // A JSON object (UTF-8) written as the journal's first record, flushed at once; none
        // when empty (the journal is then still version 2, without metadata).
        QByteArray metadata;
    };

    TrafficJournalWriter();
    ~TrafficJournalWriter(); // writes the pending batch
    TrafficJournalWriter(const TrafficJournalWriter &) = delete;
    TrafficJournalWriter &operator=(const TrafficJournalWriter &) = delete;

    // Creates the journal and writes its header. An existing file is an error unless overwrite
    // (a journal is evidence: never clobbered by accident). False with *error saying why.
    bool open(const QString &path, const Options &options, bool overwrite = false, QString *error = nullptr);
    void close(); // writes the pending batch and the end record, and closes
    [[nodiscard]] bool isOpen() const { return m_file.isOpen(); }
    [[nodiscard]] QString path() const { return m_file.fileName(); }

    void addLink(quint16 link, QStringView name);
    // A note on a transaction (a JSON object in UTF-8): it goes into the pending batch, in order
    // with the frames, and is not a frame (not counted, no sequence number).
    void addNote(quint16 link, quint64 transactionId, qint64 tNs, QByteArrayView json);
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
    // Distinct transactions among the frames written: a frame whose transaction id is above
    // every id before it on its link starts one (retries share their id; late answers carry an
    // old one; the engines of a shared log each number from 1, each on a link of its own).
    [[nodiscard]] quint64 transactionsWritten() const { return m_transactions; }
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
    quint64 m_transactions = 0;
    quint64 m_batchTransactions = 0;
    QList<quint64> m_lastTransactionIds; // by link id
    qint64 m_bytes = 0;
    QString m_error;
};

// What a read of a journal found.
struct TrafficJournalRecovery {
    enum class Ending : quint8 {
        Clean,       // the file ends where a complete batch ends (version 3: its end record)
        NotClosed,   // version 3 without its end record: the writer never closed it (killed,
                     // crashed, a failed write, or still writing); every batch it wrote is read
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
    quint32 version = 0;    // of the file's format (1, 2 or 3)
    bool closed = false;    // the end record was read (version 3)
    QByteArray metadata;    // the first metadata record's JSON (UTF-8); empty when none
    quint64 notes = 0;
    // "recovered 12,000 frames in 120 batches; the last batch was cut short at byte 480,123 and
    // is dropped (it began at byte 470,040)"; "...; truncated: its writer never closed it (killed
    // or crashed), it stops after the last complete batch, at byte 480,123"
    QString message;

    [[nodiscard]] bool isClean() const { return ending == Ending::Clean; }
};

// A note record as read: the transaction it is about and its JSON text.
struct TrafficJournalNote {
    quint16 link = 0;
    quint64 transactionId = 0;
    qint64 tNs = 0;
    QByteArrayView json; // valid during the call only
};

class TrafficJournalReader
{
public:
    using Sink = std::function<void(const TrafficEntry &)>;
    using NoteSink = std::function<void(const TrafficJournalNote &)>;
    // Reads every frame of every complete, checked batch, in order, into sink (which may be
    // empty to only count), and the notes into notes. A batch is delivered only once all of it
    // has been checked.
    [[nodiscard]] static TrafficJournalRecovery read(const QString &path, const Sink &sink, const NoteSink &notes = {});
    [[nodiscard]] static TrafficJournalRecovery readAll(const QString &path, QList<TrafficFrame> *frames);
};

// One batch of a traffic journal read where it stands (trafficjournal.h gives the format;
// defined beside the reader in trafficjournal.cpp): the frames of the batch at offset of an open
// journal (where its writer's bytesWritten() stood before the batch was flushed), checked by its
// CRCs, into sink; *next: where the next batch starts. False when no whole, sound batch is there.
// TrafficArchive reads its journal back this way, a batch at a time.
bool readJournalBatch(QFile &file, qint64 offset, const TrafficJournalReader::Sink &sink, qint64 *next = nullptr);


} // namespace mbscope
