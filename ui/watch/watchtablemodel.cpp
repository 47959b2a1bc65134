#include "watchtablemodel.h"

#include "rulepalette.h"

#include "protocol/modiconreference.h"
#include "watch/watchblock.h"
#include "watch/watchdecoder.h"

#include <QtCore/QDateTime>

namespace mbscope {

WatchTableModel::WatchTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void WatchTableModel::setDefinition(const WatchDefinition &watch)
{
    beginResetModel();
    m_watch = watch;
    m_rows.clear();
    m_lastSampleMs = 0;
    // The layout the decoder gives a full answer: every value's row, before the first poll.
    const bool bits = WatchBlock::isBitFunction(watch.function);
    const int count = watch.quantity * WatchBlock::wordsPerAddress(watch);
    const QList<WatchPointValue> layout = WatchDecoder::decode(watch, bits ? QList<quint16>() : QList<quint16>(count, 0),
                                                               bits ? QList<bool>(count, false) : QList<bool>());
    m_rows.reserve(layout.size());
    for (const WatchPointValue &value : layout) {
        Row row;
        row.value = value;
        m_rows.append(row);
    }
    endResetModel();
}

void WatchTableModel::applySample(const WatchSample &sample)
{
    m_lastSampleMs = sample.timeMs;
    if (!sample.isOk())
        return;
    const QList<WatchPointValue> &values = sample.values;
    if (values.size() != m_rows.size()) {
        // A FIFO answers with as many values as it holds: the rows follow it.
        beginResetModel();
        QList<Row> rows;
        rows.reserve(values.size());
        for (const WatchPointValue &value : values) {
            Row row;
            const int old = rowOf(QString::number(value.address));
            if (old >= 0)
                row = m_rows.at(old);
            row.changedMs = (old < 0 || row.value.text != value.text) ? sample.timeMs : row.changedMs;
            row.value = value;
            row.known = true;
            rows.append(row);
        }
        m_rows = rows;
        endResetModel();
        return;
    }
    int first = -1;
    int last = -1;
    for (int i = 0; i < values.size(); ++i) {
        Row &row = m_rows[i];
        if (row.known && row.value.text == values.at(i).text && row.value.raw == values.at(i).raw)
            continue;
        row.value = values.at(i);
        row.known = true;
        row.changedMs = sample.timeMs;
        if (first < 0)
            first = i;
        last = i;
    }
    if (first >= 0)
        Q_EMIT dataChanged(index(first, ValueColumn), index(last, ChangedColumn), {Qt::DisplayRole, Qt::ToolTipRole});
}

void WatchTableModel::applyRule(const WatchRuleEvent &event)
{
    const int r = rowOf(event.point);
    if (r < 0)
        return;
    Row &row = m_rows[r];
    for (qsizetype i = row.rules.size() - 1; i >= 0; --i) {
        if (row.rules.at(i).rule == event.rule)
            row.rules.removeAt(i);
    }
    if (event.fired)
        row.rules.append(ActiveRule{event.rule, event.severity, event.colour, event.message});
    Q_EMIT dataChanged(index(r, 0), index(r, ColumnCount - 1));
}

int WatchTableModel::activeRules() const
{
    int count = 0;
    for (const Row &row : m_rows)
        count += int(row.rules.size());
    return count;
}

const WatchTableModel::ActiveRule *WatchTableModel::strongestRule(const Row &row) const
{
    const ActiveRule *strongest = nullptr;
    for (const ActiveRule &rule : row.rules) {
        if (!strongest || rule.severity >= strongest->severity)
            strongest = &rule;
    }
    return strongest;
}

int WatchTableModel::rowOf(const QString &point) const
{
    bool isNumber = false;
    const uint address = point.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? point.mid(2).toUInt(&isNumber, 16)
                                                                                     : point.toUInt(&isNumber, 10);
    for (int i = 0; i < m_rows.size(); ++i) {
        const WatchPointValue &value = m_rows.at(i).value;
        if (!value.name.isEmpty() && value.name == point)
            return i;
        if (isNumber && value.address == address)
            return i;
    }
    return -1;
}

QString WatchTableModel::referenceText(quint16 address) const
{
    ModbusTable table = ModbusTable::HoldingRegisters;
    switch (m_watch.function) {
    case 1: table = ModbusTable::Coils; break;
    case 2: table = ModbusTable::DiscreteInputs; break;
    case 4: table = ModbusTable::InputRegisters; break;
    case 3: break;
    default: return {}; // a FIFO's values have no reference of their own
    }
    const ModiconReference reference(table, address);
    return reference.hasFiveDigitForm() ? reference.fiveDigit() : reference.sixDigit();
}

int WatchTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int WatchTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant WatchTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row &row = m_rows.at(index.row());
    const WatchPointValue &value = row.value;
    const int column = index.column();
    if (role == Qt::DisplayRole) {
        switch (column) {
        case AddressColumn:
            // Upper-case hex, as everywhere else in the window (the register table, the dissector).
            return QStringLiteral("%1 (0x%2)").arg(value.address).arg(QString::number(value.address, 16).rightJustified(4, QLatin1Char('0')).toUpper());
        case ReferenceColumn: return referenceText(value.address);
        case NameColumn: return value.name;
        case ValueColumn: return row.known ? value.text : QStringLiteral("\u2014");
        case UnitColumn: return value.unit;
        case RuleColumn:
            if (const ActiveRule *rule = strongestRule(row))
                return QStringLiteral("%1: %2").arg(RulePalette::severityName(rule->severity), rule->message);
            return {};
        case ChangedColumn:
            return row.changedMs ? QDateTime::fromMSecsSinceEpoch(row.changedMs).toString(QStringLiteral("HH:mm:ss.zzz"))
                                 : QString();
        default: break;
        }
        return {};
    }
    if (role == Qt::BackgroundRole || role == Qt::ForegroundRole) {
        if (column != ValueColumn && column != RuleColumn && column != NameColumn)
            return {};
        const ActiveRule *rule = strongestRule(row);
        if (!rule)
            return {};
        return role == Qt::BackgroundRole ? RulePalette::background(rule->severity, rule->colour)
                                          : RulePalette::foreground(rule->severity, rule->colour);
    }
    if (role == Qt::TextAlignmentRole && column == ValueColumn)
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole && column == ValueColumn) {
        QStringList lines;
        if (row.known && !value.bitFields.isEmpty()) {
            for (const WatchBitFieldValue &field : value.bitFields)
                lines << QStringLiteral("%1 = %2%3").arg(field.name).arg(field.value).arg(field.state.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(field.state));
        }
        if (value.point >= 0 && value.point < m_watch.points.size() && m_watch.points.at(value.point).writable)
            lines << tr("Double-click or press F2 to write a new value");
        for (const ActiveRule &rule : row.rules)
            lines << QStringLiteral("%1: %2").arg(RulePalette::severityName(rule.severity), rule.message);
        return lines.isEmpty() ? QVariant() : QVariant(lines.join(QLatin1Char('\n')));
    }
    if (role == PointRole)
        return value.point;
    if (role == WritableRole)
        return value.point >= 0 && value.point < m_watch.points.size() && m_watch.points.at(value.point).writable
            && (m_watch.function == 1 || m_watch.function == 3);
    return {};
}

QVariant WatchTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case AddressColumn: return tr("Address");
    case ReferenceColumn: return tr("Reference");
    case NameColumn: return tr("Name");
    case ValueColumn: return tr("Value");
    case UnitColumn: return tr("Unit");
    case RuleColumn: return tr("Rule");
    case ChangedColumn: return tr("Changed");
    default: break;
    }
    return {};
}

} // namespace mbscope
