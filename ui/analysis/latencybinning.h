#pragma once

#include "exchange/histogram.h"

#include <QtCore/QList>

#include <span>

namespace mbscope {

// How the analysis panels lay latencies out in bins: equal widths (the engine's automatic 1-2-5
// bins, as `mbscope poll --json` reports them) or logarithmic bins (a constant factor apart, for
// a tail that spans decades). Several runs binned together share one layout, so their bars can be
// compared bin for bin.
class LatencyBinning
{
public:
    enum class Scale : quint8 { Linear, Logarithmic };

    // The most bins a panel shows: enough for a shape, few enough to read; as many as the
    // engine's automatic bins (HistogramSpec::automatic), so linear bins are those of `poll --json`.
    static constexpr int kMaxBins = 50;

    // One histogram of values in ascending order (LatencySamples::sorted()) in the scale's bins,
    // about sqrt(n) of them; no bins when values is empty. Linear bins are those
    // Histogram::autoFixed chooses. Counted by binary search: O(bins x log n), not O(n).
    [[nodiscard]] static Histogram bin(std::span<const qint64> values, Scale scale, int maxBins = kMaxBins);
    // One histogram per ascending list of values, all on the same bins (covering every list's range).
    [[nodiscard]] static QList<Histogram> binCommon(const QList<std::span<const qint64>> &values, Scale scale,
                                                    int maxBins = kMaxBins);
};

} // namespace mbscope
