// TrafficModel's cells: the text, colours and tooltips of a row, made only when a view asks.
#include "trafficmodel.h"

#include "common/coretext.h"
#include "common/exchangeformat.h"
#include "common/severitystyle.h"
#include "common/trafficstyle.h"

#include "protocol/functioncode.h"
#include "protocol/hexformat.h"
#include "protocol/hextext.h"

namespace mbscope {

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
