#pragma once

#include "poll/pollrunner.h"
#include "poll/polloptions.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope::app {

// What poll and sweep print when they end, and their exit status.
class PollResults
{
public:
    PollResults(const PollConfig &config, const PollOutcome &outcome) : m_config(config), m_outcome(outcome) {}

    // poll: the heading, cycles, the statistics (each request's too when there are several);
    // with --stats the engine's counters and the histogram as text.
    [[nodiscard]] QString pollText() const;
    // Statistics::toJson's keys ({"count","ok",...,"latency_us":{...},"histogram":{...}}) at the
    // top, with "items" per request when there are several, and "target", "requests",
    // "interval_ms", "cycles", "overruns", "elapsed_ms", "stopped", "interrupted", "engine".
    [[nodiscard]] QJsonObject pollJson() const;

    // sweep: one row per interval: cycles, transactions, ok, failed, error rate, latency min,
    // mean, p50, p99, max; with --stats each interval's statistics below.
    [[nodiscard]] QString sweepText() const;
    // {"target", "requests", "count", "duration_ms", "stopped", "interrupted",
    //  "runs": [{"interval_ms", "cycles", "overruns", "elapsed_ms", "stopped", "error_rate",
    //            ...Statistics::toJson's keys}]}
    [[nodiscard]] QJsonObject sweepJson() const;

    // The --histogram PNG: one series for a poll, one per interval on common bins for a sweep.
    [[nodiscard]] bool writeHistogram(QString *error) const;

    // 0 every transaction ok, 1 some failed, 2 the link never worked.
    [[nodiscard]] int exitStatus() const;

private:
    [[nodiscard]] QString heading(const char *what) const;
    // The device's pace the engine kept, each with where it came from: "gap 51 ms between
    // requests (minGapMs 50 of --profile slow.json, 1 ms to spare), ..."; empty when none.
    [[nodiscard]] QString paceText() const;
    [[nodiscard]] QJsonObject paceJson() const;
    [[nodiscard]] QString detail(const PollRun &run) const;
    [[nodiscard]] QJsonObject runJson(const PollRun &run) const;

    const PollConfig &m_config;
    const PollOutcome &m_outcome;
};

} // namespace mbscope::app
