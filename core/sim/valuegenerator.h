#pragma once

#include "profile/generatorspec.h"
#include "sim/simrandom.h"

namespace mbscope {

// One value driven by a generator (GeneratorSpec): a pure, deterministic sequence. next() gives
// the value one period later; what it gives depends only on the spec, the seed, the values
// adopted and how many periods have passed, never on the wall clock. GeneratorDriver calls it
// from timers and writes the values into a SimUnit.
//
// Counter:    v + step; past max it starts again at min (wrap) or stays at max; a negative step
//             runs down to min, then max (wrap) or stays at min.
// RandomWalk: v + uniform(-step, +step), reflected back inside [min, max].
// Sine:       offset + amplitude * sin(2 pi n periodMs / wavePeriodMs + phaseDeg) at period n.
// Poisson:    a Poisson count of mean rate * gateMs / 1000 (or the running total, accumulate).
// Copy:       the source value it is given.
class ValueGenerator
{
public:
    ValueGenerator(const GeneratorSpec &spec, quint64 seed, double initial);

    [[nodiscard]] const GeneratorSpec &spec() const { return m_spec; }
    [[nodiscard]] double value() const { return m_value; }
    [[nodiscard]] qint64 periods() const { return m_periods; }

    // The value after one more period; source is the copied value (Copy only).
    double next(double source = 0);
    // The value was set by someone else (a client, the GUI): counters, walks and running totals
    // go on from it.
    void adopt(double value) { m_value = value; }

private:
    GeneratorSpec m_spec;
    SimRandom m_random;
    double m_value = 0;
    qint64 m_periods = 0;
};

} // namespace mbscope
