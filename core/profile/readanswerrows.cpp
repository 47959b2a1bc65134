#include "readanswerrows.h"

#include "protocol/adubuilder.h"
#include "scaledvalue.h"

#include <QtCore/QLocale>

#include <span>
#include <utility>

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

// Index into the layouts by width: registerCount() is 2 or 4 (one-register values need none).
constexpr int layoutSlot(int width)
{
    return width >= 4 ? 1 : 0;
}

} // namespace

QString RowEntry::name() const
{
    if (!entry)
        return {};
    return entry->valueCount() > 1 ? entry->name + QStringLiteral("[%1]").arg(valueIndex) : entry->name;
}

ReadAnswerRows::ReadAnswerRows(ReadAnswer answer, std::optional<UnitProfile> profile)
    : m_answer(std::move(answer)), m_profile(std::move(profile))
{
    lay();
}

ReadAnswerResult ReadAnswerRows::answerOf(const Transaction &transaction, Framing framing)
{
    if (!transaction.isOk()) {
        ReadAnswerResult refused;
        refused.error = QStringLiteral("the transaction ended with %1").arg(transactionStatusName(transaction.status));
        if (!transaction.problem.isEmpty())
            refused.error += QStringLiteral(": ") + transaction.problem;
        return refused;
    }
    return ReadAnswer::fromPdus(AduBuilder::parse(transaction.request, framing).pdu,
                                AduBuilder::parse(transaction.response, framing).pdu);
}

QList<bool> ReadAnswerRows::changedRows(const ReadAnswer &previous, const ReadAnswer &next)
{
    // Compared by address, so a change of range still marks the values that changed.
    QList<bool> changed(next.count(), false);
    if (next.table != previous.table)
        return changed;
    for (int i = 0; i < next.count(); ++i) {
        const int old = next.address + i - previous.address;
        if (old < 0 || old >= previous.count())
            continue;
        changed[i] = next.isBits() ? next.bits.at(i) != previous.bits.at(old)
                                   : next.registers.at(i) != previous.registers.at(old);
    }
    return changed;
}

void ReadAnswerRows::setAnswer(ReadAnswer answer)
{
    m_answer = std::move(answer);
    lay();
}

void ReadAnswerRows::setProfile(std::optional<UnitProfile> profile)
{
    m_profile = std::move(profile);
    lay();
}

int ReadAnswerRows::raw(int row) const
{
    return isBits() ? int(m_answer.bits.at(row)) : int(m_answer.registers.at(row));
}

// Every width a wide format can have is laid once per answer and profile: views ask per painted
// cell. A one-register value is always its own row.
void ReadAnswerRows::lay()
{
    for (QList<WideValueLayout::Value> &l : m_layouts)
        l.clear();
    if (isBits())
        return;
    WideValueLayout::EntryAt wideEntryAt;
    if (m_profile) {
        const SimTable table = simTableOf(m_answer.table);
        wideEntryAt = [this, table](int at) -> std::optional<WideValueLayout::Entry> {
            const TableEntry *entry = m_profile->entryAt(table, at);
            if (!entry || entry->width() < 2)
                return std::nullopt;
            return WideValueLayout::Entry{entry->address, entry->address + entry->count};
        };
    }
    for (const int width : {2, 4})
        m_layouts[layoutSlot(width)] = WideValueLayout::lay(m_answer.address, rowCount(), width, wideEntryAt);
}

const QList<WideValueLayout::Value> &ReadAnswerRows::layout(int width) const
{
    return m_layouts[layoutSlot(width)];
}

RowValue ReadAnswerRows::valueAt(int row, RegisterFormat format) const
{
    RowValue v;
    v.format = format;
    v.start = row;
    v.end = row + 1;
    if (isBits() || row < 0 || row >= rowCount())
        return v;
    const int width = format.registerCount();
    const WideValueLayout::Value laid = width == 1 ? WideValueLayout::Value{row, row + 1} : layout(width).at(row);
    v.start = laid.start;
    v.end = laid.end;
    v.continuation = v.firstRow() != row;
    if (v.start < 0)
        v.gap = RowValue::Gap::BeginsBefore;
    else if (v.start + width > rowCount())
        v.gap = RowValue::Gap::EndsAfter;
    else if (v.end - v.start < width)
        v.gap = RowValue::Gap::CutByProfile;
    if (v.gap == RowValue::Gap::None) {
        const RegisterValueResult decoded = RegisterValue::fromRegisters(
            std::span<const quint16>(m_answer.registers.constData() + v.start, size_t(width)), format);
        if (decoded.ok)
            v.value = decoded.value;
    }
    return v;
}

RowEntry ReadAnswerRows::entryAt(int row) const
{
    RowEntry e;
    if (!m_profile || row < 0 || row >= rowCount())
        return e;
    e.entry = m_profile->entryAt(simTableOf(m_answer.table), address(row));
    if (!e.entry)
        return e;
    const int offset = address(row) - e.entry->address;
    const int width = e.entry->width();
    e.valueIndex = offset / width;
    e.registerIndex = offset % width;
    e.complete = e.registerIndex == 0 && row + width <= rowCount();
    return e;
}

QString ReadAnswerRows::scaledText(int row) const
{
    const RowEntry e = entryAt(row);
    if (!e.entry || isBits() || !e.complete)
        return {};
    const TableEntry &entry = *e.entry;
    const std::span<const quint16> words(m_answer.registers.constData() + row, size_t(entry.width()));
    QString text;
    if (entry.scale == 1 && entry.offset == 0) {
        // Unscaled: the format's own text, exact (hex, ascii and 64-bit integers included).
        text = RegisterValue::fromRegisters(words, entry.format).value.toText();
    } else {
        const ScaledValue scaled{entry.format, entry.scale, entry.offset};
        // Twelve significant digits hide the binary fraction of a decimal scale (1050 * 0.1).
        text = QLocale::c().toString(scaled.decode(words), 'g', 12);
    }
    return entry.unit.isEmpty() ? text : text + QLatin1Char(' ') + entry.unit;
}

} // namespace mbscope
