#pragma once

#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>

namespace mbscope {

class Statistics;

// A bound a poll's statistics must keep, written as people write it: "p95 < 20 ms",
// "timeouts == 0", "error_rate <= 1 %", "mean < 5ms", "ok >= 100".
//
// Figures: the counters of Statistics (count, ok, failed, exceptions, timeouts, crc_errors,
// malformed, unexpected, late, link_errors, broadcasts), error_rate (a percentage; "%" is
// optional), and the latency of answered requests: min, max, mean, median, stddev and
// percentiles p0-p100 (p95, p99.9), nearest rank as Statistics computes them. A latency needs a
// unit: ns, us (or µs), ms or s. Comparisons: <, <=, >, >=, ==, !=.
struct PollBound {
    enum class Op : quint8 { Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual };
    enum class Kind : quint8 { Counter, Rate, Latency };

    QString text;      // as written
    QString figure;    // "p95"
    Kind kind = Kind::Counter;
    double percentile = 0; // pNN only
    Op op = Op::Less;
    double value = 0;  // counters: a count; rate: a percentage; latency: nanoseconds

    struct Parsed;
    [[nodiscard]] static Parsed parse(QStringView text);

    // The figure in stats (latency in ns, rate in percent); nullopt when there is none (no
    // latency without an answered request).
    [[nodiscard]] std::optional<double> measure(const Statistics &stats) const;
    [[nodiscard]] bool holds(double measured) const;
    // "p95 is 4.213 ms", "timeouts is 3", "p95: no request was answered"
    [[nodiscard]] QString describe(const Statistics &stats) const;

    friend bool operator==(const PollBound &, const PollBound &) = default;
};

struct PollBound::Parsed {
    std::optional<PollBound> bound;
    QString error; // "'p95 < 20': a latency needs a unit after 20: ns, us, ms or s"
};

} // namespace mbscope
