#include "trafficmodel.h"

#include "common/coretext.h"

#include "common/exchangeformat.h"
#include "common/severitystyle.h"
#include "trafficsearch.h"
#include "common/trafficstyle.h"

#include "protocol/functioncode.h"
#include "protocol/hexformat.h"
#include "protocol/hextext.h"

#include <QtGui/QFontDatabase>

#include <algorithm>

namespace mbscope {

TrafficModel::TrafficModel(QObject *parent)
    : QAbstractTableModel(parent)
    , m_monoFont(QFontDatabase::systemFont(QFontDatabase::FixedFont))
{
}

void TrafficModel::setLinkName(quint16 link, const QString &url)
{
    m_store.setLinkName(link, url);
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, LinkColumn), index(rowCount() - 1, LinkColumn));
}

void TrafficModel::setCurrentLink(const QString &url)
{
    m_currentLink = m_store.linkId(url);
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
    for (qsizetype i = 0; i < m_published; ++i) {
        if (m_filter.accepts(m_store.row(i)))
            m_shown.push_back(quint32(i));
    }
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

qsizetype TrafficModel::storeRow(int row) const
{
    if (row < 0 || row >= rowCount())
        return -1;
    return m_filtered ? qsizetype(m_shown[size_t(row)]) : row;
}

int TrafficModel::rowOfStoreRow(qsizetype storeRow) const
{
    if (storeRow < 0 || storeRow >= m_published)
        return -1;
    if (!m_filtered)
        return int(storeRow);
    const auto it = std::lower_bound(m_shown.begin(), m_shown.end(), quint32(storeRow));
    return it != m_shown.end() && *it == quint32(storeRow) ? int(it - m_shown.begin()) : -1;
}

void TrafficModel::appendFrames(const QList<TrafficFrame> &frames)
{
    if (frames.isEmpty())
        return;
    if (!m_hasOrigin) {
        m_originNs = frames.first().tNs;
        m_hasOrigin = true;
    }
    for (const TrafficFrame &f : frames)
        m_store.append(f.tNs, f.direction, f.link, f.verdict, f.transactionId, f.bytes);
    enforceLimit();
    publish();
    Q_EMIT countsChanged();
}

void TrafficModel::appendLinkFrames(const QList<TrafficFrame> &frames, const QString &link)
{
    if (frames.isEmpty())
        return;
    const quint16 id = m_store.linkId(link);
    QList<TrafficFrame> named = frames;
    for (TrafficFrame &frame : named)
        frame.link = id;
    appendFrames(named);
}

// A transaction becomes the two frames the traffic log would hold: the request out and the answer
// in, or an empty frame in carrying the verdict when nothing came (timeout, link error, broadcast),
// as the engine logs them. A late answer's request is already listed, under its timeout.
void TrafficModel::appendTransactions(const QList<Transaction> &transactions)
{
    if (transactions.isEmpty())
        return;
    if (!m_hasCurrentLink)
        setCurrentLink(QString());
    if (!m_hasOrigin) {
        m_originNs = transactions.first().sentNs != 0 ? transactions.first().sentNs : transactions.first().doneNs;
        m_hasOrigin = true;
    }
    for (const Transaction &t : transactions) {
        // A request never written (the link would not open) has no send time: it is listed when it failed.
        const qint64 outNs = t.sentNs != 0 ? t.sentNs : t.doneNs;
        if (t.status != TransactionStatus::Late)
            m_store.append(outNs, TrafficDirection::Out, m_currentLink, TrafficVerdict::Sent, t.id, t.request);
        const TrafficVerdict verdict = trafficVerdict(t.status);
        if (!t.response.isEmpty())
            m_store.append(t.firstByteNs > 0 ? t.firstByteNs : t.doneNs, TrafficDirection::In, m_currentLink, verdict,
                           t.id, t.response, t.latencyNs());
        else
            m_store.append(t.doneNs > 0 ? t.doneNs : outNs, TrafficDirection::In, m_currentLink, verdict, t.id, {});
    }
    enforceLimit();
    publish();
    Q_EMIT countsChanged();
}

void TrafficModel::publish()
{
    if (m_paused || m_published == m_store.size())
        return;
    const qsizetype from = m_published;
    const qsizetype to = m_store.size();
    if (!m_filtered) {
        beginInsertRows({}, int(from), int(to - 1));
        m_published = to;
        endInsertRows();
        return;
    }
    std::vector<quint32> accepted;
    for (qsizetype i = from; i < to; ++i) {
        if (m_filter.accepts(m_store.row(i)))
            accepted.push_back(quint32(i));
    }
    m_published = to;
    if (accepted.empty())
        return;
    const int first = int(m_shown.size());
    beginInsertRows({}, first, first + int(accepted.size()) - 1);
    m_shown.insert(m_shown.end(), accepted.begin(), accepted.end());
    endInsertRows();
}

// Rows are dropped a tenth of the limit at a time, so the cost of moving the rest is paid rarely.
void TrafficModel::enforceLimit()
{
    if (m_store.size() <= m_rowLimit)
        return;
    const qsizetype drop = m_store.size() - m_rowLimit + m_rowLimit / 10;
    const qsizetype publishedDropped = std::min(drop, m_published);
    const int shownDropped = m_filtered
        ? int(std::lower_bound(m_shown.begin(), m_shown.end(), quint32(publishedDropped)) - m_shown.begin())
        : int(publishedDropped);
    if (shownDropped > 0)
        beginRemoveRows({}, 0, shownDropped - 1);
    m_store.removeFront(drop);
    m_published -= publishedDropped;
    m_dropped += quint64(drop);
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
    m_store.clear();
    std::vector<quint32>().swap(m_shown);
    m_published = 0;
    m_dropped = 0;
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
    const TrafficStore::Row &r = m_store.row(s);
    const qsizetype paired = m_store.pairedRow(s);
    e.selected = r.direction;
    e.framing = m_store.linkFraming(r.link);
    e.link = m_store.linkName(r.link);
    e.transactionId = r.transactionId;
    if (r.direction == TrafficDirection::Out) {
        e.request = m_store.bytes(s).toByteArray();
        if (paired >= 0) {
            e.response = m_store.bytes(paired).toByteArray();
            e.verdict = m_store.row(paired).verdict;
            e.latencyNs = m_store.latencyNs(paired);
        } else {
            e.verdict = r.verdict;
        }
    } else {
        e.response = m_store.bytes(s).toByteArray();
        e.verdict = r.verdict;
        e.latencyNs = m_store.latencyNs(s);
        if (paired >= 0)
            e.request = m_store.bytes(paired).toByteArray();
    }
    return e;
}

int TrafficModel::findNext(const QString &query, int fromRow, bool forward) const
{
    const int n = rowCount();
    if (n == 0)
        return -1;
    const TrafficSearch search(query, m_store);
    if (search.isEmpty())
        return -1;
    int row = fromRow < 0 ? (forward ? n - 1 : 0) : fromRow;
    for (int k = 0; k < n; ++k) {
        row = forward ? (row + 1) % n : (row - 1 + n) % n;
        if (search.matches(storeRow(row)))
            return row;
    }
    return -1;
}

std::size_t TrafficModel::memoryBytes() const
{
    return m_store.memoryBytes() + m_shown.capacity() * sizeof(quint32);
}

int TrafficModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid())
        return 0;
    return m_filtered ? int(m_shown.size()) : int(m_published);
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
        case LatencyColumn: return tr("From the request written to its answer");
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
    const TrafficStore::Row &r = m_store.row(s);
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
        return qlonglong(m_store.latencyNs(s));
    case TimeNsRole:
        return qlonglong(r.tNs);
    case StoreRowRole:
        return qlonglong(s);
    case BytesRole:
        return m_store.bytes(s).toByteArray();
    default:
        return {};
    }
}

QVariant TrafficModel::displayText(qsizetype s, int column) const
{
    const TrafficStore::Row &r = m_store.row(s);
    switch (Column(column)) {
    case NumberColumn:
        return QString::number(m_dropped + quint64(s) + 1);
    case TimeColumn:
        return QString::number(double(r.tNs - m_originNs) / 1e9, 'f', 6);
    case DirectionColumn:
        return TrafficStyle::directionText(r.direction);
    case LinkColumn: {
        const QString name = m_store.linkName(r.link);
        return name.isEmpty() ? tr("link %1").arg(r.link) : name;
    }
    case UnitColumn:
        return r.hasUnit() ? QVariant(QString::number(r.unit)) : QVariant();
    case FunctionColumn: {
        if (!r.hasFunction())
            return {};
        // An exception response is its request's code with the high bit set (V1.1b3, 7).
        if (r.function & 0x80)
            return tr("%1 Exception to %2").arg(hexByte(r.function), fieldText(functionName(r.function & 0x7F)));
        return hexByte(r.function) + QLatin1Char(' ') + fieldText(functionName(r.function));
    }
    case LengthColumn:
        return QString::number(r.length);
    case LatencyColumn:
        return ExchangeFormat::latencyText(m_store.latencyNs(s));
    case VerdictColumn:
        return TrafficStyle::verdictText(r.verdict);
    case BytesColumn: {
        const QByteArrayView bytes = m_store.bytes(s);
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
    const TrafficStore::Row &r = m_store.row(s);
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
    const Severity severity = TrafficStyle::severity(m_store.row(s).verdict);
    return severity == Severity::Error ? QVariant(SeverityStyle::backgroundColor(severity)) : QVariant();
}

QString TrafficModel::toolTip(qsizetype s, int column) const
{
    const TrafficStore::Row &r = m_store.row(s);
    switch (column) {
    case BytesColumn: {
        const QByteArrayView bytes = m_store.bytes(s);
        HexText::FormatOptions options;
        options.bytesPerLine = 16;
        return bytes.isEmpty() ? tr("No bytes") : HexText::format(bytes, options);
    }
    case LatencyColumn:
    case VerdictColumn: {
        const qsizetype paired = m_store.pairedRow(s);
        if (paired < 0)
            return r.direction == TrafficDirection::In && r.transactionId == 0 ? tr("Not an answer to any request sent")
                                                                               : QString();
        return r.direction == TrafficDirection::In ? tr("Answers frame %1").arg(m_dropped + quint64(paired) + 1)
                                                   : tr("Answered in frame %1").arg(m_dropped + quint64(paired) + 1);
    }
    default:
        return {};
    }
}

} // namespace mbscope
