#include "simtrafficmodel.h"

#include "common/severitystyle.h"

#include "common/coretext.h"

#include "protocol/adubuilder.h"
#include "protocol/functioncode.h"

#include <QtGui/QBrush>
#include <QtGui/QColor>

#include <algorithm>

namespace mbscope {

namespace {

QString hexOf(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

QString hexByte(int value)
{
    return QString::number(value, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

} // namespace

SimTrafficModel::SimTrafficModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void SimTrafficModel::appendRecords(const QList<SimTrafficRecord> &records, int lost)
{
    m_dropped += quint64(qMax(0, lost));
    if (records.isEmpty())
        return;
    if (m_originNs < 0)
        m_originNs = records.first().entry.tNs;
    // Only the newest rowLimit records can stay: older ones of a large batch never become rows.
    const qsizetype skip = std::max<qsizetype>(0, records.size() - m_rowLimit);
    m_dropped += quint64(skip);
    const qsizetype incoming = records.size() - skip;
    trimTo(int(m_rowLimit - incoming));
    const int first = int(m_rows.size());
    beginInsertRows({}, first, first + int(incoming) - 1);
    m_rows.append(records.mid(skip));
    endInsertRows();
}

void SimTrafficModel::trimTo(int rows)
{
    rows = std::max(0, rows);
    if (m_rows.size() <= rows)
        return;
    const int excess = int(m_rows.size()) - rows;
    beginRemoveRows({}, 0, excess - 1);
    m_rows.remove(0, excess);
    endRemoveRows();
    m_dropped += quint64(excess);
}

void SimTrafficModel::clear()
{
    beginResetModel();
    m_rows.clear();
    m_dropped = 0;
    m_originNs = -1;
    endResetModel();
}

void SimTrafficModel::setRowLimit(int rows)
{
    m_rowLimit = std::max(1, rows);
    trimTo(m_rowLimit);
}

int SimTrafficModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int SimTrafficModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

int SimTrafficModel::exceptionCodeOf(const SimTrafficRecord &record)
{
    const QByteArray answer = record.sentBytes();
    if (answer.isEmpty())
        return 0;
    const AduParts parts = AduBuilder::parse(answer, record.framing);
    if (parts.pdu.size() >= 2 && (quint8(parts.pdu.at(0)) & 0x80) != 0)
        return quint8(parts.pdu.at(1));
    return 0;
}

QString SimTrafficModel::functionText(const SimTrafficRecord &record) const
{
    if (record.entry.request.isEmpty())
        return {};
    const AduParts parts = AduBuilder::parse(record.entry.request, record.framing);
    if (parts.pdu.isEmpty())
        return {};
    const quint8 code = quint8(parts.pdu.at(0));
    return tr("%1 %2").arg(hexByte(code), fieldText(functionName(code)));
}

QString SimTrafficModel::outcomeText(const SimTrafficRecord &record) const
{
    using V = SimLogEntry::Verdict;
    const SimLogEntry &entry = record.entry;
    const QString faults = entry.faults.join(QStringLiteral(", "));
    if (record.isDropped())
        return tr("no answer: dropped by fault rule %1").arg(faults);
    QString text;
    const int exception = exceptionCodeOf(record);
    if (exception != 0)
        text = tr("exception %1 (%2)").arg(hexByte(exception), QLatin1String(exceptionName(quint8(exception))));
    else {
        switch (entry.verdict) {
        case V::Answered:
        case V::Exception: text = tr("answered"); break;
        case V::NoAnswer: text = tr("no answer: %1").arg(entry.reason); break;
        case V::UnknownUnit: text = tr("unknown unit: %1").arg(entry.reason); break;
        case V::ChecksumError: text = tr("checksum error: %1").arg(entry.reason); break;
        case V::Malformed: text = tr("malformed: %1").arg(entry.reason); break;
        case V::Garbage: text = tr("garbage: %1").arg(entry.reason); break;
        case V::ConnectionOpened: text = tr("connection opened"); break;
        case V::ConnectionRefused: text = tr("connection refused: %1").arg(entry.reason); break;
        case V::ConnectionClosed: text = tr("connection closed: %1").arg(entry.reason); break;
        }
    }
    if (!faults.isEmpty())
        text = tr("%1, changed by fault rule %2").arg(text, faults);
    if (record.plan && record.plan->closeAfter)
        text = tr("%1, then the connection closed").arg(text);
    return text;
}

QVariant SimTrafficModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const SimTrafficRecord &record = m_rows[index.row()];
    const SimLogEntry &entry = record.entry;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case TimeColumn: return QString::number(double(entry.tNs - m_originNs) / 1e9, 'f', 3);
        case EndpointColumn: return entry.endpoint;
        case PeerColumn: return entry.peer;
        case UnitColumn: return entry.unitId >= 0 ? QVariant(entry.unitId) : QVariant();
        case FunctionColumn: return functionText(record);
        case OutcomeColumn: return outcomeText(record);
        case RequestColumn: return hexOf(entry.request);
        case SentColumn: return hexOf(record.sentBytes());
        default: return {};
        }
    case Qt::ToolTipRole:
        if (index.column() == OutcomeColumn || index.column() == SentColumn) {
            if (const qint64 delay = record.delayNs(); delay > 0)
                return tr("%1; sent %2 ms after the request").arg(outcomeText(record)).arg(double(delay) / 1e6, 0, 'f', 1);
            return outcomeText(record);
        }
        return {};
    case Qt::BackgroundRole:
        if (record.isFaulted())
            return QBrush(SeverityStyle::backgroundColor(Severity::Error));
        if (exceptionCodeOf(record) != 0)
            return QBrush(SeverityStyle::backgroundColor(Severity::Warning));
        return {};
    case FaultedRole: return record.isFaulted();
    case ExceptionCodeRole: return exceptionCodeOf(record);
    default: return {};
    }
}

QVariant SimTrafficModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case TimeColumn: return tr("Time (s)");
    case EndpointColumn: return tr("Endpoint");
    case PeerColumn: return tr("Peer");
    case UnitColumn: return tr("Unit");
    case FunctionColumn: return tr("Function");
    case OutcomeColumn: return tr("Outcome");
    case RequestColumn: return tr("Request");
    case SentColumn: return tr("Sent");
    default: return {};
    }
}

} // namespace mbscope
