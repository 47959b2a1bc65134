#pragma once

#include "engine/histogram.h"

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

    // The most bins a panel shows: enough for a shape, few enough to read.
    static constexpr int kMaxBins = 60;

    // One histogram of values (ascending or not) in the scale's bins; no bins when values is empty.
    [[nodiscard]] static Histogram bin(std::span<const qint64> values, Scale scale, int maxBins = kMaxBins);
    // One histogram per list of values, all on the same bins (covering every list's range).
    [[nodiscard]] static QList<Histogram> binCommon(const QList<std::span<const qint64>> &values, Scale scale,
                                                    int maxBins = kMaxBins);
};

} // namespace mbscope
