#pragma once

#include <QtCore/QMetaType>
#include <QtCore/QtGlobal>

namespace mbscope {

// Where a scan stands: steps done of a known total, and an estimate of the time left from the
// average step so far (before the first step: every step taking its whole timeout).
struct ScanProgress {
    int done = 0;
    int total = 0;
    int found = 0;           // unit scan: ids with a device behind them
    qint64 elapsedMs = 0;
    qint64 remainingMs = 0;  // estimate

    [[nodiscard]] int percent() const { return total > 0 ? int(qint64(done) * 100 / total) : 0; }
};

// Why a scan ended.
enum class ScanEnd : quint8 {
    Completed, // every step done
    Stopped,   // stop() (Ctrl-C, the Stop button)
    TimeLimit, // the scan's time limit passed first
    LinkError, // the link failed: nothing more can be learnt through it
    RequestLimit, // the scan's request limit was reached first
};

[[nodiscard]] const char *scanEndName(ScanEnd end); // "completed", "stopped", "time_limit", "link_error", "request_limit"

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::ScanProgress)
