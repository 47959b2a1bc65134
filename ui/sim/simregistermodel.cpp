#include "simregistermodel.h"

#include "common/severitystyle.h"

#include <QtGui/QBrush>
#include <QtGui/QColor>

#include <algorithm>

namespace mbscope {

SimRegisterModel::SimRegisterModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void SimRegisterModel::setUnit(quint8 unit, const QList<SimValueUpdate> &snapshot, const std::optional<UnitProfile> &profile)
{
    beginResetModel();
    m_hasUnit = true;
    m_unit = unit;
    m_profile = profile;
    m_rows.clear();
    m_rowOf.clear();
    m_changed.clear();
    for (const SimValueUpdate &update : snapshot) {
        if (update.unit != unit)
            continue;
        for (qsizetype i = 0; i < update.values.size(); ++i) {
            const int address = int(update.start) + int(i);
            if (address > 0xFFFF || m_rowOf.contains(keyOf(update.table, address)))
                continue;
            m_rowOf.insert(keyOf(update.table, address), int(m_rows.size()));
            m_rows.append(Row{update.table, quint16(address), update.values[i]});
        }
    }
    endResetModel();
}

void SimRegisterModel::clear()
{
    beginResetModel();
    m_hasUnit = false;
    m_profile.reset();
    m_rows.clear();
    m_rowOf.clear();
    m_changed.clear();
    endResetModel();
}

void SimRegisterModel::applyUpdates(const QList<SimValueUpdate> &updates)
{
    if (!m_hasUnit || m_rows.isEmpty())
        return;
    QList<int> changed;
    for (const SimValueUpdate &update : updates) {
        if (update.unit != m_unit)
            continue;
        for (qsizetype i = 0; i < update.values.size(); ++i) {
            const int row = m_rowOf.value(keyOf(update.table, int(update.start) + int(i)), -1);
            if (row < 0 || m_rows[row].value == update.values[i])
                continue;
            m_rows[row].value = update.values[i];
            changed.append(row);
        }
    }
    if (changed.isEmpty() && m_changed.isEmpty())
        return;
    // One signal for the batch: the rows changed now and the rows that lose their mark.
    QList<int> touched = changed + m_changed;
    const auto [low, high] = std::minmax_element(touched.cbegin(), touched.cend());
    m_changed = changed;
    Q_EMIT dataChanged(index(*low, 0), index(*high, ColumnCount - 1));
}

int SimRegisterModel::rowOf(SimTable table, int address) const
{
    return m_rowOf.value(keyOf(table, address), -1);
}

std::optional<quint16> SimRegisterModel::value(SimTable table, int address) const
{
    const int row = rowOf(table, address);
    if (row < 0)
        return std::nullopt;
    return m_rows[row].value;
}

int SimRegisterModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int SimRegisterModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString SimRegisterModel::tableText(SimTable table) const
{
    switch (table) {
    case SimTable::Coils: return tr("coil");
    case SimTable::DiscreteInputs: return tr("discrete input");
    case SimTable::InputRegisters: return tr("input register");
    case SimTable::HoldingRegisters: return tr("holding register");
    }
    return {};
}

QString SimRegisterModel::nameOf(const Row &row) const
{
    if (!m_profile)
        return {};
    const TableEntry *entry = m_profile->entryAt(row.table, row.address);
    if (!entry)
        return {};
    const int offset = int(row.address) - int(entry->address);
    const int width = entry->width();
    QString name = entry->name;
    if (entry->valueCount() > 1)
        name = tr("%1[%2]").arg(name).arg(offset / width);
    if (width > 1)
        name = tr("%1, register %2 of %3").arg(name).arg(offset % width + 1).arg(width);
    return name;
}

QString SimRegisterModel::descriptionOf(const Row &row) const
{
    if (!m_profile)
        return {};
    const TableEntry *entry = m_profile->entryAt(row.table, row.address);
    if (!entry)
        return {};
    if (entry->unit.isEmpty())
        return entry->description;
    return tr("%1 (unit: %2)").arg(entry->description, entry->unit);
}

QVariant SimRegisterModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Row &row = m_rows[index.row()];
    const bool bit = isBitTable(row.table);
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        switch (index.column()) {
        case TableColumn: return tableText(row.table);
        case AddressColumn:
            return role == Qt::EditRole ? QVariant(int(row.address))
                                        : QVariant(tr("%1 (0x%2)").arg(row.address).arg(QString::number(row.address, 16).toUpper().rightJustified(4, QLatin1Char('0'))));
        case NameColumn: return nameOf(row);
        case ValueColumn: return role == Qt::EditRole ? QVariant(int(row.value)) : QVariant(QString::number(row.value));
        case HexColumn:
            return bit ? QString() : QStringLiteral("0x") + QString::number(row.value, 16).toUpper().rightJustified(4, QLatin1Char('0'));
        default: return {};
        }
    case Qt::ToolTipRole: {
        const QString description = descriptionOf(row);
        return description.isEmpty() ? QVariant() : QVariant(description);
    }
    case Qt::TextAlignmentRole:
        if (index.column() == ValueColumn || index.column() == HexColumn)
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case Qt::BackgroundRole:
        if (m_changed.contains(index.row()))
            return QBrush(SeverityStyle::backgroundColor(Severity::Warning));
        return {};
    case AddressRole: return int(row.address);
    case TableRole: return int(row.table);
    case ChangedRole: return m_changed.contains(index.row());
    default: return {};
    }
}

QVariant SimRegisterModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case TableColumn: return tr("Table");
    case AddressColumn: return tr("Address");
    case NameColumn: return tr("Name");
    case ValueColumn: return tr("Value");
    case HexColumn: return tr("Hex");
    default: return {};
    }
}

Qt::ItemFlags SimRegisterModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (index.isValid() && (index.column() == ValueColumn || index.column() == HexColumn))
        flags |= Qt::ItemIsEditable;
    return flags;
}

bool SimRegisterModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid)
        || (index.column() != ValueColumn && index.column() != HexColumn))
        return false;
    const Row &row = m_rows[index.row()];
    const QString text = value.toString().trimmed();
    bool ok = false;
    uint number = 0;
    if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        number = text.mid(2).toUInt(&ok, 16);
    else if (index.column() == HexColumn)
        number = text.toUInt(&ok, 16);
    else
        number = text.toUInt(&ok, 10);
    const uint limit = isBitTable(row.table) ? 1 : 0xFFFF;
    if (!ok || number > limit) {
        Q_EMIT editRefused(isBitTable(row.table)
                               ? tr("'%1' is not a bit value for %2 %3: type 0 or 1.").arg(text, tableText(row.table)).arg(row.address)
                               : tr("'%1' is not a register value for %2 %3: type 0 to 65535, or 0x0000 to 0xFFFF.")
                                     .arg(text, tableText(row.table))
                                     .arg(row.address));
        return false;
    }
    Q_EMIT valueEdited(m_unit, row.table, row.address, quint16(number));
    return true;
}

} // namespace mbscope
