#include "replay/ignoredfields.h"

#include "session/fieldexpectation.h"

namespace mbscope {

bool IgnoredFields::add(const QString &selector, QString *error)
{
    FieldExpectation parsed;
    if (!FieldExpectation::parseSelector(selector.trimmed(), &parsed, error))
        return false;
    Rule rule;
    rule.selector = selector.trimmed();
    rule.key = parsed.key;
    if (parsed.address >= 0)
        rule.label = parsed.key + QStringLiteral("@0x") + QString::number(parsed.address, 16).toUpper().rightJustified(4, QLatin1Char('0'));
    else if (parsed.occurrence >= 0)
        rule.label = parsed.key + QStringLiteral("[%1]").arg(parsed.occurrence);
    else
        rule.anyAddress = true;
    m_rules.append(rule);
    return true;
}

QStringList IgnoredFields::selectors() const
{
    QStringList out;
    for (const Rule &r : m_rules)
        out.append(r.selector);
    return out;
}

QString IgnoredFields::selectorFor(const QString &label) const
{
    for (const Rule &r : m_rules) {
        if (r.anyAddress) {
            // "key", "key@0x....", "key[N]": the key up to the selector part.
            if (label == r.key || label.startsWith(r.key + QLatin1Char('@')) || label.startsWith(r.key + QLatin1Char('[')))
                return r.selector;
        } else if (label == r.label) {
            return r.selector;
        }
    }
    return {};
}

} // namespace mbscope
