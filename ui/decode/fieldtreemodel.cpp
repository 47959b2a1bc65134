#include "fieldtreemodel.h"

#include "common/coretext.h"
#include "common/severitystyle.h"

#include <QtGui/QFontDatabase>

namespace mbscope {

FieldTreeModel::FieldTreeModel(QObject *parent)
    : QAbstractItemModel(parent)
{
    rebuildStructure();
}

void FieldTreeModel::setDissection(const Dissection &dissection)
{
    beginResetModel();
    m_dissection = dissection;
    rebuildStructure();
    endResetModel();
}

void FieldTreeModel::clear()
{
    setDissection(Dissection{});
}

// The FieldTree is flat and depth-first with parent indexes; a tree model needs rows. One pass
// gives every field its row among its siblings. A parent that does not come before its child
// cannot be shown as such, so that field is shown at the top rather than making a cycle.
void FieldTreeModel::rebuildStructure()
{
    const FieldTree &tree = m_dissection.fields;
    const int n = tree.size();
    m_children.assign(size_t(n) + 1, {});
    m_rowInParent.assign(size_t(n), 0);
    for (int i = 0; i < n; ++i) {
        int p = tree.at(i).parent;
        if (p < -1 || p >= i)
            p = -1;
        std::vector<int> &siblings = m_children[size_t(p + 1)];
        m_rowInParent[size_t(i)] = int(siblings.size());
        siblings.push_back(i);
    }
}

static int shownParent(const FieldTree &tree, int field)
{
    const int p = tree.at(field).parent;
    return p < -1 || p >= field ? -1 : p;
}

QModelIndex FieldTreeModel::indexOfField(int fieldIndex, int column) const
{
    if (fieldIndex < 0 || fieldIndex >= m_dissection.fields.size() || column < 0 || column >= ColumnCount)
        return {};
    return createIndex(m_rowInParent[size_t(fieldIndex)], column, quintptr(fieldIndex));
}

QModelIndex FieldTreeModel::indexOfKey(const char *key, int column) const
{
    return indexOfField(m_dissection.fields.indexOf(key), column);
}

QModelIndex FieldTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (column < 0 || column >= ColumnCount || row < 0)
        return {};
    if (parent.isValid() && parent.column() != 0)
        return {};
    const size_t slot = parent.isValid() ? size_t(parent.internalId()) + 1 : 0;
    if (slot >= m_children.size())
        return {};
    const std::vector<int> &rows = m_children[slot];
    if (row >= int(rows.size()))
        return {};
    return createIndex(row, column, quintptr(rows[size_t(row)]));
}

QModelIndex FieldTreeModel::parent(const QModelIndex &child) const
{
    if (!child.isValid())
        return {};
    const int p = shownParent(m_dissection.fields, int(child.internalId()));
    return p < 0 ? QModelIndex() : createIndex(m_rowInParent[size_t(p)], 0, quintptr(p));
}

int FieldTreeModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid() && parent.column() != 0)
        return 0;
    const size_t slot = parent.isValid() ? size_t(parent.internalId()) + 1 : 0;
    return slot < m_children.size() ? int(m_children[slot].size()) : 0;
}

int FieldTreeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

Qt::ItemFlags FieldTreeModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == 0 && rowCount(index) == 0)
        f |= Qt::ItemNeverHasChildren;
    return f;
}

QVariant FieldTreeModel::displayText(int field, int column) const
{
    const FieldTree &tree = m_dissection.fields;
    const Field &f = tree.at(field);
    switch (column) {
    case OffsetColumn:
        return f.offset;
    case BytesColumn: {
        const QByteArray raw = tree.raw(field);
        if (raw.size() <= kMaxBytesShown)
            return QString::fromLatin1(raw.toHex(' ').toUpper());
        return QString::fromLatin1(raw.left(kMaxBytesShown).toHex(' ').toUpper()) + QStringLiteral(" \u2026");
    }
    case FieldColumn: {
        // FieldTree::name and display, in the window's language: the core's stay English.
        QString name = fieldText(f.name);
        if (f.address >= 0)
            name += QLatin1Char(' ') + QString::number(f.address);
        return name;
    }
    case ValueColumn: {
        QString text = tree.valueText(field);
        if (f.meaning && *f.meaning)
            text += (text.isEmpty() ? QString() : QStringLiteral(" ")) + fieldText(f.meaning);
        return text;
    }
    case ProblemColumn:
        return f.message;
    }
    return {};
}

QVariant FieldTreeModel::toolTip(int field, int column) const
{
    const FieldTree &tree = m_dissection.fields;
    const Field &f = tree.at(field);
    QString tip;
    if (column == BytesColumn) {
        const QByteArray raw = tree.raw(field);
        if (raw.size() > kMaxBytesShown)
            tip = QString::fromLatin1(raw.toHex(' ').toUpper());
    }
    if (!f.message.isEmpty())
        tip = tip.isEmpty() ? f.message : tip + QLatin1Char('\n') + f.message;
    return tip.isEmpty() ? QVariant() : QVariant(tip);
}

QVariant FieldTreeModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const int field = int(index.internalId());
    if (field < 0 || field >= m_dissection.fields.size())
        return {};
    const Field &f = m_dissection.fields.at(field);
    const int column = index.column();

    switch (role) {
    case Qt::DisplayRole:
        return displayText(field, column);
    case Qt::ToolTipRole:
        return toolTip(field, column);
    case Qt::TextAlignmentRole:
        if (column == OffsetColumn)
            return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
        return {};
    case Qt::FontRole:
        if (column == BytesColumn)
            return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        return {};
    case Qt::ForegroundRole:
        // Only the problem text is coloured; the row's tint already marks the field, and
        // coloured text on every column would be hard to read on the tinted background.
        if (column == ProblemColumn && f.severity != Severity::Ok)
            return SeverityStyle::textColor(f.severity);
        return {};
    case Qt::BackgroundRole:
        if (f.severity != Severity::Ok)
            return SeverityStyle::backgroundColor(f.severity);
        return {};
    case Qt::DecorationRole:
        if (column == FieldColumn && f.severity != Severity::Ok)
            return severityIcon(f.severity);
        return {};
    case KeyRole:
        return QString::fromLatin1(f.key);
    case SeverityRole:
        return int(f.severity);
    case FieldIndexRole:
        return field;
    case OffsetRole:
        return f.offset;
    case LengthRole:
        return f.length;
    default:
        return {};
    }
}

QIcon FieldTreeModel::severityIcon(Severity severity) const
{
    QIcon &icon = m_icons[size_t(severity) % m_icons.size()];
    if (icon.isNull())
        icon = SeverityStyle::icon(severity);
    return icon;
}

QVariant FieldTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || section < 0 || section >= ColumnCount)
        return {};
    if (role == Qt::DisplayRole) {
        switch (section) {
        case OffsetColumn: return tr("Offset");
        case BytesColumn: return tr("Bytes");
        case FieldColumn: return tr("Field");
        case ValueColumn: return tr("Value");
        case ProblemColumn: return tr("Problem");
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case OffsetColumn: return tr("Byte offset of the field in the frame, counted from 0");
        case BytesColumn: return tr("The field's raw bytes as they appear in the frame");
        case FieldColumn: return tr("The field's name; per-item fields show their register, coil or object address");
        case ValueColumn: return tr("The value and what it means");
        case ProblemColumn: return tr("What is wrong with the field and what was expected");
        }
    }
    return {};
}

QHash<int, QByteArray> FieldTreeModel::roleNames() const
{
    QHash<int, QByteArray> names = QAbstractItemModel::roleNames();
    names.insert(KeyRole, "key");
    names.insert(SeverityRole, "severity");
    names.insert(FieldIndexRole, "fieldIndex");
    names.insert(OffsetRole, "offset");
    names.insert(LengthRole, "length");
    return names;
}

} // namespace mbscope
