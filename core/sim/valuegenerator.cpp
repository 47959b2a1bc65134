#include "sim/valuegenerator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mbscope {

ValueGenerator::ValueGenerator(const GeneratorSpec &spec, quint64 seed, double initial)
    : m_spec(spec), m_random(seed), m_value(initial)
{
}

double ValueGenerator::next(double source)
{
    ++m_periods;
    using K = GeneratorSpec::Kind;
    switch (m_spec.kind) {
    case K::Constant:
        m_value = m_spec.value;
        break;
    case K::Counter:
        m_value += m_spec.step;
        if (m_value > m_spec.max)
            m_value = m_spec.wrap ? m_spec.min : m_spec.max;
        else if (m_value < m_spec.min)
            m_value = m_spec.wrap ? m_spec.max : m_spec.min;
        break;
    case K::RandomWalk: {
        double v = m_value + m_random.uniform(-m_spec.step, m_spec.step);
        if (v > m_spec.max)
            v = 2 * m_spec.max - v;
        if (v < m_spec.min)
            v = 2 * m_spec.min - v;
        m_value = std::clamp(v, m_spec.min, m_spec.max); // a step wider than the range
        break;
    }
    case K::Sine: {
        const double t = double(m_periods) * m_spec.periodMs;
        const double angle = 2 * std::numbers::pi * t / m_spec.wavePeriodMs + m_spec.phaseDeg * std::numbers::pi / 180;
        m_value = m_spec.offset + m_spec.amplitude * std::sin(angle);
        break;
    }
    case K::Poisson: {
        const double count = double(m_random.poisson(m_spec.rate * m_spec.gateMs / 1000.0));
        m_value = m_spec.accumulate ? m_value + count : count;
        break;
    }
    case K::Copy:
        m_value = source;
        break;
    }
    return m_value;
}

} // namespace mbscope
