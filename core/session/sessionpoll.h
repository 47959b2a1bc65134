#pragma once

#include <QtCore/QList>
#include <QtCore/QStringList>

namespace mbscope {

// A poll as a session saves it: requests of the document's list by name, sent in order, one
// cycle after another (PollSettings says how interval, count and duration combine).
struct SessionPoll {
    QStringList requests;
    qint64 intervalMs = 0;
    quint64 count = 0;      // 0: no count limit
    qint64 durationMs = 0;  // 0: no duration limit

    friend bool operator==(const SessionPoll &, const SessionPoll &) = default;
};

// The same poll run once per interval (SweepSettings).
struct SessionSweep {
    SessionPoll poll; // its intervalMs is not used
    QList<qint64> intervalsMs;

    friend bool operator==(const SessionSweep &, const SessionSweep &) = default;
};

} // namespace mbscope
