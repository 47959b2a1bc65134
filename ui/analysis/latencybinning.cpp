#include "latencybinning.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mbscope {

namespace {

// The empty layout for the range [minNs, maxNs] holding about target bins.
Histogram layout(qint64 minNs, qint64 maxNs, qint64 total, LatencyBinning::Scale scale, int maxBins)
{
    const auto target = std::clamp<qint64>(qint64(std::ceil(std::sqrt(double(total)))), 1, std::max(1, maxBins));
    if (scale == LatencyBinning::Scale::Logarithmic) {
        // Logarithmic bins need a positive start; the last edge lies above the largest value
        // (bins are [edge, next edge)). Bins per decade so the range gets about target bins.
        const qint64 low = std::max<qint64>(1, minNs);
        const qint64 high = std::max<qint64>(low + 1, maxNs + 1);
        const double decades = std::max(std::log10(double(high) / double(low)), 1e-3);
        const int perDecade = std::clamp(int(std::ceil(double(target) / decades)), 1, 1000);
        return Histogram::logarithmic(perDecade, low, high);
    }
    // Widths 1, 2, 5 x 10^k ns, never narrower than 1 us, about sqrt(n) bins: the layout
    // Histogram::autoFixed chooses for n values (what `poll --json` reports), found from the range
    // alone so that the samples can be counted with Histogram::addSamples.
    qint64 width = 1000;
    for (int step = 0;; ++step) {
        const qint64 bins = maxNs / width - minNs / width + 1;
        if (bins <= target || width > std::numeric_limits<qint64>::max() / 10)
            break;
        width = (step % 3 == 1) ? width / 2 * 5 : width * 2; // 1 -> 2 -> 5 -> 10 ...
    }
    const qint64 low = minNs / width * width;
    const qint64 bins = maxNs / width - minNs / width + 1;
    return Histogram::fixed(width, low, low + bins * width);
}

} // namespace

Histogram LatencyBinning::bin(const LatencySamples &values, Scale scale, int maxBins)
{
    return binCommon({&values}, scale, maxBins).constFirst();
}

QList<Histogram> LatencyBinning::binCommon(const QList<const LatencySamples *> &values, Scale scale, int maxBins)
{
    qint64 minNs = std::numeric_limits<qint64>::max();
    qint64 maxNs = std::numeric_limits<qint64>::min();
    qint64 total = 0;
    for (const LatencySamples *one : values) {
        if (one->isEmpty())
            continue;
        minNs = std::min(minNs, one->minNs());
        maxNs = std::max(maxNs, one->maxNs());
        total += one->count();
    }
    QList<Histogram> histograms;
    // Latencies are never negative; clamping keeps the integer bin arithmetic simple.
    const Histogram empty = total == 0 ? Histogram() : layout(std::max<qint64>(0, minNs), std::max<qint64>(0, maxNs), total, scale, maxBins);
    for (const LatencySamples *one : values) {
        Histogram h = empty;
        h.addSamples(*one);
        histograms.append(h);
    }
    return histograms;
}

} // namespace mbscope
