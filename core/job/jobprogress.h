#pragma once

#include <QtCore/QMetaType>
#include <QtCore/QtGlobal>

namespace mbscope {

// Where a job stands (a scan, a sampling run): steps done of a known total, what it found so far,
// the time since it began and an estimate of the time left (each job estimates its own: from the
// average step so far, before the first step every step taking its whole timeout). Sent from the
// job's thread to whoever shows it, by value.
struct JobProgress {
    int done = 0;
    int total = 0;
    int found = 0;           // what the job found so far (unit scan: ids with a device behind them)
    qint64 elapsedMs = 0;
    qint64 remainingMs = 0;  // estimate

    // done of total as 0..1 (0 while the total is unknown).
    [[nodiscard]] double fraction() const { return total > 0 ? qBound(0.0, double(done) / double(total), 1.0) : 0.0; }
    [[nodiscard]] int percent() const { return total > 0 ? int(qint64(done) * 100 / total) : 0; }
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::JobProgress)
