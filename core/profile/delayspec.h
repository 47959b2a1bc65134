#pragma once

#include <QtCore/QString>

namespace mbscope {

class SimRandom;

// How long something waits: a unit's response time, a fault's delay. Times are milliseconds
// (fractions allowed); a drawn delay is clamped to [minMs, maxMs] (0 and no upper bound by
// default) so that a normal distribution never asks for a negative wait.
struct DelaySpec {
    enum class Kind : quint8 {
        Fixed,       // ms
        Uniform,     // minMs .. maxMs
        Normal,      // meanMs, stddevMs
        Exponential, // meanMs (a memoryless wait: the tail of a busy device)
        LogNormal,   // meanMs, stddevMs of the delay itself (right-skewed: a few draws several times the median)
    };

    Kind kind = Kind::Fixed;
    double ms = 0;       // Fixed
    double meanMs = 0;   // Normal, Exponential, LogNormal
    double stddevMs = 0; // Normal, LogNormal
    double minMs = 0;    // Uniform's lower bound; the clamp for the others
    double maxMs = -1;   // Uniform's upper bound; the clamp for the others (negative: none)

    [[nodiscard]] static DelaySpec fixed(double ms);
    [[nodiscard]] bool isZero() const { return kind == Kind::Fixed && ms <= 0; }
    // Draws one delay, in nanoseconds. Fixed delays draw nothing.
    [[nodiscard]] qint64 sampleNs(SimRandom &random) const;
    // The expected value before clamping, in ms (for a unit's nominal response time).
    [[nodiscard]] double nominalMs() const;
    // "fixed", "uniform", "normal", "exponential", "lognormal"
    [[nodiscard]] static QString kindName(Kind kind);

    friend bool operator==(const DelaySpec &, const DelaySpec &) = default;
};

} // namespace mbscope
