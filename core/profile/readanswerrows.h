#pragma once

#include "deviceprofile.h"
#include "exchange/transaction.h"
#include "protocol/framing.h"
#include "protocol/readanswer.h"
#include "protocol/registerformat.h"
#include "protocol/registervalue.h"
#include "protocol/widevaluelayout.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <array>
#include <optional>

namespace mbscope {

// One value of a value column, seen from one row: the registers it stands on and what they hold.
struct RowValue {
    // Why a value cannot be decoded: some of its registers are not in the answer.
    enum class Gap : quint8 {
        None,         // every register is there
        BeginsBefore, // the answer begins inside the value
        EndsAfter,    // the answer ends inside it
        CutByProfile, // the profile's next value begins inside it
    };

    RegisterFormat format;
    int start = 0; // row of the value's first register; < 0 when it begins before the answer
    int end = 1;   // row after the last of its registers the answer holds
    bool continuation = false; // the row is not the value's first row in the table
    Gap gap = Gap::None;
    std::optional<RegisterValue> value; // decoded when gap is None

    [[nodiscard]] int width() const { return format.registerCount(); }
    // The value's first row in the table (its first register, or the answer's first row).
    [[nodiscard]] int firstRow() const { return start < 0 ? 0 : start; }
    // Rows the value covers on its first row, 0 on the rows after (a view's span).
    [[nodiscard]] int span() const { return continuation ? 0 : end - firstRow(); }
    [[nodiscard]] bool isComplete() const { return gap == Gap::None; }
};

// Where a row stands in the profile entry that names it.
struct RowEntry {
    const TableEntry *entry = nullptr; // nullptr: no profile, or it names nothing at this address
    int valueIndex = 0;                // which of the entry's values (an entry may hold several)
    int registerIndex = 0;             // which register of that value, from 0
    bool complete = false;             // on the value's first row: all its registers are there

    [[nodiscard]] int width() const { return entry ? entry->width() : 1; }
    [[nodiscard]] bool isFirstRegister() const { return registerIndex == 0; }
    // "Counts[2]": the entry's name, indexed when it holds several values; empty without an entry.
    [[nodiscard]] QString name() const;
};

// The rows a register table shows for one read answer: one row per PDU address, with its Modicon
// reference, the profile's name, the values in any RegisterFormat and the profile's scaled value.
// A value wider than one register stands on the row of its first register. Where the profile has
// a multi-register entry, values start at its address (WideValueLayout), elsewhere from the first
// register of the answer; a value whose registers are not all in the answer is never decoded and
// says why (RowValue::Gap). Pure and cheap to ask: the layouts are made once per answer and
// profile, values are decoded when asked, and nothing here is translated (the window words it).
class ReadAnswerRows
{
public:
    ReadAnswerRows() = default;
    explicit ReadAnswerRows(ReadAnswer answer, std::optional<UnitProfile> profile = std::nullopt);

    // The answer of an Ok transaction whose bytes are ADUs in framing (any other status is
    // refused with its name and problem).
    [[nodiscard]] static ReadAnswerResult answerOf(const Transaction &transaction, Framing framing);
    // Per row of next: its value differs from the value previous had at the same address (same
    // table; addresses previous did not read are unchanged).
    [[nodiscard]] static QList<bool> changedRows(const ReadAnswer &previous, const ReadAnswer &next);

    void setAnswer(ReadAnswer answer);
    void setProfile(std::optional<UnitProfile> profile);
    [[nodiscard]] const ReadAnswer &answer() const { return m_answer; }
    [[nodiscard]] const std::optional<UnitProfile> &profile() const { return m_profile; }
    [[nodiscard]] int rowCount() const { return m_answer.count(); }
    [[nodiscard]] bool isBits() const { return m_answer.isBits(); }

    [[nodiscard]] int address(int row) const { return m_answer.address + row; }
    [[nodiscard]] ModiconReference reference(int row) const { return m_answer.reference(row); }
    // The row's register (0-65535) or bit (0/1).
    [[nodiscard]] int raw(int row) const;

    // Register tables: the value of format that covers row.
    [[nodiscard]] RowValue valueAt(int row, RegisterFormat format) const;
    // The profile's entry at row (nothing in bit tables' values aside from the name).
    [[nodiscard]] RowEntry entryAt(int row) const;
    // On the first row of a complete profile value of a register table: the value as the profile
    // means it, raw × scale + offset with its unit ("12.5 V"); unscaled, the format's own text
    // (exact for hex, ascii and 64-bit integers). Empty elsewhere.
    [[nodiscard]] QString scaledText(int row) const;

private:
    void lay();
    [[nodiscard]] const QList<WideValueLayout::Value> &layout(int width) const;

    ReadAnswer m_answer;
    std::optional<UnitProfile> m_profile;
    std::array<QList<WideValueLayout::Value>, 2> m_layouts; // values 2 and 4 registers wide
};

} // namespace mbscope
