#include "trafficlog.h"

#include "transport/monotonicclock.h"

#include <algorithm>
#include <cstring>

namespace mbscope {

// One logged frame in memory. The frame's bytes are not here: they sit at the back of the chunk,
// and `end` says how far from the back this frame's bytes end, so a frame's length is its end
// minus the previous record's (no offset and length stored: 24 bytes, not 32).
struct TrafficLog::Record {
    qint64 tNs;
    quint64 transactionId;
    quint32 end;
    quint16 link;
    quint8 direction;
    quint8 verdict;
};
// Records grow from the front, bytes from the back; the chunk is full when they would meet.
struct TrafficLog::Chunk {
    static_assert(sizeof(Record) == 24, "a record is 24 bytes: see the memory note in trafficlog.h");

    std::unique_ptr<char[]> data;
    std::size_t capacity = 0;
    quint32 count = 0;
    quint32 tail = 0;
    quint64 firstSequence = 0;

    [[nodiscard]] Record record(quint32 index) const
    {
        Record r;
        std::memcpy(&r, data.get() + std::size_t(index) * sizeof(Record), sizeof(Record));
        return r;
    }
    [[nodiscard]] quint32 endBefore(quint32 index) const { return index == 0 ? 0 : record(index - 1).end; }
};

TrafficLog::TrafficLog() = default;

TrafficLog::TrafficLog(const Limits &limits) : m_limits(limits) {}

TrafficLog::~TrafficLog()
{
    closeJournal();
}

void TrafficLog::setLimits(const Limits &limits)
{
    m_limits = limits;
    while (m_size > 0 && (m_size > m_limits.maxEntries || m_retainedBytes > m_limits.maxBytes))
        evictOldest();
}

bool TrafficLog::openJournal(const QString &path, const TrafficJournalWriter::Options &options, bool overwrite,
                             QString *error)
{
    if (!m_journal.open(path, options, overwrite, error))
        return false;
    m_journalOptions = options;
    m_rotationError.clear();
    m_stopSaid = false;
    for (qsizetype i = 0; i < m_links.size(); ++i)
        m_journal.addLink(quint16(i), m_links.at(i));
    for (auto it = m_endpoints.cbegin(); it != m_endpoints.cend(); ++it)
        m_journal.addNote(it.key(), 0, monotonicNowNs(), it.value());
    return true;
}

void TrafficLog::setShared(bool shared)
{
    if (shared != isShared())
        m_lock = shared ? std::make_unique<QMutex>() : nullptr;
}

void TrafficLog::closeJournal()
{
    QMutexLocker lock(m_lock.get());
    m_journal.close();
}

void TrafficLog::annotate(quint16 link, quint64 transactionId, qint64 tNs, QByteArrayView json)
{
    QMutexLocker lock(m_lock.get());
    m_journal.addNote(link, transactionId, tNs, json);
}

void TrafficLog::flushIfDue(qint64 nowNs)
{
    QMutexLocker lock(m_lock.get());
    m_journal.flushIfDue(nowNs);
    sayIfStopped();
}

void TrafficLog::flush()
{
    QMutexLocker lock(m_lock.get());
    m_journal.flush();
    sayIfStopped();
}

void TrafficLog::setJournalRotation(qint64 maxBytes, std::function<QString(const QString &)> next)
{
    m_rotateBytes = next ? maxBytes : 0;
    m_nextJournal = std::move(next);
}

void TrafficLog::rotateJournal()
{
    const QString closed = m_journal.path();
    m_journal.close();
    const QString next = m_nextJournal(closed);
    QString error;
    if (next.isEmpty() || !openJournal(next, m_journalOptions, false, &error))
        m_rotationError = next.isEmpty() ? QStringLiteral("%1: no next journal part was given").arg(closed) : error;
    sayIfStopped();
}

void TrafficLog::setJournalStopped(std::function<void(const QString &)> handler)
{
    QMutexLocker lock(m_lock.get());
    m_journalStopped = std::move(handler);
}

void TrafficLog::sayIfStopped()
{
    if (m_stopSaid || (m_rotationError.isEmpty() && m_journal.error().isEmpty()))
        return;
    m_stopSaid = true;
    if (m_journalStopped)
        m_journalStopped(m_rotationError.isEmpty() ? m_journal.error() : m_rotationError);
}

quint16 TrafficLog::addLink(const QString &name)
{
    QMutexLocker lock(m_lock.get());
    if (const qsizetype i = m_links.indexOf(name); i >= 0)
        return quint16(i);
    return appendLink(name);
}

quint16 TrafficLog::addConnection(const QString &name)
{
    QMutexLocker lock(m_lock.get());
    return appendLink(name);
}

quint16 TrafficLog::appendLink(const QString &name)
{
    // 65,535 distinct links in one log is beyond any bench: the rest share the last id.
    if (m_links.size() >= 0xFFFF)
        return 0xFFFF;
    m_links.append(name);
    const auto id = quint16(m_links.size() - 1);
    m_journal.addLink(id, name);
    return id;
}

void TrafficLog::setEndpoints(quint16 link, qint64 tNs, quint64 transactionId, const JournalEndpoints &endpoints)
{
    QMutexLocker lock(m_lock.get());
    QByteArray &json = m_endpoints[link];
    json = endpoints.toJson();
    m_journal.addNote(link, transactionId, tNs, json);
}

QString TrafficLog::linkName(quint16 link) const
{
    return link < m_links.size() ? m_links.at(link) : QString();
}

TrafficLog::Chunk *TrafficLog::chunkFor(std::size_t bytes)
{
    if (!m_chunks.empty()) {
        Chunk &last = *m_chunks.back();
        if ((std::size_t(last.count) + 1) * sizeof(Record) + last.tail + bytes <= last.capacity)
            return &last;
    }
    const std::size_t capacity = std::max(kChunkBytes, sizeof(Record) + bytes);
    std::unique_ptr<Chunk> chunk;
    if (m_spare && m_spare->capacity >= capacity) {
        chunk = std::move(m_spare);
    } else {
        chunk = std::make_unique<Chunk>();
        chunk->data = std::make_unique_for_overwrite<char[]>(capacity);
        chunk->capacity = capacity;
    }
    chunk->count = 0;
    chunk->tail = 0;
    chunk->firstSequence = m_next;
    m_chunks.push_back(std::move(chunk));
    return m_chunks.back().get();
}

quint64 TrafficLog::append(qint64 tNs, TrafficDirection direction, quint16 link, TrafficVerdict verdict,
                           quint64 transactionId, QByteArrayView bytes)
{
    QMutexLocker lock(m_lock.get());
    const auto length = std::size_t(bytes.size());
    Chunk *chunk = chunkFor(length);
    const Record record{tNs, transactionId, quint32(chunk->tail + length), link, quint8(direction), quint8(verdict)};
    if (length > 0)
        std::memcpy(chunk->data.get() + chunk->capacity - record.end, bytes.data(), length);
    std::memcpy(chunk->data.get() + std::size_t(chunk->count) * sizeof(Record), &record, sizeof(Record));
    ++chunk->count;
    chunk->tail = record.end;

    const quint64 sequence = m_next++;
    ++m_size;
    m_retainedBytes += sizeof(Record) + length;
    if (m_journal.isOpen()) {
        m_journal.addFrame(TrafficEntry{sequence, tNs, transactionId, link, direction, verdict, bytes});
        if (m_rotateBytes > 0 && m_journal.bytesWritten() >= m_rotateBytes)
            rotateJournal();
        else if (!m_journal.error().isEmpty())
            sayIfStopped();
    }
    while (m_size > 0 && (m_size > m_limits.maxEntries || m_retainedBytes > m_limits.maxBytes))
        evictOldest();
    return sequence;
}

void TrafficLog::evictOldest()
{
    Chunk &front = *m_chunks.front();
    const quint32 end = front.record(m_headSkip).end;
    m_retainedBytes -= sizeof(Record) + (end - front.endBefore(m_headSkip));
    --m_size;
    if (++m_headSkip < front.count)
        return;
    m_headSkip = 0;
    if (m_chunks.size() == 1) {
        front.count = 0;
        front.tail = 0;
        front.firstSequence = m_next;
        return;
    }
    // Keep one standard chunk for reuse, so a full log cycles without allocating.
    if (front.capacity == kChunkBytes)
        m_spare = std::move(m_chunks.front());
    m_chunks.erase(m_chunks.begin());
}

TrafficEntry TrafficLog::entryAt(const Chunk &chunk, quint32 index) const
{
    const Record r = chunk.record(index);
    const quint32 begin = chunk.endBefore(index);
    TrafficEntry e;
    e.sequence = chunk.firstSequence + index;
    e.tNs = r.tNs;
    e.transactionId = r.transactionId;
    e.link = r.link;
    e.direction = TrafficDirection(r.direction);
    e.verdict = TrafficVerdict(r.verdict);
    e.bytes = QByteArrayView(chunk.data.get() + chunk.capacity - r.end, qsizetype(r.end - begin));
    return e;
}

TrafficEntry TrafficLog::at(quint64 sequence) const
{
    if (sequence < firstSequence() || sequence >= m_next) {
        TrafficEntry none;
        none.sequence = sequence;
        none.verdict = TrafficVerdict::Garbage;
        return none;
    }
    const auto it = std::upper_bound(m_chunks.begin(), m_chunks.end(), sequence,
                                     [](quint64 s, const std::unique_ptr<Chunk> &c) { return s < c->firstSequence; });
    const Chunk &chunk = **(it - 1);
    return entryAt(chunk, quint32(sequence - chunk.firstSequence));
}

void TrafficLog::visit(quint64 from, bool forward, const std::function<bool(const TrafficEntry &)> &visitor) const
{
    if (from < firstSequence() || from >= m_next)
        return;
    const auto it = std::upper_bound(m_chunks.begin(), m_chunks.end(), from,
                                     [](quint64 s, const std::unique_ptr<Chunk> &c) { return s < c->firstSequence; });
    auto chunk = std::size_t(it - m_chunks.begin()) - 1;
    auto index = qint64(from - m_chunks[chunk]->firstSequence);
    for (;;) {
        const Chunk &c = *m_chunks[chunk];
        const qint64 first = chunk == 0 ? qint64(m_headSkip) : 0;
        for (; index >= first && index < qint64(c.count); index += forward ? 1 : -1) {
            if (!visitor(entryAt(c, quint32(index))))
                return;
        }
        if (forward ? chunk + 1 >= m_chunks.size() : chunk == 0)
            return;
        chunk += forward ? 1 : std::size_t(-1);
        index = forward ? 0 : qint64(m_chunks[chunk]->count) - 1;
    }
}

void TrafficLog::dropOldest(quint64 count)
{
    for (quint64 i = 0; i < count && m_size > 0; ++i)
        evictOldest();
}

QList<TrafficFrame> TrafficLog::copy(quint64 fromSequence, qsizetype maxCount) const
{
    QList<TrafficFrame> frames;
    const quint64 from = std::max(fromSequence, firstSequence());
    if (from >= m_next || maxCount <= 0)
        return frames;
    const quint64 to = std::min(m_next, from + quint64(maxCount));
    frames.reserve(qsizetype(to - from));
    for (quint64 s = from; s < to; ++s)
        frames.append(TrafficFrame::from(at(s)));
    return frames;
}

std::size_t TrafficLog::memoryBytes() const
{
    std::size_t bytes = m_chunks.capacity() * sizeof(std::unique_ptr<Chunk>);
    for (const auto &chunk : m_chunks)
        bytes += sizeof(Chunk) + chunk->capacity;
    if (m_spare)
        bytes += sizeof(Chunk) + m_spare->capacity;
    bytes += m_journal.memoryBytes();
    bytes += std::size_t(m_links.capacity()) * sizeof(QString);
    for (const QString &name : m_links)
        bytes += std::size_t(name.capacity()) * sizeof(QChar);
    return bytes;
}

} // namespace mbscope
