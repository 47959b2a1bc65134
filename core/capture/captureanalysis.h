#pragma once

#include "capture/captureexchange.h"
#include "capture/exchangesource.h"
#include "exchange/statistics.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

#include <map>
#include <memory>
#include <vector>

namespace mbscope {

// The figures of a capture or journal read offline: the engine's Statistics over every exchange
// (the same counts, percentiles and histogram a poll prints), and the same per function code and
// per unit id;
// per conversation the transactions, answers and failures; the time the traffic spans.
// Answers that match no request are counted apart, as the engine counts unsolicited frames.
class CaptureAnalysis
{
public:
    explicit CaptureAnalysis(const HistogramSpec &histogram = HistogramSpec::automatic());
    ~CaptureAnalysis();

    void add(const CaptureExchange &exchange);

    [[nodiscard]] const Statistics &statistics() const { return m_overall; }
    [[nodiscard]] quint64 unmatchedResponses() const { return m_unmatched; }
    // Requests the recording ended before the outcome of (CaptureExchange::Kind::Unanswered):
    // in no figure of the statistics, timeouts included.
    [[nodiscard]] quint64 unansweredAtEnd() const { return m_unansweredAtEnd; }
    [[nodiscard]] qint64 firstNs() const { return m_firstNs; }
    [[nodiscard]] qint64 lastNs() const { return m_lastNs; }

    // Statistics::toJson's keys at the top (the shape poll --json prints), then
    // "source": {"path", "format", "complete", "error", "packets", "modbus_packets", "frames",
    //            "requests", "responses", "unmatched_responses", "unanswered_at_end", "malformed_requests",
    //            "retransmitted_bytes", "lost_bytes", "gaps", "joined_mid_stream", "cut_by_gap_bytes",
    //            "skipped_bytes", ...},
    // "span_ms", "conversations": [{"client", "server", "transport", "framing", "requests",
    // "responses", "transactions", "ok", "failed", "unmatched_responses", and for TCP
    // "request_gaps", "request_bytes_lost", "response_gaps", "response_bytes_lost",
    // "joined_mid_stream"}], "functions": [{"function", "name", ...Statistics::toJson's keys}],
    // "units": [{"unit", ...Statistics::toJson's keys}] (the request's unit id, ascending),
    // "legs" (a journal holding both the requests its recorder answered and those it sent: the
    // inline tap's): [{"leg": "answered"|"sent", ...Statistics::toJson's keys}],
    // "problems": [...], "problem_count".
    [[nodiscard]] QJsonObject toJson(const ExchangeSourceReport &report) const;
    // For a terminal: the source, its conversations, a table per function code and one per unit
    // id (and, for the tap's journal, one per leg) (counts; min, mean, median, p95, p99, max latency in one unit, "-" without answers), the
    // statistics as poll prints them, then the problems found.
    [[nodiscard]] QString summary(const ExchangeSourceReport &report) const;

private:
    struct ConversationCounts {
        quint64 transactions = 0;
        quint64 ok = 0;
        quint64 failed = 0;
        quint64 unmatched = 0;
    };

    [[nodiscard]] const Statistics &tableStatistics(const std::unique_ptr<Statistics> &entry) const;

    HistogramSpec m_spec;
    Statistics m_overall;
    // A null entry: the only one of its table, every exchange so far in it: m_overall's figures.
    std::map<quint8, std::unique_ptr<Statistics>> m_byFunction;
    std::map<quint8, std::unique_ptr<Statistics>> m_byUnit; // the request's unit id (RTU/ASCII address, MBAP unit id)
    // Journals: the requests the recorder answered and those it sent. Both only in the inline
    // tap's journal, which then gets a table per leg: masters to the tap, the tap to devices.
    std::unique_ptr<Statistics> m_answered;
    std::unique_ptr<Statistics> m_sent;
    [[nodiscard]] bool hasTwoLegs() const { return m_answered && m_sent; }
    std::vector<ConversationCounts> m_conversations;
    quint64 m_overallAdded = 0; // exchanges in m_overall, Late ones included
    quint64 m_unmatched = 0;
    quint64 m_unansweredAtEnd = 0;
    qint64 m_firstNs = 0;
    qint64 m_lastNs = 0;
};

} // namespace mbscope
