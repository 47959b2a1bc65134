#include "trafficmodel.h"

#include "common/coretext.h"

#include "common/exchangeformat.h"
#include "common/severitystyle.h"
#include "trafficsearch.h"
#include "common/trafficstyle.h"

#include "protocol/functioncode.h"
#include "protocol/hexformat.h"
#include "protocol/hextext.h"
#include "transport/monotonicclock.h"

#include <QtGui/QFontDatabase>

#include <algorithm>
#include <limits>

namespace mbscope {

namespace {

TrafficLog::Limits unbounded()
{
    TrafficLog::Limits limits;
    limits.maxEntries = std::numeric_limits<quint64>::max();
    limits.maxBytes = std::numeric_limits<quint64>::max();
    return limits;
}

// Statuses whose frame in is empty: no answer, so no latency.
bool answered(const TrafficEntry &frame)
{
    return frame.direction == TrafficDirection::In && !frame.bytes.isEmpty();
}

} // namespace

TrafficModel::TrafficModel(QObject *parent)
    : QAbstractTableModel(parent)
    , m_log(std::make_unique<TrafficLog>(unbounded()))
    , m_pairs(std::size_t(kPairCacheSize))
    , m_monoFont(QFontDatabase::systemFont(QFontDatabase::FixedFont))
{
}

TrafficModel::~TrafficModel() = default;

void TrafficModel::setLinkName(quint16 link, const QString &url)
{
    m_links.setName(link, url);
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, LinkColumn), index(rowCount() - 1, LinkColumn));
}

void TrafficModel::setCurrentLink(const QString &url)
{
    m_currentLink = m_links.idOf(url);
    m_hasCurrentLink = true;
}

void TrafficModel::setFilter(const TrafficFilter &filter)
{
    if (filter == m_filter)
        return;
    beginResetModel();
    m_filter = filter;
    rebuildShown();
    endResetModel();
}

void TrafficModel::rebuildShown()
{
    m_filtered = !m_filter.acceptsAll();
    std::vector<quint32>().swap(m_shown);
    if (!m_filtered)
        return;
    const quint64 first = firstKept();
    visitFrames(first, true, [&](const TrafficEntry &e) {
        if (e.sequence >= m_publishedEnd)
            return false;
        if (m_filter.accepts(e, keysAt(qsizetype(e.sequence - first))))
            m_shown.push_back(quint32(e.sequence - first));
        return true;
    });
}

void TrafficModel::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    if (!paused)
        publish();
    Q_EMIT countsChanged();
}

void TrafficModel::setRowLimit(qsizetype limit)
{
    m_rowLimit = std::max<qsizetype>(limit, 10);
    enforceLimit();
    Q_EMIT countsChanged();
}

void TrafficModel::setByteLimit(quint64 bytes)
{
    m_byteLimit = std::max<quint64>(bytes, 4096);
    enforceLimit();
    Q_EMIT countsChanged();
}

qsizetype TrafficModel::storeRow(int row) const
{
    if (row < 0 || row >= rowCount())
        return -1;
    return m_filtered ? qsizetype(m_shown[size_t(row)]) : row;
}

int TrafficModel::rowOfStoreRow(qsizetype storeRow) const
{
    const qsizetype published = qsizetype(m_publishedEnd - firstKept());
    if (storeRow < 0 || storeRow >= published)
        return -1;
    if (!m_filtered)
        return int(storeRow);
    const auto it = std::lower_bound(m_shown.begin(), m_shown.end(), quint32(storeRow));
    return it != m_shown.end() && *it == quint32(storeRow) ? int(it - m_shown.begin()) : -1;
}

TrafficEntry TrafficModel::frameAt(qsizetype storeRow) const
{
    const quint64 sequence = sequenceOf(storeRow);
    return sequence < m_log->firstSequence() && m_archive ? m_archive->at(sequence) : m_log->at(sequence);
}

void TrafficModel::visitFrames(quint64 from, bool forward, const std::function<bool(const TrafficEntry &)> &visitor) const
{
    const quint64 inMemory = m_log->firstSequence();
    bool goOn = true;
    const auto seen = [&](const TrafficEntry &e) { return goOn = visitor(e); };
    if (forward) {
        if (from < inMemory && m_archive) {
            m_archive->visit(from, true, seen);
            if (!goOn)
                return;
            from = inMemory;
        }
        m_log->visit(std::max(from, inMemory), true, seen);
        return;
    }
    if (from >= inMemory) {
        m_log->visit(from, false, seen);
        if (!goOn || inMemory == 0)
            return;
        from = inMemory - 1;
    }
    if (m_archive)
        m_archive->visit(from, false, seen);
}

void TrafficModel::setArchiveFolder(const QString &folder)
{
    m_archiveFolder = folder;
}

qsizetype TrafficModel::pairedRow(qsizetype storeRow) const
{
    const TrafficEntry frame = frameAt(storeRow);
    const quint64 first = firstKept();
    if (frame.transactionId == 0 || frame.sequence < first)
        return -1;
    PairSlot &slot = m_pairs[std::size_t(frame.sequence % quint64(kPairCacheSize))];
    if (slot.key == frame.sequence + 1)
        return slot.paired >= first ? qsizetype(slot.paired - first) : -1;
    // Out: the next frame in of the transaction, unless the request was sent again first (a
    // retry: the answer is the last attempt's). In: the latest frame out of the transaction.
    const bool out = frame.direction == TrafficDirection::Out;
    qint64 found = -1;
    int seen = 0;
    const quint64 from = out ? frame.sequence + 1 : frame.sequence - 1;
    if (out ? from < m_log->appended() : frame.sequence > first) {
        visitFrames(from, out, [&](const TrafficEntry &e) {
            if (++seen > kPairWindow)
                return false;
            if (e.link != frame.link || e.transactionId != frame.transactionId)
                return true;
            if (e.direction == TrafficDirection::Out && out)
                return false;
            if (e.direction == (out ? TrafficDirection::In : TrafficDirection::Out))
                found = qint64(e.sequence);
            return found < 0;
        });
    }
    if (found < 0)
        return -1;
    slot = PairSlot{frame.sequence + 1, quint64(found)};
    return qsizetype(quint64(found) - first);
}

qint64 TrafficModel::latencyNs(qsizetype storeRow) const
{
    const TrafficEntry answer = frameAt(storeRow);
    if (!answered(answer))
        return -1;
    const qsizetype request = pairedRow(storeRow);
    return request < 0 ? -1 : std::max<qint64>(0, answer.tNs - frameAt(request).tNs);
}

FrameKeys TrafficModel::keysAt(qsizetype storeRow) const
{
    const TrafficEntry frame = frameAt(storeRow);
    if (frame.verdict == TrafficVerdict::Garbage) // bytes the framer skipped: no unit, no function
        return {};
    if (frame.direction == TrafficDirection::In && frame.bytes.isEmpty()) {
        const qsizetype request = pairedRow(storeRow);
        return request >= 0 ? m_links.keysOf(frameAt(request)) : FrameKeys{};
    }
    return m_links.keysOf(frame);
}

void TrafficModel::keep(qint64 tNs, TrafficDirection direction, quint16 link, TrafficVerdict verdict,
                        quint64 transactionId, QByteArrayView bytes)
{
    if (!m_hasOrigin) {
        m_originNs = tNs;
        m_hasOrigin = true;
    }
    m_log->append(tNs, direction, link, verdict, transactionId, bytes);
}

void TrafficModel::appended()
{
    enforceLimit();
    publish();
    Q_EMIT countsChanged();
}

void TrafficModel::appendFrames(const QList<TrafficFrame> &frames)
{
    if (frames.isEmpty())
        return;
    for (const TrafficFrame &f : frames)
        keep(f.tNs, f.direction, f.link, f.verdict, f.transactionId, f.bytes);
    appended();
}

void TrafficModel::appendRecordedTransactions(const QList<Transaction> &transactions)
{
    const qint64 offset = wallToMonotonicOffsetNs();
    QList<Transaction> shifted = transactions;
    for (Transaction &t : shifted) {
        for (qint64 *ns : {&t.sentNs, &t.firstByteNs, &t.doneNs}) {
            if (*ns != 0)
                *ns += offset;
        }
    }
    appendTransactions(shifted);
}

void TrafficModel::appendLinkFrames(const QList<TrafficFrame> &frames, const QString &link)
{
    if (frames.isEmpty())
        return;
    const quint16 id = m_links.idOf(link);
    for (const TrafficFrame &f : frames)
        keep(f.tNs, f.direction, id, f.verdict, f.transactionId, f.bytes);
    appended();
}

void TrafficModel::appendNamedFrames(const QList<TrafficFrame> &frames, const QStringList &links)
{
    if (frames.isEmpty())
        return;
    std::vector<quint16> ids;
    ids.reserve(std::size_t(links.size()));
    for (const QString &name : links)
        ids.push_back(m_links.idOf(name));
    for (const TrafficFrame &f : frames) {
        const quint16 id = f.link < ids.size() ? ids[f.link] : m_links.idOf(QString());
        keep(f.tNs, f.direction, id, f.verdict, f.transactionId, f.bytes);
    }
    appended();
}

// A transaction becomes the frames its engine's traffic log holds: the request out (when its last
// byte was written) and the answer in (when its first byte came), or an empty frame in carrying
// the verdict when nothing came (timeout, link error, broadcast). A late answer's request is
// already listed, under its timeout.
void TrafficModel::appendTransactions(const QList<Transaction> &transactions)
{
    if (transactions.isEmpty())
        return;
    if (!m_hasCurrentLink)
        setCurrentLink(QString());
    for (const Transaction &t : transactions) {
        // A request never written (the link would not open) has no send time: it is listed when it failed.
        const qint64 outNs = t.sentNs != 0 ? t.sentNs : t.doneNs;
        if (t.status != TransactionStatus::Late)
            keep(outNs, TrafficDirection::Out, m_currentLink, TrafficVerdict::Sent, t.id, t.request);
        const TrafficVerdict verdict = trafficVerdict(t.status);
        if (!t.response.isEmpty())
            keep(t.firstByteNs > 0 ? t.firstByteNs : t.doneNs, TrafficDirection::In, m_currentLink, verdict, t.id,
                 t.response);
        else
            keep(t.doneNs > 0 ? t.doneNs : outNs, TrafficDirection::In, m_currentLink, verdict, t.id, {});
    }
    appended();
}

void TrafficModel::publish()
{
    if (m_paused || m_publishedEnd == m_log->appended())
        return;
    const quint64 first = firstKept();
    const quint64 from = m_publishedEnd;
    const quint64 to = m_log->appended();
    if (!m_filtered) {
        beginInsertRows({}, int(from - first), int(to - first - 1));
        m_publishedEnd = to;
        endInsertRows();
        return;
    }
    std::vector<quint32> accepted;
    visitFrames(from, true, [&](const TrafficEntry &e) {
        if (m_filter.accepts(e, keysAt(qsizetype(e.sequence - first))))
            accepted.push_back(quint32(e.sequence - first));
        return true;
    });
    m_publishedEnd = to;
    if (accepted.empty())
        return;
    const int firstRow = int(m_shown.size());
    beginInsertRows({}, firstRow, firstRow + int(accepted.size()) - 1);
    m_shown.insert(m_shown.end(), accepted.begin(), accepted.end());
    endInsertRows();
}

// Rows leave memory a tenth of a limit at a time, so the cost of moving the rest is paid rarely.
void TrafficModel::enforceLimit()
{
    const auto size = qsizetype(m_log->size());
    qsizetype drop = 0;
    if (size > m_rowLimit)
        drop = size - m_rowLimit + m_rowLimit / 10;
    if (m_log->retainedBytes() > m_byteLimit) {
        const quint64 target = m_byteLimit - m_byteLimit / 10;
        quint64 bytes = m_log->retainedBytes();
        qsizetype count = 0;
        m_log->visit(m_log->firstSequence(), true, [&](const TrafficEntry &e) {
            bytes -= 24 + quint64(e.bytes.size());
            ++count;
            return bytes > target;
        });
        drop = std::max(drop, count);
    }
    if (drop <= 0)
        return;
    if (!archiveOldest(quint64(drop)))
        dropOldest(quint64(drop));
}

bool TrafficModel::archiveOldest(quint64 count)
{
    if (m_archiveFolder.isEmpty() || !m_archiveProblem.isEmpty())
        return false;
    if (!m_archive) {
        // The archive holds the list from its first frame on, or nothing.
        if (m_log->firstSequence() != 0)
            return false;
        auto archive = std::make_unique<TrafficArchive>();
        if (!archive->open(m_archiveFolder, &m_archiveProblem)) {
            if (m_archiveProblem.isEmpty())
                m_archiveProblem = archive->error();
            return false;
        }
        m_archive = std::move(archive);
    }
    bool ok = true;
    quint64 moved = 0;
    m_log->visit(m_log->firstSequence(), true, [&](const TrafficEntry &e) {
        ok = m_archive->append(e);
        return ok && ++moved < count;
    });
    if (ok) {
        m_log->dropOldest(count);
        return true;
    }
    // The disk refused: the list goes on without the archive, from what memory holds.
    m_archiveProblem = m_archive->error().isEmpty() ? QStringLiteral("the traffic list's archive could not be written")
                                                    : m_archive->error();
    dropOldest(archivedCount());
    return false;
}

void TrafficModel::dropOldest(quint64 count)
{
    const quint64 first = firstKept();
    const qsizetype published = qsizetype(m_publishedEnd - first);
    const qsizetype publishedDropped = std::min(qsizetype(count), published);
    const int shownDropped = m_filtered
        ? int(std::lower_bound(m_shown.begin(), m_shown.end(), quint32(publishedDropped)) - m_shown.begin())
        : int(publishedDropped);
    if (shownDropped > 0)
        beginRemoveRows({}, 0, shownDropped - 1);
    // The archive goes whole (it holds the oldest frames, and only from the first on).
    const quint64 archived = archivedCount();
    if (m_archive && count >= archived)
        m_archive.reset();
    m_log->dropOldest(count - std::min(count, archived));
    if (m_publishedEnd < firstKept())
        m_publishedEnd = firstKept();
    if (m_filtered) {
        m_shown.erase(m_shown.begin(), m_shown.begin() + shownDropped);
        const quint64 shift = firstKept() - first;
        for (quint32 &row : m_shown)
            row -= quint32(shift);
    }
    if (shownDropped > 0)
        endRemoveRows();
}

void TrafficModel::clear()
{
    beginResetModel();
    m_log = std::make_unique<TrafficLog>(unbounded());
    m_archive.reset();
    m_archiveProblem.clear();
    std::fill(m_pairs.begin(), m_pairs.end(), PairSlot{});
    std::vector<quint32>().swap(m_shown);
    m_publishedEnd = 0;
    m_hasOrigin = false;
    endResetModel();
    Q_EMIT countsChanged();
}

FrameExchange TrafficModel::exchangeAt(int row) const
{
    FrameExchange e;
    const qsizetype s = storeRow(row);
    if (s < 0)
        return e;
    const TrafficEntry frame = frameAt(s);
    const qsizetype paired = pairedRow(s);
    e.selected = frame.direction;
    e.framing = m_links.framing(frame.link);
    e.link = m_links.name(frame.link);
    e.transactionId = frame.transactionId;
    e.latencyNs = frame.direction == TrafficDirection::In ? latencyNs(s) : paired >= 0 ? latencyNs(paired) : -1;
    if (frame.direction == TrafficDirection::Out) {
        e.request = frame.bytes.toByteArray();
        if (paired >= 0) {
            const TrafficEntry answer = frameAt(paired);
            e.response = answer.bytes.toByteArray();
            e.verdict = answer.verdict;
        } else {
            e.verdict = frame.verdict;
        }
    } else {
        e.response = frame.bytes.toByteArray();
        e.verdict = frame.verdict;
        if (paired >= 0)
            e.request = frameAt(paired).bytes.toByteArray();
    }
    return e;
}

int TrafficModel::findNext(const QString &query, int fromRow, bool forward) const
{
    const int n = rowCount();
    if (n == 0)
        return -1;
    const TrafficSearch search(query, m_links);
    if (search.isEmpty())
        return -1;
    int row = fromRow < 0 ? (forward ? n - 1 : 0) : fromRow;
    for (int k = 0; k < n; ++k) {
        row = forward ? (row + 1) % n : (row - 1 + n) % n;
        const qsizetype s = storeRow(row);
        if (search.matches(frameAt(s), keysAt(s)))
            return row;
    }
    return -1;
}

std::size_t TrafficModel::memoryBytes() const
{
    return m_log->memoryBytes() + (m_archive ? m_archive->memoryBytes() : 0) + m_links.memoryBytes() + m_shown.capacity() * sizeof(quint32)
        + m_pairs.capacity() * sizeof(PairSlot);
}

int TrafficModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid())
        return 0;
    return m_filtered ? int(m_shown.size()) : int(m_publishedEnd - firstKept());
}

int TrafficModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

} // namespace mbscope
