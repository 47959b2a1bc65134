#pragma once

#include "histogram.h"
#include "latencysamples.h"
#include "transaction.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

#include <array>

namespace mbscope {

// The unit latencies read best in for a terminal: the typical one (a median) decides, so a run
// around 7 ms with one 300 ms outlier still reads in ms. µs under 1 ms, ms under 10 s, else s.
struct LatencyUnit {
    const char *name;
    double ns;    // nanoseconds in one unit
    int decimals; // shown after the point
    [[nodiscard]] static LatencyUnit forTypical(qint64 typicalNs);
    [[nodiscard]] QString format(double valueNs) const;
};

// The figures of a run of transactions (one request item's, or all of them), fed one Transaction
// at a time in O(1) (amortized: the latency store is a growing vector, or fixed bins once past
// setExactLatencyLimit()).
//
// What is counted:
// - count: every transaction except Late records (a late answer belongs to a request already
//   counted, as a timeout), so count = ok + broadcasts + failed().
// - failed(): exceptions + timeouts + crc errors + malformed + unexpected + link errors.
// - latency: doneNs - sentNs of the answered transactions, Ok and Exception (the device answered
//   this request); a timeout has no latency, a late answer's is past its timeout and would only
//   stretch the tail, a CRC error or malformed answer may not be the answer at all.
// - what each latency is measured from: the write (network links, and serial answers that
//   outran the line) or the computed end of the request's transmission (serial); outranLine()
//   counts the serial answers that came before the line could have carried them (Transaction).
// - the histogram counts the same latencies: O(1) per transaction with fixed or logarithmic bins;
//   with HistogramSpec::Auto the bins are fitted to the stored latencies when asked.
// Not thread-safe, const queries included (percentiles sort the stored latencies in place): the
// engine's thread owns it; others get a copy.
class Statistics
{
public:
    explicit Statistics(const HistogramSpec &histogram = HistogramSpec::automatic());

    void add(const Transaction &transaction);
    void clear();

    [[nodiscard]] quint64 count() const { return m_count; }
    [[nodiscard]] quint64 ok() const { return m_ok; }
    [[nodiscard]] quint64 exceptions() const { return m_exceptions; }
    [[nodiscard]] quint64 exceptions(quint8 code) const { return m_exceptionsByCode[code]; }
    [[nodiscard]] quint64 timeouts() const { return m_timeouts; }
    [[nodiscard]] quint64 crcErrors() const { return m_crcErrors; }
    [[nodiscard]] quint64 malformed() const { return m_malformed; }
    [[nodiscard]] quint64 unexpected() const { return m_unexpected; }
    [[nodiscard]] quint64 late() const { return m_late; }
    [[nodiscard]] quint64 linkErrors() const { return m_linkErrors; }
    [[nodiscard]] quint64 broadcasts() const { return m_broadcasts; }
    [[nodiscard]] quint64 failed() const;
    // failed() / (count() - broadcasts()): the share of requests that wanted an answer and did
    // not get a good one. 0 when there were none.
    [[nodiscard]] double errorRate() const;

    // Answered transactions by what their latency is measured from, and those that outran
    // their serial line (measured from the write for that reason).
    [[nodiscard]] quint64 measuredFromWrite() const { return m_fromWrite; }
    [[nodiscard]] quint64 measuredFromLineEnd() const { return m_fromLineEnd; }
    [[nodiscard]] quint64 outranLine() const { return m_outranLine; }
    // A listen-only tap (the bus monitor) writes nothing: its latencies run from the request's
    // last byte as it read it off the line, which latencyOrigin() and "latency_from"
    // ("request_last_byte") then say. Kept by clear().
    void setMeasuredOnTheLine(bool onTheLine) { m_onTheLine = onTheLine; }
    [[nodiscard]] bool isMeasuredOnTheLine() const { return m_onTheLine; }
    // "the write" / "the computed end of transmission" / both, for the output; empty without answers.
    [[nodiscard]] QString latencyOrigin() const;
    // The warning when answers outran their line; empty when none did.
    [[nodiscard]] QString outranLineWarning() const;

    [[nodiscard]] const LatencySamples &latency() const { return m_latency; }
    // Latencies past limit are binned (LatencySamples::setExactLimit); 0, the default: all kept.
    void setExactLatencyLimit(std::size_t limit) { m_latency.setExactLimit(limit); } // kept by clear()
    [[nodiscard]] const HistogramSpec &histogramSpec() const { return m_spec; }
    // The latency histogram: the one kept up to date, or for Auto one fitted to the latencies now.
    [[nodiscard]] Histogram histogram() const;

    // {"count","ok","exceptions","timeouts","crc_errors","malformed","late","link_errors",
    //  "unexpected","broadcasts","exceptions_by_code":{"0x02":n,...},
    //  "latency_us":{"count","min","mean","median","p90","p95","p99","max","stddev"},
    //  "latency_from":"write"|"line_end"|"mixed"|"request_last_byte" (absent without answers),"outran_line":n,
    //  "histogram":{"bin_edges_us","counts","underflow","overflow"}}
    // Latency figures are microseconds (ns / 1000, not rounded); null when nothing was answered.
    [[nodiscard]] QJsonObject toJson() const;

    // Aligned lines for a terminal, one counter a line, then the latency in a unit that suits it:
    //   transactions  100  ok 97 (97.0 %)  failed 3
    //   exceptions      1  0x02 Illegal Data Address: 1
    //   ...
    //   latency ms    min 5.663  mean 7.249  median 7.100  p90 9.001 ... max 13.771  stddev 1.234
    [[nodiscard]] QString summary() const;
    // The same for a recording, whose times were taken elsewhere than a live run's: the "latency
    // from" line names these two points ("the capture time of the request's packet", "...") in
    // place of the live ones (an engine's journal keeps an answer's first byte, not its last).
    [[nodiscard]] QString summary(const QString &latencyFrom, const QString &latencyTo) const;

private:
    HistogramSpec m_spec;
    Histogram m_histogram; // Fixed and Logarithmic specs: kept up to date in add()
    LatencySamples m_latency;
    quint64 m_count = 0;
    quint64 m_ok = 0;
    quint64 m_exceptions = 0;
    quint64 m_timeouts = 0;
    quint64 m_crcErrors = 0;
    quint64 m_malformed = 0;
    quint64 m_unexpected = 0;
    quint64 m_late = 0;
    quint64 m_linkErrors = 0;
    quint64 m_broadcasts = 0;
    quint64 m_fromWrite = 0;
    quint64 m_fromLineEnd = 0;
    quint64 m_outranLine = 0;
    bool m_onTheLine = false;
    std::array<quint64, 256> m_exceptionsByCode{};
};

} // namespace mbscope
