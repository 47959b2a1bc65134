#include "latencysamples.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace mbscope {

namespace {

constexpr quint64 kExactBins = quint64(1) << LatencySamples::kSignificantBits; // values below: a bin each
constexpr quint64 kHalf = kExactBins / 2;                                       // bins per doubling above

} // namespace

// Bins as HdrHistogram lays them out: a value under 2^S is its own bin; above, a value keeps its
// top S bits q (2^(S-1) <= q < 2^S) and the shift s that dropped the rest, bin s * 2^(S-1) + q,
// which continues 0 .. 2^S - 1 without a gap. A bin spans 2^s values starting at q << s >= 2^(S-1+s),
// so its middle is within 2^(s-1) / 2^(S-1+s) = 2^-S of every value in it.
std::size_t LatencySamples::binOf(qint64 ns)
{
    const quint64 u = quint64(std::max<qint64>(0, ns));
    if (u < kExactBins)
        return std::size_t(u);
    const int shift = int(std::bit_width(u)) - kSignificantBits;
    return std::size_t(quint64(shift) * kHalf + (u >> shift));
}

std::size_t LatencySamples::maxBins()
{
    return binOf(std::numeric_limits<qint64>::max()) + 1;
}

qint64 LatencySamples::binMiddle(std::size_t bin) const
{
    qint64 middle = qint64(bin);
    if (bin >= kExactBins) {
        const quint64 shift = quint64(bin) / kHalf - 1;
        const quint64 q = quint64(bin) - shift * kHalf;
        middle = qint64((q << shift) + ((quint64(1) << shift) >> 1));
    }
    return std::clamp(middle, m_min, m_max);
}

void LatencySamples::add(qint64 ns)
{
    if (m_count == 0) {
        m_min = m_max = ns;
    } else {
        m_min = std::min(m_min, ns);
        m_max = std::max(m_max, ns);
    }
    ++m_count;
    if (m_binned) {
        const std::size_t bin = binOf(ns);
        if (bin >= m_bins.size())
            m_bins.resize(bin + 1, 0);
        ++m_bins[bin];
    } else {
        m_values.push_back(ns);
        if (m_limit != 0 && m_values.size() > m_limit)
            binAll();
    }
    // Welford (Knuth, TAOCP vol. 2, 4.2.2): mean and M2 in one pass, no catastrophic cancellation.
    const double x = double(ns);
    const double delta = x - m_mean;
    m_mean += delta / double(m_count);
    m_m2 += delta * (x - m_mean);
}

void LatencySamples::binAll()
{
    m_binned = true;
    for (const qint64 ns : m_values) {
        const std::size_t bin = binOf(ns);
        if (bin >= m_bins.size())
            m_bins.resize(bin + 1, 0);
        ++m_bins[bin];
    }
    std::vector<qint64>().swap(m_values); // its memory given back, not just emptied
    m_sorted = 0;
}

void LatencySamples::setExactLimit(std::size_t limit)
{
    m_limit = limit;
    if (!m_binned && m_limit != 0 && m_values.size() > m_limit)
        binAll();
}

void LatencySamples::clear()
{
    std::vector<qint64>().swap(m_values);
    std::vector<quint64>().swap(m_bins);
    m_binned = false;
    m_count = 0;
    m_sorted = 0;
    m_min = m_max = 0;
    m_mean = m_m2 = 0;
}

double LatencySamples::varianceNs2() const
{
    return m_count < 2 ? 0.0 : std::max(0.0, m_m2 / double(m_count));
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

qint64 LatencySamples::countBelow(double valueNs) const
{
    if (!m_binned) {
        const std::span<const qint64> values = sorted();
        return qint64(std::lower_bound(values.begin(), values.end(), valueNs, [](qint64 v, double e) { return double(v) < e; })
                      - values.begin());
    }
    qint64 below = 0;
    for (std::size_t bin = 0; bin < m_bins.size(); ++bin) {
        if (m_bins[bin] == 0)
            continue;
        if (!(double(binMiddle(bin)) < valueNs))
            break; // middles only grow with the bin
        below += qint64(m_bins[bin]);
    }
    return below;
}

qint64 LatencySamples::percentileNs(double p) const
{
    if (m_count == 0)
        return 0;
    if (!(p > 0.0)) // also NaN
        return m_min;
    if (p >= 100.0)
        return m_max;
    const auto n = double(m_count);
    // Rank ceil(p/100 * n), computed so that 90% of 10 values is rank 9 exactly, not 9.000001
    // rounded up to 10: p * n is exact for the integers and halves used in practice.
    auto rank = std::size_t(std::ceil(p * n / 100.0 - 1e-9));
    rank = std::clamp<std::size_t>(rank, 1, std::size_t(m_count));
    if (m_binned) {
        quint64 seen = 0;
        for (std::size_t bin = 0; bin < m_bins.size(); ++bin) {
            seen += m_bins[bin];
            if (seen >= rank)
                return binMiddle(bin);
        }
        return m_max;
    }
    sortNow();
    return m_values[rank - 1];
}

} // namespace mbscope
