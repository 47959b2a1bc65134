#include "registertablemodel.h"

#include "common/coretext.h"

#include "protocol/adubuilder.h"
#include "protocol/hexformat.h"
#include "protocol/registervalue.h"
#include "profile/scaledvalue.h"

#include <QtCore/QLocale>
#include <QtGui/QBrush>
#include <QtGui/QColor>
#include <QtGui/QFontDatabase>

namespace mbscope {

namespace {

SimTable simTableOf(ModbusTable table)
{
    switch (table) {
    case ModbusTable::Coils: return SimTable::Coils;
    case ModbusTable::DiscreteInputs: return SimTable::DiscreteInputs;
    case ModbusTable::InputRegisters: return SimTable::InputRegisters;
    case ModbusTable::HoldingRegisters: return SimTable::HoldingRegisters;
    }
    return SimTable::HoldingRegisters;
}

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

// What a value column shows on one row.
struct RegisterTableModel::ValueCell {
    QString text;         // the display text or the tooltip, as asked
    int firstRow = 0;     // the row of the value's first register
    int span = 1;         // rows the value covers (0 on the rows after its first)
    bool continuation = false;
    bool complete = true; // all the value's registers are in the answer
};

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
    return update(AduBuilder::parse(transaction.request, framing).pdu,
                  AduBuilder::parse(transaction.response, framing).pdu);
}

void RegisterTableModel::setAnswer(const ReadAnswer &answer)
{
    const bool sameRows = m_hasAnswer && answer.table == m_answer.table && answer.address == m_answer.address
        && answer.count() == m_answer.count();
    // Compared by address, so a change of range still marks the values that changed.
    QList<bool> changed(answer.count(), false);
    if (m_hasAnswer && answer.table == m_answer.table) {
        for (int i = 0; i < answer.count(); ++i) {
            const int old = answer.address + i - m_answer.address;
            if (old < 0 || old >= m_answer.count())
                continue;
            changed[i] = answer.isBits() ? answer.bits.at(i) != m_answer.bits.at(old)
                                         : answer.registers.at(i) != m_answer.registers.at(old);
        }
    }
    m_lastProblem.clear();
    if (sameRows) {
        m_answer = answer;
        m_changed = changed;
        if (rowCount() > 0)
            Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
    } else {
        beginResetModel();
        m_answer = answer;
        m_changed = changed;
        m_hasAnswer = true;
        m_layouts.clear();
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
    m_answer = ReadAnswer();
    m_hasAnswer = false;
    m_changed.clear();
    m_layouts.clear();
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
    if (m_answer.isBits() && m_hasAnswer) {
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
    if (m_answer.isBits() && m_hasAnswer) {
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
    return m_hasAnswer && m_answer.isBits() ? 1 : int(m_formats.size());
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
    m_profile = unit;
    m_profileName = profileName;
    m_layouts.clear();
    endResetModel();
    Q_EMIT layoutOfValuesChanged();
}

void RegisterTableModel::clearProfile()
{
    beginResetModel();
    m_profile.reset();
    m_profileName.clear();
    m_layouts.clear();
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
    return parent.isValid() || !m_hasAnswer ? 0 : m_answer.count();
}

int RegisterTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : FirstValueColumn + valueColumnCount() + 1;
}

const TableEntry *RegisterTableModel::entryAt(int row) const
{
    if (!m_profile)
        return nullptr;
    return m_profile->entryAt(simTableOf(m_answer.table), m_answer.address + row);
}

const QList<WideValueLayout::Value> &RegisterTableModel::valueLayout(int width) const
{
    auto it = m_layouts.find(width);
    if (it == m_layouts.end()) {
        WideValueLayout::EntryAt wideEntryAt;
        if (m_profile && !m_answer.isBits()) {
            const SimTable table = simTableOf(m_answer.table);
            wideEntryAt = [this, table](int address) -> std::optional<WideValueLayout::Entry> {
                const TableEntry *entry = m_profile->entryAt(table, address);
                if (!entry || entry->width() < 2)
                    return std::nullopt;
                return WideValueLayout::Entry{entry->address, entry->address + entry->count};
            };
        }
        it = m_layouts.insert(width, WideValueLayout::lay(m_answer.address, m_answer.count(), width, wideEntryAt));
    }
    return *it;
}

QString RegisterTableModel::rowWhere(int row) const
{
    const int address = m_answer.address + row;
    const QString reference = ReadAnswer::referenceText(m_answer.reference(row));
    if (!m_answer.isBits())
        return tr("register %1 (PDU address %2)").arg(reference).arg(address);
    return m_answer.table == ModbusTable::Coils ? tr("coil %1 (PDU address %2)").arg(reference).arg(address)
                                                : tr("discrete input %1 (PDU address %2)").arg(reference).arg(address);
}

RegisterTableModel::ValueCell RegisterTableModel::valueCell(int row, int valueIndex, CellText wanted) const
{
    // The layout is arithmetic; text is made only for the role asked (views ask per painted cell).
    ValueCell cell;
    cell.firstRow = row;
    if (m_answer.isBits()) {
        if (wanted == CellText::Display)
            cell.text = m_answer.bits.at(row) ? tr("1  ON") : tr("0  OFF");
        return cell;
    }
    const RegisterFormat format = m_formats.at(valueIndex);
    const int width = format.registerCount();
    const WideValueLayout::Value value = valueLayout(width).at(row);
    cell.firstRow = qMax(value.start, 0);
    cell.continuation = cell.firstRow != row;
    cell.span = cell.continuation ? 0 : value.end - cell.firstRow;
    cell.complete = value.start >= 0 && value.end - value.start == width;
    if (wanted == CellText::None)
        return cell;

    // The value's own first register, also when the answer begins inside it.
    const QString firstRef = ReadAnswer::referenceText(m_answer.reference(value.start));
    if (cell.continuation) {
        if (wanted == CellText::Display)
            cell.text = tr("\u2191 %1 from %2").arg(format.typeName(), firstRef);
        else
            cell.text = tr("Register %1 is register %2 of the %3 registers of the %4 value at %5")
                            .arg(ReadAnswer::referenceText(m_answer.reference(row)))
                            .arg(row - cell.firstRow + 1)
                            .arg(width)
                            .arg(format.name(), firstRef);
        return cell;
    }
    if (!cell.complete) {
        if (wanted == CellText::Display)
            cell.text = tr("(%1 of %2 registers)").arg(cell.span).arg(width);
        else if (value.start < 0)
            cell.text = tr("%1 needs %2 registers from %3; the answer begins %4 registers into it")
                            .arg(format.name())
                            .arg(width)
                            .arg(firstRef)
                            .arg(-value.start);
        else if (value.start + width > m_answer.count())
            cell.text = tr("%1 needs %2 registers from %3; the answer ends after %4")
                            .arg(format.name())
                            .arg(width)
                            .arg(firstRef)
                            .arg(cell.span);
        else
            cell.text = tr("%1 needs %2 registers from %3; the profile's next value begins after %4")
                            .arg(format.name())
                            .arg(width)
                            .arg(firstRef)
                            .arg(cell.span);
        return cell;
    }
    if (wanted == CellText::Display) {
        const RegisterValueResult decoded = RegisterValue::fromRegisters(
            std::span<const quint16>(m_answer.registers.constData() + row, size_t(width)), format);
        cell.text = decoded.ok ? decoded.value.toText() : decoded.error;
        return cell;
    }
    QString raw;
    for (int i = row; i < row + width; ++i)
        raw += (raw.isEmpty() ? QString() : QStringLiteral(" ")) + hexDigits(m_answer.registers.at(i), 4);
    const QString span = width == 1
        ? firstRef
        : tr("%1 registers %2-%3").arg(width).arg(firstRef,
                                                             ReadAnswer::referenceText(m_answer.reference(row + width - 1)));
    cell.text = tr("%1\n%2, on the wire %3").arg(describe(format), span, raw);
    return cell;
}

QString RegisterTableModel::nameText(int row) const
{
    const TableEntry *entry = entryAt(row);
    if (!entry)
        return {};
    const int offset = m_answer.address + row - entry->address;
    const int width = entry->width();
    QString name = entry->name;
    if (entry->valueCount() > 1)
        name += QStringLiteral("[%1]").arg(offset / width);
    if (offset % width != 0)
        name += tr(" (register %1 of %2)").arg(offset % width + 1).arg(width);
    return name;
}

QString RegisterTableModel::scaledText(int row) const
{
    const TableEntry *entry = entryAt(row);
    if (!entry || m_answer.isBits())
        return {};
    const int offset = m_answer.address + row - entry->address;
    const int width = entry->width();
    if (offset % width != 0)
        return QStringLiteral("\u2191");
    if (row + width > m_answer.count())
        return tr("(%1 of %2 registers)").arg(m_answer.count() - row).arg(width);
    const std::span<const quint16> words(m_answer.registers.constData() + row, size_t(width));
    QString text;
    if (entry->scale == 1 && entry->offset == 0) {
        // Unscaled: the format's own text, exact (hex, ascii and 64-bit integers included).
        text = RegisterValue::fromRegisters(words, entry->format).value.toText();
    } else {
        const ScaledValue scaled{entry->format, entry->scale, entry->offset};
        // Twelve significant digits hide the binary fraction of a decimal scale (1050 * 0.1).
        text = QLocale::c().toString(scaled.decode(words), 'g', 12);
    }
    return entry->unit.isEmpty() ? text : text + QLatin1Char(' ') + entry->unit;
}

bool RegisterTableModel::isChanged(int row, int column) const
{
    int first = row;
    int width = 1;
    if (const int vi = valueIndexOf(column); vi >= 0) {
        if (!m_answer.isBits()) {
            const WideValueLayout::Value value = valueLayout(m_formats.at(vi).registerCount()).at(row);
            first = value.start;
            width = value.end - value.start;
        }
    } else if (column == scaledColumn()) {
        const TableEntry *entry = entryAt(row);
        if (!entry)
            return false;
        width = entry->width();
        first = row - (m_answer.address + row - entry->address) % width;
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
        return m_answer.reference(row).describe();
    if (column == NameColumn) {
        const TableEntry *entry = entryAt(row);
        return entry ? QVariant(entry->description) : QVariant();
    }
    if (const int vi = valueIndexOf(column); vi >= 0)
        return m_answer.isBits() ? QVariant() : QVariant(valueCell(row, vi, CellText::ToolTip).text);
    if (column == scaledColumn()) {
        const TableEntry *entry = entryAt(row);
        if (!entry)
            return m_profile ? tr("The profile names no value at this address") : QVariant();
        return tr("%1 as %2, value = raw \u00d7 %3 + %4")
            .arg(entry->name, entry->format.name())
            .arg(entry->scale)
            .arg(entry->offset);
    }
    return {};
}

bool RegisterTableModel::isEditableCell(int row, int column) const
{
    if (!ModiconReference::isWritable(m_answer.table))
        return false;
    if (const int vi = valueIndexOf(column); vi >= 0) {
        const ValueCell cell = valueCell(row, vi, CellText::None);
        return m_answer.isBits() || (!cell.continuation && cell.complete);
    }
    if (column == scaledColumn() && !m_answer.isBits()) {
        const TableEntry *entry = entryAt(row);
        return entry && (m_answer.address + row - entry->address) % entry->width() == 0
            && row + entry->width() <= m_answer.count();
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
            return ReadAnswer::addressText(m_answer.address + row);
        if (column == ReferenceColumn)
            return ReadAnswer::referenceText(m_answer.reference(row));
        if (column == NameColumn)
            return nameText(row);
        if (vi >= 0) {
            const ValueCell cell = valueCell(row, vi, CellText::Display);
            if (role == Qt::EditRole && m_answer.isBits())
                return m_answer.bits.at(row) ? QStringLiteral("1") : QStringLiteral("0");
            return cell.text;
        }
        return scaledText(row);
    case Qt::ToolTipRole:
        return toolTip(row, column);
    case Qt::CheckStateRole:
        if (vi >= 0 && m_answer.isBits())
            return m_answer.bits.at(row) ? Qt::Checked : Qt::Unchecked;
        return {};
    case Qt::BackgroundRole:
        return isChanged(row, column) ? QVariant(QBrush(kChangedBackground)) : QVariant();
    case Qt::ForegroundRole:
        if (vi >= 0 && !m_answer.isBits() && valueCell(row, vi, CellText::None).continuation)
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
        return m_answer.address + row;
    case ChangedRole:
        return isChanged(row, column);
    case SpanRole:
        if (vi >= 0)
            return valueCell(row, vi, CellText::None).span;
        return 1;
    case RawRole:
        return m_answer.isBits() ? int(m_answer.bits.at(row)) : int(m_answer.registers.at(row));
    case FormatRole:
        return vi >= 0 ? QVariant(m_answer.isBits() ? QStringLiteral("bit") : m_formats.at(vi).name()) : QVariant();
    default:
        return {};
    }
}

QVariant RegisterTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
    const int digit = ModiconReference::tableDigit(m_answer.table);
    if (role == Qt::DisplayRole) {
        if (section == AddressColumn)
            return tr("PDU address");
        if (section == ReferenceColumn)
            return tr("Modicon (%1xxxx, from 1)").arg(digit);
        if (section == NameColumn)
            return tr("Name");
        if (const int vi = valueIndexOf(section); vi >= 0)
            return m_hasAnswer && m_answer.isBits() ? tr("Value") : m_formats.at(vi).name();
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
            return m_profile ? tr("Names from the profile %1").arg(m_profileName)
                             : tr("No profile: no names");
        if (const int vi = valueIndexOf(section); vi >= 0)
            return m_answer.isBits() ? QVariant()
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
        if (m_answer.isBits())
            f |= Qt::ItemIsUserCheckable;
    }
    return f;
}

std::optional<QList<quint16>> RegisterTableModel::wordsFromText(int row, int column, const QString &text,
                                                                QString *error) const
{
    const QString trimmed = text.trimmed();
    if (column == scaledColumn()) {
        const TableEntry *entry = entryAt(row);
        QString number = trimmed;
        if (!entry->unit.isEmpty() && number.endsWith(entry->unit))
            number = number.chopped(entry->unit.size()).trimmed();
        if (entry->scale == 1 && entry->offset == 0) {
            const RegisterValueResult v = RegisterValue::fromText(number, entry->format);
            if (!v.ok) {
                *error = entry->format.name() + QLatin1String(": ") + v.error;
                return std::nullopt;
            }
            return v.value.registers();
        }
        bool ok = false;
        const double value = QLocale::c().toDouble(number, &ok);
        if (!ok) {
            *error = tr("'%1' is not a number: the scaled value of %2 takes a decimal number")
                         .arg(trimmed, entry->name);
            return std::nullopt;
        }
        const RegisterValueResult v = ScaledValue{entry->format, entry->scale, entry->offset}.encode(value);
        if (!v.ok) {
            *error = tr("%1 %2 (raw = (value - %3) / %4): %5")
                         .arg(entry->name, entry->format.name())
                         .arg(entry->offset)
                         .arg(entry->scale)
                         .arg(v.error);
            return std::nullopt;
        }
        return v.value.registers();
    }
    const RegisterFormat format = formatOfColumn(column);
    // Spaces are characters in ASCII ("A " is 0x4120); elsewhere they only surround the number.
    const RegisterValueResult v =
        RegisterValue::fromText(format.type() == RegisterType::Ascii ? text : trimmed, format);
    if (!v.ok) {
        *error = format.name() + QLatin1String(": ") + v.error;
        return std::nullopt;
    }
    return v.value.registers();
}

TableWriteResult RegisterTableModel::writeFor(const QModelIndex &index, const QString &text) const
{
    TableWriteResult result;
    if (!index.isValid() || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return result;
    const int row = index.row();
    const int column = index.column();
    if (!ModiconReference::isWritable(m_answer.table)) {
        result.error = tr("%1: %2 are read-only; only coils and holding registers can be written")
                           .arg(rowWhere(row), fieldText(ModiconReference::tableName(m_answer.table)));
        return result;
    }
    if (!isEditableCell(row, column)) {
        result.error = tr("%1: this cell cannot be written (edit a value's first register)").arg(rowWhere(row));
        return result;
    }
    if (m_answer.isBits()) {
        const std::optional<bool> on = TableWrite::coilFromText(text);
        if (!on) {
            result.error = tr("%1: '%2' is not a coil value: expected 1 or 0 (on/off, true/false)")
                               .arg(rowWhere(row), text.trimmed());
            return result;
        }
        return TableWrite::coil(m_answer.address + row, *on, m_writeChoice);
    }
    QString error;
    const std::optional<QList<quint16>> words = wordsFromText(row, column, text, &error);
    if (!words) {
        result.error = tr("%1, %2").arg(rowWhere(row), error);
        return result;
    }
    result = TableWrite::registers(m_answer.address + row, *words, m_writeChoice);
    return result;
}

bool RegisterTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    QString text;
    if (role == Qt::CheckStateRole && m_answer.isBits())
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
