#pragma once

#include <QtCore/QtGlobal>

#include <span>
#include <vector>

namespace mbscope {

// Every latency of a run, kept whole so percentiles are exact (8 bytes a sample: a million
// transactions cost 8 MB), plus running figures updated in O(1) per sample: count, min, max, and
// mean and variance by Welford's method (numerically stable where sum-of-squares is not).
//
// Percentiles use the nearest-rank method: the p-th percentile (0 < p <= 100) of n sorted values
// is the value at 1-based rank ceil(p/100 * n); p = 0 gives the minimum. It is always a value
// that was measured. The median is the 50th percentile by the same rule, i.e. the lower of the
// two middle values when n is even.
//
// Percentile queries sort the samples in place the first time and then only the samples added
// since (sorted and merged in), so a view asking 30 times a second during a long poll pays little.
// Not thread-safe, queries included: the engine's thread owns it, others receive copies.
class LatencySamples
{
public:
    void add(qint64 ns);
    void clear();
    void reserve(std::size_t count) { m_values.reserve(count); }

    [[nodiscard]] qint64 count() const { return qint64(m_values.size()); }
    [[nodiscard]] bool isEmpty() const { return m_values.empty(); }
    [[nodiscard]] qint64 minNs() const { return m_min; } // 0 when empty
    [[nodiscard]] qint64 maxNs() const { return m_max; } // 0 when empty
    [[nodiscard]] double meanNs() const { return m_mean; }
    // Population standard deviation (divided by n, as numpy.std): the spread of the samples
    // measured, not an estimate for a larger population. 0 for fewer than two samples.
    [[nodiscard]] double stddevNs() const;
    [[nodiscard]] double varianceNs2() const;

    // Nearest-rank percentile (see above); p is clamped to [0, 100]; 0 when empty.
    [[nodiscard]] qint64 percentileNs(double p) const;
    [[nodiscard]] qint64 medianNs() const { return percentileNs(50.0); }
    // All samples in ascending order.
    [[nodiscard]] std::span<const qint64> sorted() const;

    // Bytes held by the sample store (its capacity).
    [[nodiscard]] std::size_t memoryBytes() const { return m_values.capacity() * sizeof(qint64); }

private:
    void sortNow() const;

    mutable std::vector<qint64> m_values;
    mutable std::size_t m_sorted = 0; // m_values[0, m_sorted) is in ascending order
    qint64 m_min = 0;
    qint64 m_max = 0;
    double m_mean = 0;
    double m_m2 = 0; // Welford: sum of squared distances from the running mean
};

} // namespace mbscope
