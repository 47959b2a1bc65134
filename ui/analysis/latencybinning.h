#pragma once

#include "exchange/histogram.h"
#include "exchange/latencysamples.h"

#include <QtCore/QList>


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

    // One histogram of a store's latencies in the scale's bins, about sqrt(n) of them; no bins
    // when it is empty. Linear bins are those Histogram::autoFixed chooses. Counted with
    // Histogram::addSamples: O(bins x log n) while the store keeps every sample, O(bins x its
    // bins) once it has binned them (LatencySamples::setExactLimit), never O(n).
    [[nodiscard]] static Histogram bin(const LatencySamples &values, Scale scale, int maxBins = kMaxBins);
    // One histogram per store, all on the same bins (covering every store's range).
    [[nodiscard]] static QList<Histogram> binCommon(const QList<const LatencySamples *> &values, Scale scale,
                                                    int maxBins = kMaxBins);
};

} // namespace mbscope
