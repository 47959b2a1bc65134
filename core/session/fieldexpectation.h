#pragma once

#include <QtCore/QString>

#include <optional>

namespace mbscope {

class FieldTree;

// A decoded field of an answer and the value it must have: exactly, or within [min, max].
// The field is named by its dissector key (the Wireshark-style keys of core/protocol:
// "modbus.function_code", "modbus.register_value", "modbus.exception_code") and, where a frame
// holds several, which one: "modbus.register_value@0x007F" (the one at that register or coil
// address) or "modbus.register_value[2]" (the third); the first one without either.
struct FieldExpectation {
    QString selector;       // as written: "modbus.register_value@0x007F"
    QString key;            // "modbus.register_value"
    int address = -1;       // @ADDRESS, else -1
    int occurrence = -1;    // [N], else -1
    std::optional<qint64> equals;
    std::optional<qint64> min;
    std::optional<qint64> max;

    // Reads a selector; false with *error saying what is wrong in it.
    static bool parseSelector(const QString &text, FieldExpectation *out, QString *error);
    // The field's index in tree, or -1.
    [[nodiscard]] int find(const FieldTree &tree) const;
    // "1050", "0 to 1000", "at least 5", "at most 7"
    [[nodiscard]] QString expectedText() const;
    [[nodiscard]] bool accepts(qint64 value) const;

    friend bool operator==(const FieldExpectation &, const FieldExpectation &) = default;
};

} // namespace mbscope
