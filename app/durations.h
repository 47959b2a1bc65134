#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringView>

namespace mbscope::app {

struct DurationResult {
    qint64 ns = 0;
    QString error; // "'10 parsecs' is not a duration: ..."; empty when ok
    bool ok = false;
};

struct DurationListResult {
    QList<qint64> ns;
    QString error;
    bool ok = false;
};

// Durations as people type them on a command line: "100ms", "1s", "60s", "1.5s", "250us",
// "2min", "0". A bare number is milliseconds (as in target URLs: timeout=1000). Units: ns, us
// (or µs), ms, s, min, h, case-insensitive; a decimal fraction is allowed ("0.5ms"); a space
// between number and unit is tolerated. Negative values and values beyond a year are refused.
[[nodiscard]] DurationResult parseDuration(QStringView text);
// A comma-separated list ("100,200,300ms,1s"): each item as parseDuration; the error names the item.
[[nodiscard]] DurationListResult parseDurationList(QStringView text);

// For people: "0 ms", "100 ms", "1.5 s", "250 µs", "2 min": the largest unit that keeps the
// value at or above 1, with at most three decimals and no trailing zeros.
[[nodiscard]] QString formatDuration(qint64 ns);

} // namespace mbscope::app
