#pragma once

#include <QtCore/QList>

#include <functional>
#include <optional>

namespace mbscope {

// Where the values of a column of N-register values (32/64-bit integers and floats) stand in a
// read answer. A device profile's multi-register entry fixes its values' registers: a float at
// 0x007A covers 0x007A-0x007B whatever register the answer begins with, so the column's values are
// laid from the entry's address in steps of N. Elsewhere values follow each other from the first
// register not taken, and stop where the profile's next multi-register value begins. A value can
// begin before the answer (the answer starts inside it), end after it, or be cut by the next
// profile value: such a value is incomplete and is shown as such, never decoded.
class WideValueLayout
{
public:
    // One row's value, in rows of the answer: [start, end). start < 0 when the value begins
    // before the answer; end - start < width when it is cut.
    struct Value {
        int start = 0;
        int end = 1;
    };
    // The profile's multi-register value covering a PDU address: its entry's first address and the
    // address after the entry; nullopt where the profile has none (or only single registers).
    struct Entry {
        int address = 0;
        int end = 0;
    };
    using EntryAt = std::function<std::optional<Entry>(int address)>;

    // One Value per row of an answer of count registers from address.
    [[nodiscard]] static QList<Value> lay(int address, int count, int width, const EntryAt &entryAt);
};

} // namespace mbscope
