#pragma once

#include "metricsregistry.h"

namespace mbscope {

// The process_* metrics every Prometheus client library exports (resident and virtual memory, CPU
// seconds, start time, open file descriptors), read from /proc/self on Linux when a scrape asks,
// so that "memory flat over millions of polls" can be watched by the same Prometheus. Elsewhere
// the families exist with no series.
class ProcessMetrics
{
public:
    explicit ProcessMetrics(MetricsRegistry &registry);

    void update();

private:
    MetricFamily &m_resident;
    MetricFamily &m_virtual;
    MetricFamily &m_cpu;
    MetricFamily &m_start;
    MetricFamily &m_fds;
};

} // namespace mbscope
