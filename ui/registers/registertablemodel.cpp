#include "registertablemodel.h"

#include "registerwrite.h"

#include "common/coretext.h"

#include "protocol/hexformat.h"
#include "protocol/registervalue.h"

#include <QtGui/QBrush>
#include <QtGui/QColor>
#include <QtGui/QFontDatabase>

namespace mbscope {

namespace {

// RegisterFormat::description in the window's language: "float32 (IEEE 754 single), word swap (CDAB)".
QString describe(const RegisterFormat &format)
{
    return QCoreApplication::translate("mbscope::RegisterTableModel", "%1, %2 (%3)")
        .arg(fieldText(format.typeDescription()), fieldText(format.orderWords()), format.orderName());
}

// A changed value's background: light amber, readable with the default palette's text.
const QColor kChangedBackground(255, 226, 140);
const QColor kContinuationText(128, 128, 128);

} // namespace

RegisterTableModel::RegisterTableModel(QObject *parent)
    : QAbstractTableModel(parent),
      m_formats{RegisterFormat(RegisterType::UInt16), RegisterFormat(RegisterType::Hex16)}
{
    m_highlightTimer.setSingleShot(true);
    connect(&m_highlightTimer, &QTimer::timeout, this, &RegisterTableModel::clearHighlights);
}

bool RegisterTableModel::update(const QByteArray &requestPdu, const QByteArray &responsePdu)
{
    const ReadAnswerResult r = ReadAnswer::fromPdus(requestPdu, responsePdu);
    if (!r.ok) {
        m_lastProblem = tr("answer not shown: %1").arg(r.error);
        Q_EMIT answerRefused(m_lastProblem);
        return false;
    }
    setAnswer(r.answer);
    return true;
}

bool RegisterTableModel::updateFromTransaction(const Transaction &transaction, Framing framing)
{
    if (!transaction.isOk()) {
        const QString status = transactionStatusName(transaction.status);
        m_lastProblem = transaction.problem.isEmpty()
            ? tr("answer not shown: the transaction ended with %1").arg(status)
            : tr("answer not shown: the transaction ended with %1: %2").arg(status, transaction.problem);
        Q_EMIT answerRefused(m_lastProblem);
        return false;
    }
    const ReadAnswerResult r = ReadAnswerRows::answerOf(transaction, framing);
    if (!r.ok) {
        m_lastProblem = tr("answer not shown: %1").arg(r.error);
        Q_EMIT answerRefused(m_lastProblem);
        return false;
    }
    setAnswer(r.answer);
    return true;
}

void RegisterTableModel::setAnswer(const ReadAnswer &answer)
{
    const ReadAnswer &previous = m_rows.answer();
    const bool sameRows = m_hasAnswer && answer.table == previous.table && answer.address == previous.address
        && answer.count() == previous.count();
    const QList<bool> changed =
        m_hasAnswer ? ReadAnswerRows::changedRows(previous, answer) : QList<bool>(answer.count(), false);
    m_lastProblem.clear();
    if (sameRows) {
        m_rows.setAnswer(answer);
        m_changed = changed;
        if (rowCount() > 0)
            Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
    } else {
        beginResetModel();
        m_rows.setAnswer(answer);
        m_changed = changed;
        m_hasAnswer = true;
        endResetModel();
        Q_EMIT layoutOfValuesChanged();
    }
    if (m_highlightMs > 0 && changed.contains(true))
        m_highlightTimer.start(m_highlightMs);
    else
        m_highlightTimer.stop();
}

void RegisterTableModel::clear()
{
    beginResetModel();
    m_rows.setAnswer(ReadAnswer());
    m_hasAnswer = false;
    m_changed.clear();
    m_lastProblem.clear();
    endResetModel();
    Q_EMIT layoutOfValuesChanged();
}

void RegisterTableModel::setValueFormats(const QList<RegisterFormat> &formats)
{
    if (formats.isEmpty() || formats == m_formats)
        return;
    beginResetModel();
    m_formats = formats;
    endResetModel();
    Q_EMIT layoutOfValuesChanged();
}

void RegisterTableModel::setValueFormat(int valueIndex, RegisterFormat format)
{
    if (valueIndex < 0 || valueIndex >= m_formats.size() || m_formats.at(valueIndex) == format)
        return;
    m_formats[valueIndex] = format;
    valueColumnsChanged();
}

void RegisterTableModel::addValueColumn(RegisterFormat format)
{
    if (m_rows.isBits() && m_hasAnswer) {
        m_formats.append(format); // bit tables show one value column whatever the formats
        return;
    }
    const int column = FirstValueColumn + int(m_formats.size());
    beginInsertColumns({}, column, column);
    m_formats.append(format);
    endInsertColumns();
    Q_EMIT layoutOfValuesChanged();
}

void RegisterTableModel::removeValueColumn(int valueIndex)
{
    // The last value column stays: a table without values shows nothing.
    if (valueIndex < 0 || valueIndex >= m_formats.size() || m_formats.size() == 1)
        return;
    if (m_rows.isBits() && m_hasAnswer) {
        m_formats.removeAt(valueIndex);
        return;
    }
    const int column = FirstValueColumn + valueIndex;
    beginRemoveColumns({}, column, column);
    m_formats.removeAt(valueIndex);
    endRemoveColumns();
    Q_EMIT layoutOfValuesChanged();
}

void RegisterTableModel::setOrder(RegisterOrder order)
{
    bool any = false;
    for (RegisterFormat &f : m_formats) {
        const RegisterFormat ordered(f.type(), order);
        any = any || ordered != f;
        f = ordered;
    }
    if (any)
        valueColumnsChanged();
}

void RegisterTableModel::valueColumnsChanged()
{
    const int first = FirstValueColumn;
    const int last = FirstValueColumn + valueColumnCount() - 1;
    Q_EMIT headerDataChanged(Qt::Horizontal, first, last);
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, first), index(rowCount() - 1, last));
    Q_EMIT layoutOfValuesChanged();
}

int RegisterTableModel::valueColumnCount() const
{
    return m_hasAnswer && m_rows.isBits() ? 1 : int(m_formats.size());
}

int RegisterTableModel::valueIndexOf(int column) const
{
    const int i = column - FirstValueColumn;
    return i >= 0 && i < valueColumnCount() ? i : -1;
}

RegisterFormat RegisterTableModel::formatOfColumn(int column) const
{
    const int i = valueIndexOf(column);
    return i >= 0 ? m_formats.at(i) : RegisterFormat();
}

void RegisterTableModel::setProfile(const UnitProfile &unit, const QString &profileName)
{
    beginResetModel();
    m_rows.setProfile(unit);
    m_profileName = profileName;
    endResetModel();
    Q_EMIT layoutOfValuesChanged();
}

void RegisterTableModel::clearProfile()
{
    beginResetModel();
    m_rows.setProfile(std::nullopt);
    m_profileName.clear();
    endResetModel();
    Q_EMIT layoutOfValuesChanged();
}

void RegisterTableModel::setHighlightDuration(int ms)
{
    m_highlightMs = qMax(0, ms);
    if (m_highlightMs == 0)
        m_highlightTimer.stop();
}

void RegisterTableModel::clearHighlights()
{
    m_highlightTimer.stop();
    if (!m_changed.contains(true))
        return;
    m_changed.fill(false);
    Q_EMIT dataChanged(index(0, FirstValueColumn), index(rowCount() - 1, columnCount() - 1),
                       {Qt::BackgroundRole, ChangedRole});
}

int RegisterTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_hasAnswer ? 0 : m_rows.rowCount();
}

int RegisterTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : FirstValueColumn + valueColumnCount() + 1;
}

RowValue RegisterTableModel::valueAt(int row, int valueIndex) const
{
    return m_rows.valueAt(row, m_formats.at(valueIndex));
}

// Text is made only for the role asked: views ask per painted cell.
QString RegisterTableModel::valueText(int row, const RowValue &value) const
{
    if (m_rows.isBits())
        return m_rows.raw(row) ? tr("1  ON") : tr("0  OFF");
    if (value.continuation)
        return tr("\u2191 %1 from %2").arg(value.format.typeName(), ReadAnswer::referenceText(m_rows.reference(value.start)));
    if (!value.isComplete())
        return tr("(%1 of %2 registers)").arg(value.span()).arg(value.width());
    return value.value ? value.value->toText() : QString();
}

QString RegisterTableModel::valueToolTip(int row, const RowValue &value) const
{
    const RegisterFormat format = value.format;
    const int width = value.width();
    // The value's own first register, also when the answer begins inside it.
    const QString firstRef = ReadAnswer::referenceText(m_rows.reference(value.start));
    if (value.continuation)
        return tr("Register %1 is register %2 of the %3 registers of the %4 value at %5")
            .arg(ReadAnswer::referenceText(m_rows.reference(row)))
            .arg(row - value.firstRow() + 1)
            .arg(width)
            .arg(format.name(), firstRef);
    switch (value.gap) {
    case RowValue::Gap::BeginsBefore:
        return tr("%1 needs %2 registers from %3; the answer begins %4 registers into it")
            .arg(format.name())
            .arg(width)
            .arg(firstRef)
            .arg(-value.start);
    case RowValue::Gap::EndsAfter:
        return tr("%1 needs %2 registers from %3; the answer ends after %4")
            .arg(format.name())
            .arg(width)
            .arg(firstRef)
            .arg(value.span());
    case RowValue::Gap::CutByProfile:
        return tr("%1 needs %2 registers from %3; the profile's next value begins after %4")
            .arg(format.name())
            .arg(width)
            .arg(firstRef)
            .arg(value.span());
    case RowValue::Gap::None:
        break;
    }
    QString raw;
    for (int i = row; i < row + width; ++i)
        raw += (raw.isEmpty() ? QString() : QStringLiteral(" ")) + hexDigits(quint16(m_rows.raw(i)), 4);
    const QString span = width == 1
        ? firstRef
        : tr("%1 registers %2-%3").arg(width).arg(firstRef,
                                                             ReadAnswer::referenceText(m_rows.reference(row + width - 1)));
    return tr("%1\n%2, on the wire %3").arg(describe(format), span, raw);
}

QString RegisterTableModel::nameText(int row) const
{
    const RowEntry entry = m_rows.entryAt(row);
    QString name = entry.name();
    if (entry.entry && !entry.isFirstRegister())
        name += tr(" (register %1 of %2)").arg(entry.registerIndex + 1).arg(entry.width());
    return name;
}

QString RegisterTableModel::scaledText(int row) const
{
    const RowEntry entry = m_rows.entryAt(row);
    if (!entry.entry || m_rows.isBits())
        return {};
    if (!entry.isFirstRegister())
        return QStringLiteral("\u2191");
    if (!entry.complete)
        return tr("(%1 of %2 registers)").arg(m_rows.rowCount() - row).arg(entry.width());
    return m_rows.scaledText(row);
}
bool RegisterTableModel::isChanged(int row, int column) const
{
    int first = row;
    int width = 1;
    if (const int vi = valueIndexOf(column); vi >= 0) {
        if (!m_rows.isBits()) {
            const RowValue value = valueAt(row, vi);
            first = value.start;
            width = value.end - value.start;
        }
    } else if (column == scaledColumn()) {
        const RowEntry entry = m_rows.entryAt(row);
        if (!entry.entry)
            return false;
        width = entry.width();
        first = row - entry.registerIndex;
    } else {
        return false;
    }
    for (int i = qMax(0, first); i < first + width && i < m_changed.size(); ++i) {
        if (m_changed.at(i))
            return true;
    }
    return false;
}

QVariant RegisterTableModel::toolTip(int row, int column) const
{
    if (column == ReferenceColumn)
        return m_rows.reference(row).describe();
    if (column == NameColumn) {
        const TableEntry *entry = m_rows.entryAt(row).entry;
        return entry ? QVariant(entry->description) : QVariant();
    }
    if (const int vi = valueIndexOf(column); vi >= 0)
        return m_rows.isBits() ? QVariant() : QVariant(valueToolTip(row, valueAt(row, vi)));
    if (column == scaledColumn()) {
        const TableEntry *entry = m_rows.entryAt(row).entry;
        if (!entry)
            return hasProfile() ? tr("The profile names no value at this address") : QVariant();
        return tr("%1 as %2, value = raw \u00d7 %3 + %4")
            .arg(entry->name, entry->format.name())
            .arg(entry->scale)
            .arg(entry->offset);
    }
    return {};
}

bool RegisterTableModel::isEditableCell(int row, int column) const
{
    if (!ModiconReference::isWritable(m_rows.answer().table))
        return false;
    if (const int vi = valueIndexOf(column); vi >= 0) {
        if (m_rows.isBits())
            return true;
        const RowValue value = valueAt(row, vi);
        return !value.continuation && value.isComplete();
    }
    if (column == scaledColumn() && !m_rows.isBits()) {
        const RowEntry entry = m_rows.entryAt(row);
        return entry.entry && entry.complete;
    }
    return false;
}

QVariant RegisterTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const int row = index.row();
    const int column = index.column();
    const int vi = valueIndexOf(column);
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        if (column == AddressColumn)
            return ReadAnswer::addressText(m_rows.address(row));
        if (column == ReferenceColumn)
            return ReadAnswer::referenceText(m_rows.reference(row));
        if (column == NameColumn)
            return nameText(row);
        if (vi >= 0) {
            if (role == Qt::EditRole && m_rows.isBits())
                return m_rows.raw(row) ? QStringLiteral("1") : QStringLiteral("0");
            return valueText(row, m_rows.isBits() ? RowValue() : valueAt(row, vi));
        }
        return scaledText(row);
    case Qt::ToolTipRole:
        return toolTip(row, column);
    case Qt::CheckStateRole:
        if (vi >= 0 && m_rows.isBits())
            return m_rows.raw(row) ? Qt::Checked : Qt::Unchecked;
        return {};
    case Qt::BackgroundRole:
        return isChanged(row, column) ? QVariant(QBrush(kChangedBackground)) : QVariant();
    case Qt::ForegroundRole:
        if (vi >= 0 && !m_rows.isBits() && valueAt(row, vi).continuation)
            return QBrush(kContinuationText);
        return {};
    case Qt::FontRole:
        if (column == AddressColumn || column == ReferenceColumn || vi >= 0)
            return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        return {};
    case Qt::TextAlignmentRole:
        if (vi >= 0 || column == scaledColumn())
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        return QVariant::fromValue(Qt::AlignLeft | Qt::AlignVCenter);
    case AddressRole:
        return m_rows.address(row);
    case ChangedRole:
        return isChanged(row, column);
    case SpanRole:
        if (vi >= 0)
            return m_rows.isBits() ? 1 : valueAt(row, vi).span();
        return 1;
    case RawRole:
        return m_rows.raw(row);
    case FormatRole:
        return vi >= 0 ? QVariant(m_rows.isBits() ? QStringLiteral("bit") : m_formats.at(vi).name()) : QVariant();
    default:
        return {};
    }
}

QVariant RegisterTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
    const int digit = ModiconReference::tableDigit(m_rows.answer().table);
    if (role == Qt::DisplayRole) {
        if (section == AddressColumn)
            return tr("PDU address");
        if (section == ReferenceColumn)
            return tr("Modicon (%1xxxx, from 1)").arg(digit);
        if (section == NameColumn)
            return tr("Name");
        if (const int vi = valueIndexOf(section); vi >= 0)
            return m_hasAnswer && m_rows.isBits() ? tr("Value") : m_formats.at(vi).name();
        if (section == scaledColumn())
            return tr("Scaled");
        return {};
    }
    if (role == Qt::ToolTipRole) {
        if (section == AddressColumn)
            return tr("The 0-based address the request carries (V1.1b3, 4.4)");
        if (section == ReferenceColumn)
            return tr("Modicon reference: the table digit %1, then the 1-based element number "
                      "(PDU address + 1)")
                .arg(digit);
        if (section == NameColumn)
            return hasProfile() ? tr("Names from the profile %1").arg(m_profileName)
                             : tr("No profile: no names");
        if (const int vi = valueIndexOf(section); vi >= 0)
            return m_rows.isBits() ? QVariant()
                                     : QVariant(tr("%1\nRight-click to change the format").arg(describe(m_formats.at(vi))));
        if (section == scaledColumn())
            return tr("The profile's format, scale, offset and unit: value = raw \u00d7 scale + offset");
    }
    return {};
}

Qt::ItemFlags RegisterTableModel::flags(const QModelIndex &index) const
{
    if (!index.isValid() || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemNeverHasChildren;
    if (isEditableCell(index.row(), index.column())) {
        f |= Qt::ItemIsEditable;
        if (m_rows.isBits())
            f |= Qt::ItemIsUserCheckable;
    }
    return f;
}

TableWriteResult RegisterTableModel::writeFor(const QModelIndex &index, const QString &text) const
{
    TableWriteResult result;
    if (!index.isValid() || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return result;
    const int row = index.row();
    const int column = index.column();
    const ModbusTable table = m_rows.answer().table;
    if (!ModiconReference::isWritable(table)) {
        result.error = tr("%1: %2 are read-only; only coils and holding registers can be written")
                           .arg(RegisterWrite::where(m_rows, row), fieldText(ModiconReference::tableName(table)));
        return result;
    }
    if (!isEditableCell(row, column)) {
        result.error = tr("%1: this cell cannot be written (edit a value's first register)").arg(RegisterWrite::where(m_rows, row));
        return result;
    }
    if (m_rows.isBits())
        return RegisterWrite::coil(m_rows, row, text, m_writeChoice);
    if (column == scaledColumn())
        return RegisterWrite::scaled(m_rows, row, text, m_writeChoice);
    return RegisterWrite::value(m_rows, row, formatOfColumn(column), text, m_writeChoice);
}

bool RegisterTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    QString text;
    if (role == Qt::CheckStateRole && m_rows.isBits())
        text = value.toInt() == Qt::Checked ? QStringLiteral("1") : QStringLiteral("0");
    else if (role == Qt::EditRole)
        text = value.toString();
    else
        return false;
    const TableWriteResult write = writeFor(index, text);
    if (!write.ok) {
        refuse(write.error.isEmpty() ? tr("no cell to write") : write.error);
        return false;
    }
    Q_EMIT writeRequested(write.pdu, write.description);
    return true;
}

void RegisterTableModel::refuse(const QString &message)
{
    m_lastProblem = tr("not written: %1").arg(message);
    Q_EMIT editRefused(m_lastProblem);
}

} // namespace mbscope
