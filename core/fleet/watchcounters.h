#pragma once

#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

// What happened to one watch since the runner started it.
struct WatchCounters {
    int watch = -1;
    QString watchName;
    quint64 polls = 0;        // requests answered or failed (every WatchSample)
    quint64 ok = 0;
    quint64 exceptions = 0;   // all codes
    QMap<int, quint64> exceptionsByCode;
    quint64 timeouts = 0;
    quint64 crcErrors = 0;
    quint64 otherErrors = 0;  // malformed or unexpected answers
    quint64 linkErrors = 0;   // polls lost to the link (refused, closed, I/O error)
    quint64 reconnects = 0;   // of the watch's link: times it opened again after it was lost
    quint64 ruleFirings = 0;  // rules of this watch that fired
    quint64 overruns = 0;     // polls that started later than their interval asked (the link was busy)
    QString lastError;
    qint64 lastErrorMs = 0;   // ms since the epoch, UTC; 0: never
    qint64 lastOkMs = 0;      // the last good answer; 0: never
    qint64 lastLatencyNs = -1;
    qint64 minLatencyNs = 0;  // over the answered polls (ok and exceptions)
    qint64 maxLatencyNs = 0;
    double meanLatencyNs = 0;
    quint64 latencyCount = 0;
    // Answered polls by latency: bucket i counts latencies below latencyBucketLimitNs(i), the
    // last bucket the rest. Limits 1, 2, 5 ms, 10, 20, 50 ms ... 10 s.
    QList<quint64> latencyBuckets;

    [[nodiscard]] static int latencyBucketCount() { return 14; }
    [[nodiscard]] static qint64 latencyBucketLimitNs(int bucket); // -1 for the last (no limit)
    void addLatency(qint64 ns);
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::WatchCounters)
