#pragma once

#include "simtable.h"

#include <QtCore/QString>

#include <optional>

namespace mbscope {

// What drives a value of a device profile over time (see docs/profiles.md). Values are in
// engineering units, i.e. after scaling: the generator's output v becomes the raw register
// value (v - offset) / scale, rounded for integer types and clamped to the type's range.
//
// Every kind produces a new value every periodMs milliseconds of simulated time. The numbers
// depend only on the seed and on how many periods have passed, never on the wall clock.
struct GeneratorSpec {
    enum class Kind : quint8 {
        Constant,   // value, again and again (undoes what a client wrote)
        Counter,    // += step each period; past max back to min (wrap) or stays at max
        RandomWalk, // += a uniform step in [-step, +step], reflected at min and max
        Sine,       // offset + amplitude * sin(2 pi t / wavePeriodMs + phaseDeg)
        Poisson,    // counts in a gate of gateMs at rate counts per second (radiation detectors)
        Copy,       // the value of another register or bit (sourceTable, sourceAddress)
    };

    Kind kind = Kind::Constant;
    double periodMs = 1000;

    double value = 0;    // Constant
    double step = 1;     // Counter (may be negative), RandomWalk (largest step)
    double min = 0;      // Counter, RandomWalk: the loader fills the type's range when absent
    double max = 65535;
    bool wrap = true;    // Counter

    double amplitude = 1;     // Sine
    double offset = 0;        // Sine: the centre line
    double wavePeriodMs = 60000;
    double phaseDeg = 0;

    double rate = 1;          // Poisson: counts per second
    double gateMs = 1000;     // Poisson: counting time of one value (periodMs by default)
    bool accumulate = false;  // Poisson: a running total instead of the count of the last gate

    SimTable sourceTable = SimTable::HoldingRegisters; // Copy
    quint16 sourceAddress = 0;

    std::optional<quint64> seed; // else derived from the profile's seed and the value's place

    [[nodiscard]] static QString kindName(Kind kind); // "randomWalk"
    [[nodiscard]] static std::optional<Kind> kindFromName(QStringView name);

    friend bool operator==(const GeneratorSpec &, const GeneratorSpec &) = default;
};

} // namespace mbscope
