#pragma once

#include <QtCore/QtGlobal>

#include <span>
#include <vector>

namespace mbscope {

// Every latency of a run, kept whole so percentiles are exact (8 bytes a sample: a million
// transactions cost 8 MB), plus running figures updated in O(1) per sample: count, min, max, and
// mean and variance by Welford's method (numerically stable where sum-of-squares is not).
//
// A store that must not grow without end (the window, polling all day) is given an exact limit:
// past that many samples they are counted in fixed bins instead, 2^kSignificantBits - 1 of them
// per doubling (values under 2^kSignificantBits ns, about 1 us, each have a bin of their own), and
// the samples themselves are let go. From then on the store holds at most maxBins() counters
// (225 KB however long the run) and each percentile is the middle of its bin, within
// kRelativeError (1/1024, under 0.1 %) of the exact one, clamped to the exact min and max;
// count, min, max, mean and standard deviation stay exact. The command line's stores have no
// limit: their percentiles are exact.
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
    static constexpr int kSignificantBits = 10;
    static constexpr double kRelativeError = 1.0 / double(1 << kSignificantBits);
    // The limit of the stores that live as long as the window does (its poll, the Analysis
    // dock's runs): 100,000 samples (800 KB) exact, then bins.
    static constexpr std::size_t kLongRunExactLimit = 100'000;

    void add(qint64 ns);
    void clear(); // the exact limit is kept
    void reserve(std::size_t count) { m_values.reserve(count); }

    // Past limit samples, bin them (see above); 0: no limit, every sample kept (the default).
    // A store already over a new limit is binned at once.
    void setExactLimit(std::size_t limit);
    [[nodiscard]] std::size_t exactLimit() const { return m_limit; }
    // True while every sample is kept (percentiles exact, sorted() complete).
    [[nodiscard]] bool isExact() const { return !m_binned; }
    // The most counters a binned store can hold (values up to 2^63 ns).
    [[nodiscard]] static std::size_t maxBins();

    [[nodiscard]] qint64 count() const { return m_count; }
    [[nodiscard]] bool isEmpty() const { return m_count == 0; }
    [[nodiscard]] qint64 minNs() const { return m_min; } // 0 when empty
    [[nodiscard]] qint64 maxNs() const { return m_max; } // 0 when empty
    [[nodiscard]] double meanNs() const { return m_mean; }
    // Population standard deviation (divided by n, as numpy.std): the spread of the samples
    // measured, not an estimate for a larger population. 0 for fewer than two samples.
    [[nodiscard]] double stddevNs() const;
    [[nodiscard]] double varianceNs2() const;

    // Nearest-rank percentile (see above); p is clamped to [0, 100]; 0 when empty. Exact while
    // isExact(), else the middle of the bin that holds that rank (within kRelativeError).
    [[nodiscard]] qint64 percentileNs(double p) const;
    [[nodiscard]] qint64 medianNs() const { return percentileNs(50.0); }
    // All samples in ascending order; empty once binned (!isExact()): use countBelow().
    [[nodiscard]] std::span<const qint64> sorted() const;
    // How many samples lie below valueNs (Histogram::addSamples counts bins with it): exact while
    // isExact(), else the samples of the bins whose middle (clamped to min and max) lies below.
    [[nodiscard]] qint64 countBelow(double valueNs) const;

    // Bytes held by the sample store (its capacities).
    [[nodiscard]] std::size_t memoryBytes() const
    {
        return m_values.capacity() * sizeof(qint64) + m_bins.capacity() * sizeof(quint64);
    }

private:
    void sortNow() const;
    void binAll();
    [[nodiscard]] static std::size_t binOf(qint64 ns);
    [[nodiscard]] qint64 binMiddle(std::size_t bin) const; // clamped to [min, max]

    mutable std::vector<qint64> m_values;
    mutable std::size_t m_sorted = 0; // m_values[0, m_sorted) is in ascending order
    std::vector<quint64> m_bins;      // binned: samples per bin (binOf)
    std::size_t m_limit = 0;
    bool m_binned = false;
    qint64 m_count = 0;
    qint64 m_min = 0;
    qint64 m_max = 0;
    double m_mean = 0;
    double m_m2 = 0; // Welford: sum of squared distances from the running mean
};

} // namespace mbscope
