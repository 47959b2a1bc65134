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
    const quint64 first = m_log->firstSequence();
    m_log->visit(first, true, [&](const TrafficEntry &e) {
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
    const qsizetype published = qsizetype(m_publishedEnd - m_log->firstSequence());
    if (storeRow < 0 || storeRow >= published)
        return -1;
    if (!m_filtered)
        return int(storeRow);
    const auto it = std::lower_bound(m_shown.begin(), m_shown.end(), quint32(storeRow));
    return it != m_shown.end() && *it == quint32(storeRow) ? int(it - m_shown.begin()) : -1;
}

TrafficEntry TrafficModel::frameAt(qsizetype storeRow) const
{
    return m_log->at(sequenceOf(storeRow));
}

qsizetype TrafficModel::pairedRow(qsizetype storeRow) const
{
    const TrafficEntry frame = frameAt(storeRow);
    if (frame.transactionId == 0 || frame.sequence < m_log->firstSequence())
        return -1;
    const quint64 first = m_log->firstSequence();
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
        m_log->visit(from, out, [&](const TrafficEntry &e) {
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
    const quint64 first = m_log->firstSequence();
    const quint64 from = m_publishedEnd;
    const quint64 to = m_log->appended();
    if (!m_filtered) {
        beginInsertRows({}, int(from - first), int(to - first - 1));
        m_publishedEnd = to;
        endInsertRows();
        return;
    }
    std::vector<quint32> accepted;
    m_log->visit(from, true, [&](const TrafficEntry &e) {
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

// Rows are dropped a tenth of a limit at a time, so the cost of moving the rest is paid rarely.
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
    const qsizetype published = qsizetype(m_publishedEnd - m_log->firstSequence());
    const qsizetype publishedDropped = std::min(drop, published);
    const int shownDropped = m_filtered
        ? int(std::lower_bound(m_shown.begin(), m_shown.end(), quint32(publishedDropped)) - m_shown.begin())
        : int(publishedDropped);
    if (shownDropped > 0)
        beginRemoveRows({}, 0, shownDropped - 1);
    m_log->dropOldest(quint64(drop));
    if (m_publishedEnd < m_log->firstSequence())
        m_publishedEnd = m_log->firstSequence();
    if (m_filtered) {
        m_shown.erase(m_shown.begin(), m_shown.begin() + shownDropped);
        for (quint32 &row : m_shown)
            row -= quint32(drop);
    }
    if (shownDropped > 0)
        endRemoveRows();
}

void TrafficModel::clear()
{
    beginResetModel();
    m_log = std::make_unique<TrafficLog>(unbounded());
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
    return m_log->memoryBytes() + m_links.memoryBytes() + m_shown.capacity() * sizeof(quint32)
        + m_pairs.capacity() * sizeof(PairSlot);
}

int TrafficModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid())
        return 0;
    return m_filtered ? int(m_shown.size()) : int(m_publishedEnd - m_log->firstSequence());
}

int TrafficModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TrafficModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || section < 0 || section >= ColumnCount)
        return {};
    if (role == Qt::DisplayRole) {
        switch (Column(section)) {
        case NumberColumn: return tr("No.");
        case TimeColumn: return tr("Time (s)");
        case DirectionColumn: return tr("Dir");
        case LinkColumn: return tr("Link");
        case UnitColumn: return tr("Unit");
        case FunctionColumn: return tr("Function");
        case LengthColumn: return tr("Length");
        case LatencyColumn: return tr("Latency");
        case VerdictColumn: return tr("Verdict");
        case BytesColumn: return tr("Bytes");
        case ColumnCount: break;
        }
    } else if (role == Qt::ToolTipRole) {
        switch (Column(section)) {
        case TimeColumn: return tr("Seconds since the first frame listed (monotonic clock)");
        case LatencyColumn: return tr("From the request's write to the first byte of its answer, as the recording keeps them; the Analysis dock measures from the request's last byte to the answer's last byte");
        case VerdictColumn: return tr("What became of the frame: a request is 'sent', its answer carries the verdict");
        default: break;
        }
    }
    return {};
}

QVariant TrafficModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const qsizetype s = storeRow(index.row());
    const int column = index.column();
    const TrafficEntry r = frameAt(s);
    switch (role) {
    case Qt::DisplayRole:
        return displayText(s, column);
    case Qt::ForegroundRole:
        return foreground(s, column);
    case Qt::BackgroundRole:
        return background(s);
    case Qt::ToolTipRole:
        return toolTip(s, column);
    case Qt::FontRole:
        return column == BytesColumn ? QVariant(m_monoFont) : QVariant();
    case Qt::TextAlignmentRole:
        switch (column) {
        case NumberColumn:
        case TimeColumn:
        case UnitColumn:
        case LengthColumn:
        case LatencyColumn:
            return QVariant(Qt::AlignRight | Qt::AlignVCenter);
        default:
            return QVariant(Qt::AlignLeft | Qt::AlignVCenter);
        }
    case DirectionRole:
        return int(r.direction);
    case VerdictRole:
        return int(r.verdict);
    case TransactionIdRole:
        return qulonglong(r.transactionId);
    case LatencyNsRole:
        return qlonglong(latencyNs(s));
    case TimeNsRole:
        return qlonglong(r.tNs);
    case StoreRowRole:
        return qlonglong(s);
    case BytesRole:
        return r.bytes.toByteArray();
    default:
        return {};
    }
}

QVariant TrafficModel::displayText(qsizetype s, int column) const
{
    const TrafficEntry r = frameAt(s);
    switch (Column(column)) {
    case NumberColumn:
        return QString::number(r.sequence + 1);
    case TimeColumn:
        return QString::number(double(r.tNs - m_originNs) / 1e9, 'f', 6);
    case DirectionColumn:
        return TrafficStyle::directionText(r.direction);
    case LinkColumn: {
        const QString name = m_links.name(r.link);
        return name.isEmpty() ? tr("link %1").arg(r.link) : name;
    }
    case UnitColumn: {
        const FrameKeys keys = keysAt(s);
        return keys.valid ? QVariant(QString::number(keys.unit)) : QVariant();
    }
    case FunctionColumn: {
        const FrameKeys keys = keysAt(s);
        if (!keys.valid)
            return {};
        const quint8 function = keys.functionCode;
        // An exception response is its request's code with the high bit set (V1.1b3, 7).
        if (function & 0x80)
            return tr("%1 Exception to %2").arg(hexByte(function), fieldText(functionName(function & 0x7F)));
        return hexByte(function) + QLatin1Char(' ') + fieldText(functionName(function));
    }
    case LengthColumn:
        return QString::number(r.bytes.size());
    case LatencyColumn:
        return ExchangeFormat::latencyText(latencyNs(s));
    case VerdictColumn:
        return TrafficStyle::verdictText(r.verdict);
    case BytesColumn: {
        const QByteArrayView bytes = r.bytes;
        if (bytes.size() <= kBytesShown)
            return HexText::format(bytes);
        return HexText::format(bytes.first(kBytesShown)) + QStringLiteral(" \u2026");
    }
    case ColumnCount:
        break;
    }
    return {};
}

QVariant TrafficModel::foreground(qsizetype s, int column) const
{
    const TrafficEntry r = frameAt(s);
    if (column == DirectionColumn)
        return TrafficStyle::directionColor(r.direction);
    if (column == VerdictColumn) {
        const Severity severity = TrafficStyle::severity(r.verdict);
        if (severity != Severity::Ok)
            return SeverityStyle::textColor(severity);
    }
    return {};
}

// Rows whose verdict is an error are tinted whole, as a packet list colours bad packets, so they
// stand out while scrolling; warnings colour only their verdict.
QVariant TrafficModel::background(qsizetype s) const
{
    const Severity severity = TrafficStyle::severity(frameAt(s).verdict);
    return severity == Severity::Error ? QVariant(SeverityStyle::backgroundColor(severity)) : QVariant();
}

QString TrafficModel::toolTip(qsizetype s, int column) const
{
    const TrafficEntry r = frameAt(s);
    switch (column) {
    case BytesColumn: {
        const QByteArrayView bytes = r.bytes;
        HexText::FormatOptions options;
        options.bytesPerLine = 16;
        return bytes.isEmpty() ? tr("No bytes") : HexText::format(bytes, options);
    }
    case LatencyColumn:
    case VerdictColumn: {
        const qsizetype paired = pairedRow(s);
        if (paired < 0)
            return r.direction == TrafficDirection::In && r.transactionId == 0 ? tr("Not an answer to any request sent")
                                                                               : QString();
        return r.direction == TrafficDirection::In ? tr("Answers frame %1").arg(sequenceOf(paired) + 1)
                                                   : tr("Answered in frame %1").arg(sequenceOf(paired) + 1);
    }
    default:
        return {};
    }
}

} // namespace mbscope
