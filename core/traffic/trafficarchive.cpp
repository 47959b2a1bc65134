#include "trafficarchive.h"

#include "trafficjournal.h"


#include <QtCore/QDir>
#include <QtCore/QTemporaryFile>

#include <limits>

namespace mbscope {

TrafficArchive::TrafficArchive() = default;

TrafficArchive::~TrafficArchive()
{
    clear();
}

bool TrafficArchive::open(const QString &folder, QString *error)
{
    clear();
    if (!QDir().mkpath(folder)) {
        if (error)
            *error = QStringLiteral("%1: cannot make the folder for the traffic list's older frames").arg(folder);
        return false;
    }
    // A unique name that is ours; the writer opens it again (it never clobbers by accident,
    // so overwrite is said: the file is the empty one just made).
    QTemporaryFile name(QDir(folder).filePath(QStringLiteral("traffic-list-XXXXXX.mbscope.journal")));
    name.setAutoRemove(false);
    if (!name.open()) {
        if (error)
            *error = QStringLiteral("%1: cannot make the traffic list's archive: %2").arg(folder, name.errorString());
        return false;
    }
    m_path = name.fileName();
    name.close();
    TrafficJournalWriter::Options options;
    // Batches of kBatchFrames frames, whatever their times: append() hands the writer a whole
    // batch at once, so each batch starts at a known frame.
    options.batchEntries = kBatchFrames;
    options.batchNs = std::numeric_limits<qint64>::max();
    if (!m_writer.open(m_path, options, true, error)) {
        QFile::remove(m_path);
        m_path.clear();
        return false;
    }
    m_reader.setFileName(m_path);
    if (!m_reader.open(QIODevice::ReadOnly | QIODevice::Unbuffered)) {
        if (error)
            *error = QStringLiteral("%1: cannot read the traffic list's archive: %2").arg(m_path, m_reader.errorString());
        clear();
        return false;
    }
#if defined(Q_OS_UNIX)
    // Both ends are open: the name can go, and the file with the last of them, even when the
    // process is killed (no archive is ever left behind in the folder).
    QFile::remove(m_path);
#endif
    return true;
}

void TrafficArchive::clear()
{
    m_reader.close();
    if (m_writer.isOpen())
        m_writer.close();
    if (!m_path.isEmpty())
        QFile::remove(m_path);
    m_path.clear();
    m_offsets.clear();
    m_pending.clear();
    m_size = 0;
    m_cache.clear();
    m_cacheIndex.clear();
    m_readError.clear();
}

const QString &TrafficArchive::error() const
{
    return m_writer.error().isEmpty() ? m_readError : m_writer.error();
}

bool TrafficArchive::append(const TrafficEntry &entry)
{
    if (!m_writer.isOpen() || entry.sequence != m_size || !m_writer.error().isEmpty())
        return false;
    if (m_pending.empty())
        m_pending.reserve(kBatchFrames);
    m_pending.push_back(TrafficFrame::from(entry));
    ++m_size;
    if (m_pending.size() < std::size_t(kBatchFrames))
        return true;
    const qint64 offset = m_writer.bytesWritten();
    for (const TrafficFrame &f : m_pending)
        m_writer.addFrame(TrafficEntry{f.sequence, f.tNs, f.transactionId, f.link, f.direction, f.verdict, f.bytes});
    m_writer.flush();
    if (!m_writer.error().isEmpty()) {
        m_size -= m_pending.size();
        m_pending.clear();
        return false;
    }
    m_offsets.push_back(offset);
    std::vector<TrafficFrame>().swap(m_pending);
    return true;
}

const TrafficArchive::Batch *TrafficArchive::batch(std::size_t index) const
{
    ++m_clock;
    for (std::size_t slot = 0; slot < m_cache.size(); ++slot) {
        if (m_cacheIndex[slot] == index) {
            m_cache[slot]->used = m_clock;
            return m_cache[slot].get();
        }
    }
    auto read = std::make_unique<Batch>();
    read->first = quint64(index) * kBatchFrames;
    read->frames.reserve(kBatchFrames);
    const bool ok = readJournalBatch(m_reader, m_offsets[index], [&read](const TrafficEntry &e) {
        read->frames.push_back(TrafficFrame::from(e));
    });
    if (!ok || read->frames.size() != std::size_t(kBatchFrames) || read->frames.front().sequence != read->first) {
        m_readError = QStringLiteral("%1: the batch at byte %2 of the traffic list's archive is damaged").arg(m_path).arg(m_offsets[index]);
        return nullptr;
    }
    read->used = m_clock;
    if (m_cache.size() < std::size_t(kCachedBatches)) {
        m_cache.push_back(std::move(read));
        m_cacheIndex.push_back(index);
        return m_cache.back().get();
    }
    std::size_t oldest = 0;
    for (std::size_t slot = 1; slot < m_cache.size(); ++slot) {
        if (m_cache[slot]->used < m_cache[oldest]->used)
            oldest = slot;
    }
    m_cache[oldest] = std::move(read);
    m_cacheIndex[oldest] = index;
    return m_cache[oldest].get();
}

namespace {

TrafficEntry entryOf(const TrafficFrame &f)
{
    return TrafficEntry{f.sequence, f.tNs, f.transactionId, f.link, f.direction, f.verdict, f.bytes};
}

} // namespace

TrafficEntry TrafficArchive::at(quint64 sequence) const
{
    TrafficEntry missing;
    missing.sequence = sequence;
    missing.verdict = TrafficVerdict::Garbage;
    if (sequence >= m_size)
        return missing;
    const quint64 written = quint64(m_offsets.size()) * kBatchFrames;
    if (sequence >= written)
        return entryOf(m_pending[std::size_t(sequence - written)]);
    const Batch *b = batch(std::size_t(sequence / kBatchFrames));
    return b ? entryOf(b->frames[std::size_t(sequence - b->first)]) : missing;
}

void TrafficArchive::visit(quint64 from, bool forward, const std::function<bool(const TrafficEntry &)> &visitor) const
{
    if (from >= m_size)
        return;
    const quint64 written = quint64(m_offsets.size()) * kBatchFrames;
    quint64 s = from;
    while (true) {
        if (s >= written) {
            if (!visitor(entryOf(m_pending[std::size_t(s - written)])))
                return;
        } else {
            const Batch *b = batch(std::size_t(s / kBatchFrames));
            if (!b)
                return;
            // The whole batch while it is at hand: one cache look-up per batch, not per frame.
            const quint64 end = b->first + kBatchFrames;
            while (true) {
                if (!visitor(entryOf(b->frames[std::size_t(s - b->first)])))
                    return;
                if (forward ? s + 1 >= end : s == b->first)
                    break;
                s = forward ? s + 1 : s - 1;
            }
        }
        if (forward ? s + 1 >= m_size : s == 0)
            return;
        s = forward ? s + 1 : s - 1;
    }
}

std::size_t TrafficArchive::memoryBytes() const
{
    std::size_t bytes = m_offsets.capacity() * sizeof(qint64) + m_pending.capacity() * sizeof(TrafficFrame)
        + m_writer.memoryBytes();
    for (const TrafficFrame &f : m_pending)
        bytes += std::size_t(f.bytes.capacity());
    for (const auto &b : m_cache) {
        bytes += sizeof(Batch) + b->frames.capacity() * sizeof(TrafficFrame);
        for (const TrafficFrame &f : b->frames)
            bytes += std::size_t(f.bytes.capacity());
    }
    return bytes;
}

} // namespace mbscope
