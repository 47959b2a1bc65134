#pragma once

#include "latencysamples.h"

#include <QtCore/QJsonObject>
#include <QtCore/QtGlobal>

#include <span>
#include <vector>

namespace mbscope {

// How a histogram's bins are laid out. Values are nanoseconds (latencies from the monotonic
// clock); edges are shown in microseconds in JSON.
struct HistogramSpec {
    enum class Kind : quint8 {
        Auto,        // fixed-width bins chosen from the data when asked (see Histogram::autoFixed)
        Fixed,       // bins of widthNs from lowNs up to highNs
        Logarithmic, // binsPerDecade bins per factor of ten from lowNs up to highNs
    };
    Kind kind = Kind::Auto;
    qint64 widthNs = 0;
    qint64 lowNs = 0;
    qint64 highNs = 0;
    int binsPerDecade = 0;
    int maxBins = 50; // Auto: the most bins it may choose

    [[nodiscard]] static HistogramSpec automatic(int maxBins = 50);
    [[nodiscard]] static HistogramSpec fixed(qint64 widthNs, qint64 lowNs, qint64 highNs);
    [[nodiscard]] static HistogramSpec logarithmic(int binsPerDecade, qint64 lowNs, qint64 highNs);
};

// Counts of values in bins [edge[i], edge[i+1]); values below the first edge are underflow, at or
// above the last edge overflow, so every value added is counted exactly once. add() is O(1):
// fixed bins by integer division, logarithmic bins by a logarithm corrected against the stored
// edges (so a value exactly on an edge always lands in the bin that starts there).
class Histogram
{
public:
    Histogram() = default; // no bins: every value is overflow

    // Bins of widthNs covering [lowNs, highNs); the last bin is cut short at highNs when the
    // range is not a whole number of widths. Invalid arguments (width <= 0, high <= low) give a
    // histogram with no bins; isValid() says so.
    [[nodiscard]] static Histogram fixed(qint64 widthNs, qint64 lowNs, qint64 highNs);
    // binsPerDecade bins per factor of ten starting at lowNs (> 0): edge i is lowNs * 10^(i/b),
    // up to the first edge at or above highNs.
    [[nodiscard]] static Histogram logarithmic(int binsPerDecade, qint64 lowNs, qint64 highNs);
    // Fixed bins fitted to the values: a 1-2-5 width (1 ns, 2 ns, 5 ns, 10 ns ... ) giving at most
    // maxBins bins (fewer for few values: about sqrt(n)), edges on multiples of the width, the
    // values added. Empty values give a histogram with no bins.
    [[nodiscard]] static Histogram autoFixed(std::span<const qint64> values, int maxBins = 50);
    // The same bins for a store of latencies (binned or not: see LatencySamples), counted with
    // addSamples().
    [[nodiscard]] static Histogram autoFixed(const LatencySamples &samples, int maxBins = 50);
    // The layout a spec names (Auto gives no bins: use autoFixed with the data).
    [[nodiscard]] static Histogram fromSpec(const HistogramSpec &spec);

    void add(qint64 valueNs);
    // Adds values given in ascending order (LatencySamples::sorted()): the same counts as add()
    // for each, found with a binary search per edge, so rebinning a million stored latencies
    // costs O(bins x log n) instead of a bin lookup per value.
    void addSorted(std::span<const qint64> ascending);
    // Adds a store's samples: the same counts as addSorted(samples.sorted()) while it keeps every
    // sample, and from its bins once it no longer does (LatencySamples::countBelow per edge).
    void addSamples(const LatencySamples &samples);
    void clear(); // counts to zero, bins kept

    [[nodiscard]] bool isValid() const { return !m_counts.empty(); }
    [[nodiscard]] bool isLogarithmic() const { return m_log; }
    [[nodiscard]] int binCount() const { return int(m_counts.size()); }
    // binCount() + 1 edges, in nanoseconds (logarithmic edges are not whole nanoseconds).
    [[nodiscard]] const std::vector<double> &edgesNs() const { return m_edges; }
    [[nodiscard]] const std::vector<quint64> &counts() const { return m_counts; }
    [[nodiscard]] quint64 count(int bin) const { return m_counts.at(std::size_t(bin)); }
    [[nodiscard]] quint64 underflow() const { return m_underflow; }
    [[nodiscard]] quint64 overflow() const { return m_overflow; }
    [[nodiscard]] quint64 total() const { return m_total; }
    // The bin a value falls in, -1 for underflow, binCount() for overflow.
    [[nodiscard]] int binOf(qint64 valueNs) const;

    // {"bin_edges_us": [...], "counts": [...], "underflow": n, "overflow": n}
    [[nodiscard]] QJsonObject toJson() const;

private:
    std::vector<double> m_edges;
    std::vector<quint64> m_counts;
    quint64 m_underflow = 0;
    quint64 m_overflow = 0;
    quint64 m_total = 0;
    bool m_log = false;
    qint64 m_lowNs = 0;   // fixed: first edge
    qint64 m_widthNs = 0; // fixed: bin width
    double m_binsPerDecade = 0;
};

} // namespace mbscope
