#include "latencysamples.h"

#include <algorithm>
#include <array>
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

namespace {

// LSD radix sort, 11 bits a pass over the values' range (latencies within 4 ms take two passes,
// within 8 s three): several times std::sort's speed on a million samples, which analysing a
// large capture sorts once per table. The scratch buffer is freed on return.
void radixSort(qint64 *first, qint64 *last)
{
    const std::size_t n = std::size_t(last - first);
    const auto [low, high] = std::minmax_element(first, last);
    const quint64 base = quint64(*low);
    const quint64 range = quint64(*high) - base;
    if (range == 0)
        return;
    constexpr int kBits = 11;
    constexpr std::size_t kBuckets = std::size_t(1) << kBits;
    std::vector<qint64> scratch(n);
    qint64 *from = first;
    qint64 *to = scratch.data();
    for (int shift = 0; shift < 64 && (range >> shift) != 0; shift += kBits) {
        std::array<std::size_t, kBuckets + 1> counts{};
        for (std::size_t i = 0; i < n; ++i)
            ++counts[((quint64(from[i]) - base) >> shift & (kBuckets - 1)) + 1];
        for (std::size_t b = 1; b <= kBuckets; ++b)
            counts[b] += counts[b - 1];
        for (std::size_t i = 0; i < n; ++i)
            to[counts[(quint64(from[i]) - base) >> shift & (kBuckets - 1)]++] = from[i];
        std::swap(from, to);
    }
    if (from != first)
        std::copy(from, from + n, first);
}

} // namespace

void LatencySamples::sortNow() const
{
    if (m_sorted == m_values.size())
        return;
    const auto middle = m_values.begin() + std::ptrdiff_t(m_sorted);
    constexpr std::size_t kRadixFrom = 4096; // below, std::sort is as fast
    if (m_values.size() - m_sorted >= kRadixFrom)
        radixSort(m_values.data() + m_sorted, m_values.data() + m_values.size());
    else
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
