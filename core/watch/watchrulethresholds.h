#pragma once

#include "watch/watchdefinition.h"

#include <optional>

namespace mbscope {

// The thresholds each kind of rule compares with, and the thresholds that make no sense for the
// point a rule names (so that a rule never fires, or never clears, because of a number it does
// not show). Shared by the session reader (messages located by JSON path) and the window's rule
// editor (messages located by column).
//   above: High only    below, equal, not equal: Low only    bits: Low (the mask)
//   outside, inside: Low and High, Low at most High
class WatchRuleThresholds
{
public:
    enum class Field : quint8 { Low, High };

    struct Problem {
        Field field;
        QString message; // "mask 0x10000 has bits beyond the 16 bits of 'status'"
    };

    [[nodiscard]] static bool uses(WatchRule::Condition condition, Field field);
    // The first threshold of rule that makes no sense in watch, or nothing. The rule's point must
    // name an address of the watch (checked before).
    [[nodiscard]] static std::optional<Problem> problem(const WatchDefinition &watch, const WatchRule &rule);
    // How many bits the raw value of the rule's point has: 1 in the coil and discrete input
    // tables, 16 per register otherwise (32 for a watch of 32-bit Enron registers).
    [[nodiscard]] static int rawBits(const WatchDefinition &watch, const QString &point);
};

} // namespace mbscope
