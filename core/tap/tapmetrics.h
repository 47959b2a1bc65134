#pragma once

#include "tapsettings.h"

#include "metrics/metricsregistry.h"

#include <QtCore/QString>

namespace mbscope {

// What the inline tap tells Prometheus (`mbscope tap --metrics ADDRESS`), in Prometheus's
// conventions (mbscope_ prefix, seconds, counters ending in _total):
//
//   mbscope_tap_requests_total         counter    requests taken from masters, by outcome: answered,
//                                                 exception (the device's), no_answer, link_error,
//                                                 damaged, broadcast, no_route, refused (read-only)
//   mbscope_tap_waiting                gauge      requests waiting for a device (queued or in flight)
//   mbscope_tap_device_latency_seconds histogram  request sent to the device until its answer was in,
//                                                 by target: the device's own time
//   mbscope_tap_answer_seconds         histogram  a master's request in until its answer left the tap
//                                                 (before any delay a fault rule adds), by target
//   mbscope_build_info                 gauge      the version, as a label
class TapMetrics
{
public:
    explicit TapMetrics(const QString &version);

    [[nodiscard]] const MetricsRegistry &registry() const { return m_registry; }

    // The counters and the queue as they are now (before each scrape).
    void update(const TapCounters &counters, int waiting);
    // One forwarded request answered by its device.
    void observe(const QString &target, qint64 deviceNs, qint64 answerNs);

private:
    MetricsRegistry m_registry;
    MetricFamily &m_requests;
    MetricFamily &m_waiting;
    MetricFamily &m_deviceLatency;
    MetricFamily &m_answer;
};

} // namespace mbscope
