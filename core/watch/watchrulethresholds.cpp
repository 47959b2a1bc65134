#include "watchrulethresholds.h"

#include "json/jsonreader.h"
#include "watch/watchruleevaluator.h"

#include <cmath>

namespace mbscope {

namespace {

bool bitTable(const WatchDefinition &watch)
{
    return watch.function == 1 || watch.function == 2;
}

} // namespace

bool WatchRuleThresholds::uses(WatchRule::Condition condition, Field field)
{
    switch (condition) {
    case WatchRule::Condition::Above: return field == Field::High;
    case WatchRule::Condition::Outside:
    case WatchRule::Condition::Inside: return true;
    case WatchRule::Condition::Below:
    case WatchRule::Condition::Equal:
    case WatchRule::Condition::NotEqual:
    case WatchRule::Condition::Bits: return field == Field::Low;
    }
    return false;
}

int WatchRuleThresholds::rawBits(const WatchDefinition &watch, const QString &point)
{
    if (bitTable(watch))
        return 1;
    if (watch.enron32)
        return 32;
    const int address = WatchRuleEvaluator::ruleAddress(watch, point);
    for (const WatchPoint &p : watch.points) {
        if (p.address == address)
            return 16 * p.format.registerCount();
    }
    return 16;
}

std::optional<WatchRuleThresholds::Problem> WatchRuleThresholds::problem(const WatchDefinition &watch, const WatchRule &rule)
{
    switch (rule.condition) {
    case WatchRule::Condition::Outside:
    case WatchRule::Condition::Inside:
        if (rule.low > rule.high)
            return Problem{Field::Low, QStringLiteral("low %1 is above high %2").arg(JsonReader::numberText(rule.low), JsonReader::numberText(rule.high))};
        return std::nullopt;
    case WatchRule::Condition::Equal:
    case WatchRule::Condition::NotEqual:
        if (bitTable(watch) && rule.low != 0 && rule.low != 1)
            return Problem{Field::Low, QStringLiteral("%1 is not 0 or 1: a coil or discrete input is never %1")
                                           .arg(JsonReader::numberText(rule.low))};
        return std::nullopt;
    case WatchRule::Condition::Bits: {
        const int bits = rawBits(watch, rule.point);
        if (rule.low < 1 || rule.low != std::floor(rule.low))
            return Problem{Field::Low, QStringLiteral("mask %1 is not a whole number of 1 or more").arg(JsonReader::numberText(rule.low))};
        if (bits < 64 && rule.low >= std::ldexp(1.0, bits))
            return Problem{Field::Low, QStringLiteral("mask 0x%1 has bits beyond the %2 bit(s) of '%3' (at most 0x%4)")
                                           .arg(QString::number(quint64(rule.low), 16).toUpper())
                                           .arg(bits)
                                           .arg(rule.point)
                                           .arg(QString::number((quint64(1) << bits) - 1, 16).toUpper())};
        return std::nullopt;
    }
    case WatchRule::Condition::Above:
    case WatchRule::Condition::Below: return std::nullopt;
    }
    return std::nullopt;
}

} // namespace mbscope
