#pragma once

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope {
class BusMonitor;
struct CaptureExchange;
}

namespace mbscope::app {

// Why a monitor stopped.
enum class MonitorStop { Count, Duration, Interrupted, LinkLost };

// What monitor prints: one line per exchange as it is seen, and the statistics when it stops.
class MonitorReport
{
public:
    // "   12  unit 1   0x03 Read Holding Registers        ok           3.201 ms" and the problem, if any.
    [[nodiscard]] static QString exchangeLine(const CaptureExchange &exchange);
    // The heading, what the bus carried (frames, requests, answers, CRC errors...), then the
    // statistics as poll prints them, then the first problems.
    [[nodiscard]] static QString text(const BusMonitor &monitor, qint64 elapsedNs, MonitorStop stop);
    // Statistics::toJson's keys at the top (poll --json's shape), then "target", "elapsed_ms",
    // "stopped" ("count", "duration", "interrupted", "link_lost"), "interrupted",
    // "bus": {"bytes", "frames", "requests", "responses", "crc_errors", "truncated", "malformed",
    // "skipped_bytes", "skipped_runs", "unmatched_responses", "late_responses", "silence_us"},
    // "problems", "problem_count".
    [[nodiscard]] static QJsonObject json(const BusMonitor &monitor, qint64 elapsedNs, MonitorStop stop);
    // 0 every exchange ok and no damaged frame, 1 otherwise, 3 not one byte heard (2, a lost link, is the caller's).
    [[nodiscard]] static int exitStatus(const BusMonitor &monitor);
};

} // namespace mbscope::app
