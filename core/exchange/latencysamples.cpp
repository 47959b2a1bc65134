#include "latencysamples.h"

#include <algorithm>
#include <cmath>

namespace mbscope {

void LatencySamples::add(qint64 ns)
{
    if (m_values.empty()) {
        m_min = m_max = ns;
    } else {
        m_min = std::min(m_min, ns);
        m_max = std::max(m_max, ns);
    }
    m_values.push_back(ns);
    // Welford (Knuth, TAOCP vol. 2, 4.2.2): mean and M2 in one pass, no catastrophic cancellation.
    const double x = double(ns);
    const double delta = x - m_mean;
    m_mean += delta / double(m_values.size());
    m_m2 += delta * (x - m_mean);
}

void LatencySamples::clear()
{
    m_values.clear();
    m_sorted = 0;
    m_min = m_max = 0;
    m_mean = m_m2 = 0;
}

double LatencySamples::varianceNs2() const
{
    return m_values.size() < 2 ? 0.0 : std::max(0.0, m_m2 / double(m_values.size()));
}

double LatencySamples::stddevNs() const
{
    return std::sqrt(varianceNs2());
}

void LatencySamples::sortNow() const
{
    if (m_sorted == m_values.size())
        return;
    const auto middle = m_values.begin() + std::ptrdiff_t(m_sorted);
    std::sort(middle, m_values.end());
    std::inplace_merge(m_values.begin(), middle, m_values.end());
    m_sorted = m_values.size();
}

std::span<const qint64> LatencySamples::sorted() const
{
    sortNow();
    return {m_values.data(), m_values.size()};
}

qint64 LatencySamples::percentileNs(double p) const
{
    if (m_values.empty())
        return 0;
    if (!(p > 0.0)) // also NaN
        return m_min;
    if (p >= 100.0)
        return m_max;
    sortNow();
    const auto n = double(m_values.size());
    // Rank ceil(p/100 * n), computed so that 90% of 10 values is rank 9 exactly, not 9.000001
    // rounded up to 10: p * n is exact for the integers and halves used in practice.
    auto rank = std::size_t(std::ceil(p * n / 100.0 - 1e-9));
    rank = std::clamp<std::size_t>(rank, 1, m_values.size());
    return m_values[rank - 1];
}

} // namespace mbscope
