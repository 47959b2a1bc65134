#include "watchcounters.h"

namespace mbscope {

qint64 WatchCounters::latencyBucketLimitNs(int bucket)
{
    // 1, 2, 5 steps from 1 ms to 10 s: 13 limits, then the open bucket.
    static constexpr qint64 kLimitsUs[] = {1000, 2000, 5000, 10000, 20000, 50000, 100000, 200000,
                                           500000, 1000000, 2000000, 5000000, 10000000};
    if (bucket < 0 || bucket >= int(std::size(kLimitsUs)))
        return -1;
    return kLimitsUs[bucket] * 1000;
}

void WatchCounters::addLatency(qint64 ns)
{
    if (ns < 0)
        return;
    if (latencyBuckets.size() != latencyBucketCount())
        latencyBuckets = QList<quint64>(latencyBucketCount(), 0);
    int bucket = 0;
    while (bucket < latencyBucketCount() - 1 && ns >= latencyBucketLimitNs(bucket))
        ++bucket;
    ++latencyBuckets[bucket];
    lastLatencyNs = ns;
    if (latencyCount == 0 || ns < minLatencyNs)
        minLatencyNs = ns;
    if (ns > maxLatencyNs)
        maxLatencyNs = ns;
    ++latencyCount;
    meanLatencyNs += (double(ns) - meanLatencyNs) / double(latencyCount);
}

} // namespace mbscope
