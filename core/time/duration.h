#pragma once

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringView>

namespace mbscope {

// One grammar for every duration a person types: on the command line (--interval 100ms), in a
// target URL (timeout=1.5s, turnaround=500us), in a session's poll bounds ("p95 < 20 ms") and a
// plan's wait ("2 s"). A number (digits with at most one decimal point: no sign, no exponent) and
// an optional unit: ns, us (or µs), ms, s, min (or m), h, case-insensitive, a space between them
// tolerated. A bare number is in the caller's unit (milliseconds everywhere mbscope takes one),
// or refused when the caller requires a unit. At most a year.
struct Duration {
    static constexpr qint64 Nanosecond = 1;
    static constexpr qint64 Microsecond = 1000;
    static constexpr qint64 Millisecond = 1'000'000;
    static constexpr qint64 Second = 1'000'000'000;
    static constexpr qint64 Minute = 60 * Second;
    static constexpr qint64 Hour = 60 * Minute;
    static constexpr qint64 Year = 366 * 24 * Hour;
    // bareUnitNs for texts that must carry a unit.
    static constexpr qint64 UnitRequired = 0;
};

struct DurationResult {
    enum class Problem : quint8 { None, Syntax, Negative, UnitMissing, TooLong };
    qint64 ns = 0;
    Problem problem = Problem::Syntax;
    QString error; // "'10 parsecs' is not a duration: ..."; empty when ok

    [[nodiscard]] bool ok() const { return problem == Problem::None; }
};

struct DurationListResult {
    QList<qint64> ns;
    QString error; // names the item at fault
    bool ok = false;
};

[[nodiscard]] DurationResult parseDuration(QStringView text, qint64 bareUnitNs = Duration::Millisecond);
// A comma-separated list ("100,200,300ms,1s"): each item as parseDuration.
[[nodiscard]] DurationListResult parseDurationList(QStringView text, qint64 bareUnitNs = Duration::Millisecond);
// What parseDuration accepts, said for an error message.
[[nodiscard]] QString durationGrammar(qint64 bareUnitNs = Duration::Millisecond);

// For people: "0 ms", "100 ms", "1.5 s", "250 µs", "2 min": the largest unit that keeps the
// value at or above 1, with at most three decimals and no trailing zeros.
[[nodiscard]] QString formatDuration(qint64 ns);

} // namespace mbscope
