#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace mbscope {

// Fields of an answer a replay expects to change (a live counter, a clock, a measured value):
// their differences are reported as ignored, never as a verdict. Each is selected as a plan's
// expectations select fields (FieldExpectation): "modbus.register_value@0x007D" or "@125" (the
// one at that address), "modbus.register_value[2]" (the third without an address), or a key
// alone, which ignores the key at every address.
class IgnoredFields
{
public:
    // Adds one selector; false with *error saying what is wrong in it.
    bool add(const QString &selector, QString *error);

    [[nodiscard]] bool isEmpty() const { return m_rules.isEmpty(); }
    // The selectors as given, in order.
    [[nodiscard]] QStringList selectors() const;
    // The selector that covers a comparison label ("modbus.register_value@0x007D",
    // "modbus.byte_count", "modbus.register_value[1]"), or an empty string.
    [[nodiscard]] QString selectorFor(const QString &label) const;

private:
    struct Rule {
        QString selector; // as given
        QString label;    // in AnswerComparison's form: key@0x007D, key[N], key
        QString key;
        bool anyAddress = false; // a key alone
    };
    QList<Rule> m_rules;
};

} // namespace mbscope
