#include "trafficjournal.h"

#include "transport/monotonicclock.h"

#include <QtCore/QDateTime>
#include <QtCore/QLocale>
#include <QtCore/QtEndian>

#include <algorithm>
#include <array>
#include <cstring>

#if defined(Q_OS_UNIX)
#include <unistd.h>
#endif

namespace mbscope {

namespace {

constexpr char kFileMagic[8] = {'M', 'B', 'S', 'C', 'T', 'L', 'O', 'G'};
constexpr char kBatchMagic[4] = {'B', 'T', 'C', 'H'};
constexpr quint32 kVersion = 3;
constexpr quint32 kOldestVersion = 1;
constexpr std::size_t kFileHeaderSize = 40;
constexpr std::size_t kBatchHeaderSize = 32;
constexpr std::size_t kRecordHeaderSize = 28;
constexpr quint8 kKindFrame = 1;
constexpr quint8 kKindLink = 2;
constexpr quint8 kKindMetadata = 3;
constexpr quint8 kKindNote = 4;
constexpr quint8 kKindEnd = 5;

// CRC-32/ISO-HDLC, slicing by 8 (eight table lookups per 8 bytes): about 1-2 GB/s, so the
// checksum of a batch costs a few ns per logged frame on the engine's thread.
struct Crc32Tables {
    std::array<std::array<quint32, 256>, 8> t{};
    constexpr Crc32Tables()
    {
        for (quint32 i = 0; i < 256; ++i) {
            quint32 c = i;
            for (int bit = 0; bit < 8; ++bit)
                c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
            t[0][i] = c;
        }
        for (quint32 i = 0; i < 256; ++i)
            for (std::size_t k = 1; k < 8; ++k)
                t[k][i] = (t[k - 1][i] >> 8) ^ t[0][t[k - 1][i] & 0xFF];
    }
};
constexpr Crc32Tables kCrc;

QString grouped(qint64 n)
{
    return QLocale(QLocale::English, QLocale::UnitedStates).toString(n);
}

template<typename T>
T readLe(const char *p)
{
    return qFromLittleEndian<T>(p);
}

// A frame record (its header at rec) as the entry it holds, numbered sequence.
TrafficEntry frameEntry(const char *rec, quint64 sequence)
{
    TrafficEntry e;
    e.sequence = sequence;
    e.direction = TrafficDirection(quint8(rec[1]) & 1);
    e.verdict = quint8(rec[2]) < kTrafficVerdictCount ? TrafficVerdict(quint8(rec[2])) : TrafficVerdict::Garbage;
    e.link = readLe<quint16>(rec + 4);
    e.tNs = readLe<qint64>(rec + 12);
    e.transactionId = readLe<quint64>(rec + 20);
    e.bytes = QByteArrayView(rec + kRecordHeaderSize, qsizetype(readLe<quint32>(rec + 8)));
    return e;
}

} // namespace

quint32 TrafficJournalWriter::crc32(const void *data, std::size_t size)
{
    const auto *p = static_cast<const unsigned char *>(data);
    quint32 c = 0xFFFFFFFFu;
    while (size >= 8) {
        const quint32 lo = c ^ (quint32(p[0]) | quint32(p[1]) << 8 | quint32(p[2]) << 16 | quint32(p[3]) << 24);
        c = kCrc.t[7][lo & 0xFF] ^ kCrc.t[6][(lo >> 8) & 0xFF] ^ kCrc.t[5][(lo >> 16) & 0xFF] ^ kCrc.t[4][lo >> 24]
            ^ kCrc.t[3][p[4]] ^ kCrc.t[2][p[5]] ^ kCrc.t[1][p[6]] ^ kCrc.t[0][p[7]];
        p += 8;
        size -= 8;
    }
    while (size-- > 0)
        c = (c >> 8) ^ kCrc.t[0][(c ^ *p++) & 0xFF];
    return c ^ 0xFFFFFFFFu;
}

TrafficJournalWriter::TrafficJournalWriter() = default;

TrafficJournalWriter::~TrafficJournalWriter()
{
    close();
}

bool TrafficJournalWriter::open(const QString &path, const Options &options, bool overwrite, QString *error)
{
    close();
    m_error.clear();
    m_options = options;
    m_options.batchEntries = std::max(1, options.batchEntries);
    m_batches = m_frames = m_lost = 0;
    m_transactions = m_batchTransactions = 0;
    m_lastTransactionIds.clear();
    m_bytes = 0;
    m_file.setFileName(path);
    QIODevice::OpenMode mode = QIODevice::WriteOnly | QIODevice::Unbuffered;
    mode |= overwrite ? QIODevice::Truncate : QIODevice::NewOnly;
    if (!m_file.open(mode)) {
        if (error)
            *error = QStringLiteral("%1: cannot create the traffic journal: %2")
                         .arg(path, !overwrite && m_file.exists() ? QStringLiteral("the file exists (a journal is never overwritten)")
                                                                 : m_file.errorString());
        return false;
    }
    char header[kFileHeaderSize] = {};
    std::memcpy(header, kFileMagic, sizeof kFileMagic);
    qToLittleEndian<quint32>(kVersion, header + 8);
    qToLittleEndian<quint32>(quint32(kFileHeaderSize), header + 12);
    qToLittleEndian<qint64>(QDateTime::currentMSecsSinceEpoch(), header + 16);
    qToLittleEndian<qint64>(monotonicNowNs(), header + 24);
    qToLittleEndian<quint32>(crc32(header, 36), header + 36);
    if (m_file.write(header, qint64(kFileHeaderSize)) != qint64(kFileHeaderSize)) {
        if (error)
            *error = QStringLiteral("%1: cannot write the traffic journal's header: %2").arg(path, m_file.errorString());
        m_file.close();
        return false;
    }
    m_bytes = qint64(kFileHeaderSize);
    // A batch of small frames, header space included; it grows if frames are bigger.
    const std::size_t wanted = kBatchHeaderSize + std::size_t(m_options.batchEntries) * (kRecordHeaderSize + 16);
    if (m_capacity < wanted) {
        m_buffer = std::make_unique<char[]>(wanted);
        m_capacity = wanted;
    }
    startBatch();
    if (!options.metadata.isEmpty()) {
        char *p = reserve(kRecordHeaderSize + std::size_t(options.metadata.size()));
        std::memset(p, 0, kRecordHeaderSize);
        p[0] = char(kKindMetadata);
        qToLittleEndian<quint32>(quint32(options.metadata.size()), p + 8);
        qToLittleEndian<qint64>(monotonicNowNs(), p + 12);
        std::memcpy(p + kRecordHeaderSize, options.metadata.constData(), std::size_t(options.metadata.size()));
        ++m_batchRecords;
        flush();
        if (!m_error.isEmpty()) {
            if (error)
                *error = m_error;
            m_file.close();
            return false;
        }
    }
    return true;
}

void TrafficJournalWriter::close()
{
    if (!m_file.isOpen())
        return;
    flush();
    if (m_error.isEmpty()) {
        // The end record, alone in the last batch: a reader tells a journal closed from one whose
        // writer was killed between two batches. It is not a batch of traffic (not counted).
        const quint64 batches = m_batches;
        char *p = reserve(kRecordHeaderSize);
        std::memset(p, 0, kRecordHeaderSize);
        p[0] = char(kKindEnd);
        qToLittleEndian<qint64>(monotonicNowNs(), p + 12);
        ++m_batchRecords;
        flush();
        m_batches = batches;
    }
    m_file.close();
}

void TrafficJournalWriter::startBatch()
{
    m_size = kBatchHeaderSize;
    m_batchFrames = 0;
    m_batchRecords = 0;
    m_batchFirstSequence = 0;
    m_batchFirstNs = 0;
}

char *TrafficJournalWriter::reserve(std::size_t bytes)
{
    if (m_size + bytes > m_capacity) {
        const std::size_t capacity = std::max(m_capacity * 2, m_size + bytes);
        auto grown = std::make_unique<char[]>(capacity);
        if (m_size > 0)
            std::memcpy(grown.get(), m_buffer.get(), m_size);
        m_buffer = std::move(grown);
        m_capacity = capacity;
    }
    char *p = m_buffer.get() + m_size;
    m_size += bytes;
    return p;
}

void TrafficJournalWriter::addLink(quint16 link, QStringView name)
{
    if (!m_file.isOpen() || !m_error.isEmpty())
        return;
    const QByteArray utf8 = name.toUtf8();
    char *p = reserve(kRecordHeaderSize + std::size_t(utf8.size()));
    std::memset(p, 0, kRecordHeaderSize);
    p[0] = char(kKindLink);
    qToLittleEndian<quint16>(link, p + 4);
    qToLittleEndian<quint32>(quint32(utf8.size()), p + 8);
    std::memcpy(p + kRecordHeaderSize, utf8.constData(), std::size_t(utf8.size()));
    ++m_batchRecords;
}

void TrafficJournalWriter::addNote(quint16 link, quint64 transactionId, qint64 tNs, QByteArrayView json)
{
    if (!m_file.isOpen() || !m_error.isEmpty())
        return;
    char *p = reserve(kRecordHeaderSize + std::size_t(json.size()));
    std::memset(p, 0, kRecordHeaderSize);
    p[0] = char(kKindNote);
    qToLittleEndian<quint16>(link, p + 4);
    qToLittleEndian<quint32>(quint32(json.size()), p + 8);
    qToLittleEndian<qint64>(tNs, p + 12);
    qToLittleEndian<quint64>(transactionId, p + 20);
    if (!json.isEmpty())
        std::memcpy(p + kRecordHeaderSize, json.data(), std::size_t(json.size()));
    ++m_batchRecords;
}

void TrafficJournalWriter::addFrame(const TrafficEntry &entry)
{
    if (!m_file.isOpen())
        return;
    if (!m_error.isEmpty()) {
        ++m_lost;
        return;
    }
    const auto length = std::size_t(entry.bytes.size());
    char *p = reserve(kRecordHeaderSize + length);
    p[0] = char(kKindFrame);
    p[1] = char(entry.direction);
    p[2] = char(entry.verdict);
    p[3] = 0;
    qToLittleEndian<quint16>(entry.link, p + 4);
    qToLittleEndian<quint16>(0, p + 6);
    qToLittleEndian<quint32>(quint32(length), p + 8);
    qToLittleEndian<qint64>(entry.tNs, p + 12);
    qToLittleEndian<quint64>(entry.transactionId, p + 20);
    if (length > 0)
        std::memcpy(p + kRecordHeaderSize, entry.bytes.data(), length);
    if (m_batchFrames == 0) {
        m_batchFirstSequence = entry.sequence;
        m_batchFirstNs = entry.tNs;
    }
    if (entry.link >= m_lastTransactionIds.size())
        m_lastTransactionIds.resize(qsizetype(entry.link) + 1, 0);
    if (quint64 &last = m_lastTransactionIds[entry.link]; entry.transactionId > last) {
        last = entry.transactionId;
        ++m_batchTransactions;
    }
    ++m_batchFrames;
    ++m_batchRecords;
    // A batch also ends at 256 MiB, far inside the header's 32-bit payload size.
    if (m_batchFrames >= quint32(m_options.batchEntries) || entry.tNs - m_batchFirstNs >= m_options.batchNs
        || m_size >= (std::size_t(1) << 28))
        flush();
}

void TrafficJournalWriter::flushIfDue(qint64 nowNs)
{
    if (m_batchFrames > 0 && nowNs - m_batchFirstNs >= m_options.batchNs)
        flush();
}

void TrafficJournalWriter::flush()
{
    if (!m_file.isOpen() || m_batchRecords == 0 || !m_error.isEmpty())
        return;
    char *h = m_buffer.get();
    const std::size_t payload = m_size - kBatchHeaderSize;
    std::memcpy(h, kBatchMagic, sizeof kBatchMagic);
    qToLittleEndian<quint32>(quint32(payload), h + 4);
    qToLittleEndian<quint32>(m_batchFrames, h + 8);
    qToLittleEndian<quint32>(m_batchRecords, h + 12);
    qToLittleEndian<quint64>(m_batchFirstSequence, h + 16);
    qToLittleEndian<quint32>(crc32(h + kBatchHeaderSize, payload), h + 24);
    qToLittleEndian<quint32>(crc32(h, 28), h + 28);
    // One write for the whole batch: the kernel sees it at once, and a kill between two batches
    // leaves only whole ones behind.
    const qint64 written = m_file.write(h, qint64(m_size));
    if (written != qint64(m_size)) {
        m_error = QStringLiteral("%1: write failed after %2 batches: %3")
                      .arg(m_file.fileName(), grouped(qint64(m_batches)), m_file.errorString());
        m_lost += m_batchFrames;
        m_batchTransactions = 0;
        startBatch();
        return;
    }
#if defined(Q_OS_UNIX)
    if (m_options.sync)
        ::fdatasync(m_file.handle());
#endif
    m_bytes += written;
    m_frames += m_batchFrames;
    m_transactions += m_batchTransactions;
    m_batchTransactions = 0;
    ++m_batches;
    startBatch();
}

TrafficJournalRecovery TrafficJournalReader::readAll(const QString &path, QList<TrafficFrame> *frames)
{
    return read(path, [frames](const TrafficEntry &entry) {
        if (frames)
            frames->append(TrafficFrame::from(entry));
    });
}

TrafficJournalRecovery TrafficJournalReader::read(const QString &path, const Sink &sink, const NoteSink &notes)
{
    TrafficJournalRecovery r;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        r.message = QStringLiteral("%1: cannot open the traffic journal: %2").arg(path, file.errorString());
        return r;
    }
    r.fileBytes = file.size();
    QByteArray copy;
    const char *data = reinterpret_cast<const char *>(r.fileBytes > 0 ? file.map(0, r.fileBytes) : nullptr);
    if (!data && r.fileBytes > 0) {
        copy = file.readAll();
        data = copy.constData();
        r.fileBytes = copy.size();
    }
    const auto size = std::size_t(r.fileBytes);

    r.ending = TrafficJournalRecovery::Ending::NotAJournal;
    if (size < kFileHeaderSize) {
        r.message = QStringLiteral("%1: the journal's header was cut short at byte %2 (%3 bytes expected): nothing to recover")
                        .arg(path, grouped(r.fileBytes), QString::number(kFileHeaderSize));
        return r;
    }
    if (std::memcmp(data, kFileMagic, sizeof kFileMagic) != 0) {
        r.message = QStringLiteral("%1: not an mbscope traffic journal (it does not start with \"MBSCTLOG\")").arg(path);
        return r;
    }
    if (readLe<quint32>(data + 36) != TrafficJournalWriter::crc32(data, 36)) {
        r.message = QStringLiteral("%1: the journal's header fails its CRC: nothing to recover").arg(path);
        return r;
    }
    const auto version = readLe<quint32>(data + 8);
    const auto headerSize = readLe<quint32>(data + 12);
    if (version < kOldestVersion || version > kVersion || headerSize < kFileHeaderSize || headerSize > size) {
        r.message = QStringLiteral("%1: journal version %2 (header %3 bytes) is not one this mbscope reads (versions %4 to %5)")
                        .arg(path, QString::number(version), QString::number(headerSize), QString::number(kOldestVersion),
                             QString::number(kVersion));
        return r;
    }
    r.version = version;
    const quint8 lastKind = version >= 3 ? kKindEnd : version >= 2 ? kKindNote : kKindLink;
    r.wallClockMs = readLe<qint64>(data + 16);
    r.monotonicNs = readLe<qint64>(data + 24);

    std::size_t at = headerSize;
    quint64 nextSequence = 0;
    bool sawFrames = false;
    QString trouble;
    r.ending = TrafficJournalRecovery::Ending::Clean;
    while (at < size) {
        const char *h = data + at;
        const std::size_t left = size - at;
        if (left < kBatchHeaderSize) {
            r.ending = TrafficJournalRecovery::Ending::CutShort;
            break;
        }
        if (std::memcmp(h, kBatchMagic, sizeof kBatchMagic) != 0 || readLe<quint32>(h + 28) != TrafficJournalWriter::crc32(h, 28)) {
            r.ending = TrafficJournalRecovery::Ending::Corrupt;
            trouble = QStringLiteral("its header is damaged");
            break;
        }
        const auto payload = std::size_t(readLe<quint32>(h + 4));
        const auto frames = readLe<quint32>(h + 8);
        const auto records = readLe<quint32>(h + 12);
        const auto firstSequence = readLe<quint64>(h + 16);
        if (left - kBatchHeaderSize < payload) {
            r.ending = TrafficJournalRecovery::Ending::CutShort;
            break;
        }
        const char *p = h + kBatchHeaderSize;
        const quint32 expectedCrc = readLe<quint32>(h + 24);
        if (const quint32 crc = TrafficJournalWriter::crc32(p, payload); crc != expectedCrc) {
            r.ending = TrafficJournalRecovery::Ending::Corrupt;
            trouble = QStringLiteral("its payload CRC is 0x%1, the header says 0x%2")
                          .arg(QString::number(crc, 16).toUpper().rightJustified(8, QLatin1Char('0')),
                               QString::number(expectedCrc, 16).toUpper().rightJustified(8, QLatin1Char('0')));
            break;
        }
        if (sawFrames && frames > 0 && firstSequence != nextSequence) {
            r.ending = TrafficJournalRecovery::Ending::Corrupt;
            trouble = QStringLiteral("its first frame is number %1, %2 was next").arg(firstSequence).arg(nextSequence);
            break;
        }
        // Check every record's bounds before delivering any of the batch.
        quint32 seenFrames = 0, seenRecords = 0;
        std::size_t off = 0;
        while (off + kRecordHeaderSize <= payload) {
            const std::size_t length = readLe<quint32>(p + off + 8);
            const auto kind = quint8(p[off]);
            if (kind < kKindFrame || kind > lastKind || length > payload - off - kRecordHeaderSize)
                break;
            seenFrames += kind == kKindFrame ? 1 : 0;
            ++seenRecords;
            off += kRecordHeaderSize + length;
        }
        if (off != payload || seenFrames != frames || seenRecords != records) {
            r.ending = TrafficJournalRecovery::Ending::Corrupt;
            trouble = QStringLiteral("its records do not add up to its header (%1 frames, %2 records, %3 bytes)")
                          .arg(frames).arg(records).arg(payload);
            break;
        }
        quint64 sequence = firstSequence;
        for (off = 0; off < payload;) {
            const char *rec = p + off;
            const std::size_t length = readLe<quint32>(rec + 8);
            const auto link = readLe<quint16>(rec + 4);
            const auto kind = quint8(rec[0]);
            if (kind == kKindLink) {
                while (r.links.size() <= link)
                    r.links.append(QString());
                r.links[link] = QString::fromUtf8(rec + kRecordHeaderSize, qsizetype(length));
            } else if (kind == kKindMetadata) {
                if (r.metadata.isEmpty())
                    r.metadata = QByteArray(rec + kRecordHeaderSize, qsizetype(length));
            } else if (kind == kKindEnd) {
                r.closed = true;
            } else if (kind == kKindNote) {
                ++r.notes;
                if (notes)
                    notes(TrafficJournalNote{link, readLe<quint64>(rec + 20), readLe<qint64>(rec + 12),
                                             QByteArrayView(rec + kRecordHeaderSize, qsizetype(length))});
            } else if (sink) {
                sink(frameEntry(rec, sequence));
            }
            sequence += kind == kKindFrame ? 1 : 0;
            off += kRecordHeaderSize + length;
        }
        r.frames += frames;
        if (frames > 0) {
            nextSequence = firstSequence + frames;
            sawFrames = true;
        }
        // The end record's batch is not one of traffic (the writer does not count it either).
        const bool endOnly = records == 1 && frames == 0 && quint8(p[0]) == kKindEnd;
        r.batches += endOnly ? 0 : 1;
        at += kBatchHeaderSize + payload;
        r.goodBytes = qint64(at);
    }
    if (r.goodBytes == 0)
        r.goodBytes = qint64(std::min<std::size_t>(headerSize, size));
    if (r.ending == TrafficJournalRecovery::Ending::Clean && version >= 3 && !r.closed)
        r.ending = TrafficJournalRecovery::Ending::NotClosed;

    QString text = QStringLiteral("recovered %1 frames in %2 batches").arg(grouped(qint64(r.frames)), grouped(qint64(r.batches)));
    switch (r.ending) {
    case TrafficJournalRecovery::Ending::Clean:
        text += version >= 3 ? QStringLiteral("; the journal ends cleanly at byte %1").arg(grouped(r.fileBytes))
                             : QStringLiteral("; the journal ends after a complete batch, at byte %1 (a version %2 journal does not "
                                              "say whether its writer closed it)")
                                   .arg(grouped(r.fileBytes))
                                   .arg(version);
        break;
    case TrafficJournalRecovery::Ending::NotClosed:
        text += QStringLiteral("; truncated: its writer never closed it (killed, crashed or still writing), it stops after "
                               "the last complete batch, at byte %1; whatever the writer held then is not in it")
                    .arg(grouped(r.fileBytes));
        break;
    case TrafficJournalRecovery::Ending::CutShort:
        text += QStringLiteral("; the last batch was cut short at byte %1 and is dropped (it began at byte %2)")
                    .arg(grouped(r.fileBytes), grouped(r.goodBytes));
        break;
    case TrafficJournalRecovery::Ending::Corrupt:
        text += QStringLiteral("; the batch at byte %1 is damaged (%2): it and all after it, %3 bytes, are dropped")
                    .arg(grouped(r.goodBytes), trouble, grouped(r.fileBytes - r.goodBytes));
        break;
    case TrafficJournalRecovery::Ending::NotAJournal:
    case TrafficJournalRecovery::Ending::Unreadable:
        break;
    }
    r.message = text;
    return r;
}

bool readJournalBatch(QFile &file, qint64 offset, const TrafficJournalReader::Sink &sink, qint64 *next)
{
    char h[kBatchHeaderSize];
    if (!file.seek(offset) || file.read(h, qint64(kBatchHeaderSize)) != qint64(kBatchHeaderSize)
        || std::memcmp(h, kBatchMagic, sizeof kBatchMagic) != 0 || readLe<quint32>(h + 28) != TrafficJournalWriter::crc32(h, 28))
        return false;
    const auto payload = qint64(readLe<quint32>(h + 4));
    const QByteArray p = file.read(payload);
    if (p.size() != payload || TrafficJournalWriter::crc32(p.constData(), std::size_t(payload)) != readLe<quint32>(h + 24))
        return false;
    quint64 sequence = readLe<quint64>(h + 16);
    for (qint64 off = 0; off + qint64(kRecordHeaderSize) <= payload;) {
        const char *rec = p.constData() + off;
        const auto length = qint64(readLe<quint32>(rec + 8));
        if (length > payload - off - qint64(kRecordHeaderSize))
            return false;
        if (quint8(rec[0]) == kKindFrame) {
            if (sink)
                sink(frameEntry(rec, sequence));
            ++sequence;
        }
        off += qint64(kRecordHeaderSize) + length;
    }
    if (next)
        *next = offset + qint64(kBatchHeaderSize) + payload;
    return true;
}

} // namespace mbscope
