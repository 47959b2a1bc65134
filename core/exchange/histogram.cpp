#include "histogram.h"

#include <QtCore/QJsonArray>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mbscope {

namespace {

// The largest number of bins a layout may have: a histogram is for looking at, and a runaway
// width (1 ns over an hour) must not allocate gigabytes.
constexpr qint64 kMaxBins = 100000;

} // namespace

HistogramSpec HistogramSpec::automatic(int maxBins)
{
    HistogramSpec spec;
    spec.maxBins = maxBins;
    return spec;
}

HistogramSpec HistogramSpec::fixed(qint64 widthNs, qint64 lowNs, qint64 highNs)
{
    HistogramSpec spec;
    spec.kind = Kind::Fixed;
    spec.widthNs = widthNs;
    spec.lowNs = lowNs;
    spec.highNs = highNs;
    return spec;
}

HistogramSpec HistogramSpec::logarithmic(int binsPerDecade, qint64 lowNs, qint64 highNs)
{
    HistogramSpec spec;
    spec.kind = Kind::Logarithmic;
    spec.binsPerDecade = binsPerDecade;
    spec.lowNs = lowNs;
    spec.highNs = highNs;
    return spec;
}

Histogram Histogram::fixed(qint64 widthNs, qint64 lowNs, qint64 highNs)
{
    Histogram h;
    if (widthNs <= 0 || highNs <= lowNs)
        return h;
    // (high - low) cannot overflow for the latencies this is for; guard anyway.
    if (lowNs < 0 && highNs > std::numeric_limits<qint64>::max() + lowNs)
        return h;
    const qint64 span = highNs - lowNs;
    const qint64 bins = span / widthNs + (span % widthNs != 0 ? 1 : 0);
    if (bins > kMaxBins)
        return h;
    h.m_lowNs = lowNs;
    h.m_widthNs = widthNs;
    h.m_edges.reserve(std::size_t(bins + 1));
    for (qint64 i = 0; i < bins; ++i)
        h.m_edges.push_back(double(lowNs + i * widthNs));
    h.m_edges.push_back(double(highNs));
    h.m_counts.assign(std::size_t(bins), 0);
    return h;
}

Histogram Histogram::logarithmic(int binsPerDecade, qint64 lowNs, qint64 highNs)
{
    Histogram h;
    if (binsPerDecade <= 0 || lowNs <= 0 || highNs <= lowNs)
        return h;
    const double b = binsPerDecade;
    const double decades = std::log10(double(highNs) / double(lowNs));
    // A relative tolerance, so that 10^(k/b) computed a hair below highNs does not add a bin.
    const auto bins = qint64(std::ceil(decades * b - 1e-9));
    if (bins > kMaxBins)
        return h;
    h.m_log = true;
    h.m_lowNs = lowNs;
    h.m_binsPerDecade = b;
    h.m_edges.reserve(std::size_t(bins + 1));
    for (qint64 i = 0; i <= bins; ++i)
        h.m_edges.push_back(double(lowNs) * std::pow(10.0, double(i) / b));
    h.m_edges.front() = double(lowNs);
    h.m_counts.assign(std::size_t(bins), 0);
    return h;
}

namespace {

// The 1-2-5 layout autoFixed chooses for count values from minNs to maxNs.
Histogram autoLayout(qint64 minNs, qint64 maxNs, qint64 count, int maxBins)
{
    const auto target = std::clamp<qint64>(qint64(std::ceil(std::sqrt(double(count)))), 1, std::max(1, maxBins));
    // Widths 1, 2, 5 x 10^k ns, never narrower than 1 us (the unit the edges are shown in).
    const auto floorDiv = [](qint64 a, qint64 w) { return a >= 0 ? a / w : -((-a + w - 1) / w); };
    qint64 width = 1000;
    for (int step = 0;; ++step) {
        const qint64 bins = floorDiv(maxNs, width) - floorDiv(minNs, width) + 1;
        if (bins <= target || width > std::numeric_limits<qint64>::max() / 10)
            break;
        width = (step % 3 == 1) ? width / 2 * 5 : width * 2; // 1 -> 2 -> 5 -> 10 ...
    }
    const qint64 low = floorDiv(minNs, width) * width;
    const qint64 bins = floorDiv(maxNs, width) - floorDiv(minNs, width) + 1;
    return Histogram::fixed(width, low, low + bins * width);
}

} // namespace

Histogram Histogram::autoFixed(std::span<const qint64> values, int maxBins)
{
    if (values.empty())
        return {};
    const auto [minIt, maxIt] = std::minmax_element(values.begin(), values.end());
    Histogram h = autoLayout(*minIt, *maxIt, qint64(values.size()), maxBins);
    for (const qint64 v : values)
        h.add(v);
    return h;
}

Histogram Histogram::autoFixed(const LatencySamples &samples, int maxBins)
{
    if (samples.isEmpty())
        return {};
    Histogram h = autoLayout(samples.minNs(), samples.maxNs(), samples.count(), maxBins);
    h.addSamples(samples);
    return h;
}

Histogram Histogram::fromSpec(const HistogramSpec &spec)
{
    switch (spec.kind) {
    case HistogramSpec::Kind::Fixed:
        return fixed(spec.widthNs, spec.lowNs, spec.highNs);
    case HistogramSpec::Kind::Logarithmic:
        return logarithmic(spec.binsPerDecade, spec.lowNs, spec.highNs);
    case HistogramSpec::Kind::Auto:
        break;
    }
    return {};
}

int Histogram::binOf(qint64 valueNs) const
{
    const int n = binCount();
    if (n == 0)
        return 0;
    const double v = double(valueNs);
    if (v < m_edges.front())
        return -1;
    if (v >= m_edges.back())
        return n;
    if (!m_log) {
        const qint64 bin = (valueNs - m_lowNs) / m_widthNs;
        return int(std::min<qint64>(bin, n - 1));
    }
    // A binary search over the edges: a few comparisons, where a logarithm (and the correction
    // of its rounding at the edges) cost about ten times as much per value.
    const auto above = std::upper_bound(m_edges.begin(), m_edges.end(), v);
    return std::clamp(int(above - m_edges.begin()) - 1, 0, n - 1);
}

void Histogram::add(qint64 valueNs)
{
    ++m_total;
    const int bin = binOf(valueNs);
    if (bin < 0)
        ++m_underflow;
    else if (bin >= binCount())
        ++m_overflow;
    else
        ++m_counts[std::size_t(bin)];
}

void Histogram::addSorted(std::span<const qint64> ascending)
{
    m_total += ascending.size();
    if (m_counts.empty()) {
        m_overflow += ascending.size();
        return;
    }
    // The first value at or above an edge: bins are [edge, next edge), as in binOf().
    const auto from = [&ascending](auto begin, double edge) {
        return std::lower_bound(begin, ascending.end(), edge, [](qint64 v, double e) { return double(v) < e; });
    };
    auto start = from(ascending.begin(), m_edges.front());
    m_underflow += quint64(start - ascending.begin());
    for (std::size_t bin = 0; bin < m_counts.size(); ++bin) {
        const auto end = from(start, m_edges[bin + 1]);
        m_counts[bin] += quint64(end - start);
        start = end;
    }
    m_overflow += quint64(ascending.end() - start);
}

void Histogram::addSamples(const LatencySamples &samples)
{
    const auto n = quint64(samples.count());
    m_total += n;
    if (m_counts.empty()) {
        m_overflow += n;
        return;
    }
    auto below = quint64(samples.countBelow(m_edges.front()));
    m_underflow += below;
    for (std::size_t bin = 0; bin < m_counts.size(); ++bin) {
        const auto next = quint64(samples.countBelow(m_edges[bin + 1]));
        m_counts[bin] += next - below;
        below = next;
    }
    m_overflow += n - below;
}

void Histogram::clear()
{
    std::fill(m_counts.begin(), m_counts.end(), 0);
    m_underflow = m_overflow = m_total = 0;
}

QJsonObject Histogram::toJson() const
{
    QJsonArray edges;
    for (const double e : m_edges)
        edges.append(e / 1000.0);
    QJsonArray counts;
    for (const quint64 c : m_counts)
        counts.append(double(c));
    return QJsonObject{
        {QStringLiteral("bin_edges_us"), edges},
        {QStringLiteral("counts"), counts},
        {QStringLiteral("underflow"), double(m_underflow)},
        {QStringLiteral("overflow"), double(m_overflow)},
    };
}

} // namespace mbscope
