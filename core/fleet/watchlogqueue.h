#pragma once

#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QMutex>

#include <deque>
#include <optional>

namespace mbscope {

// What the fleet hands the CSV log (WatchLogWriter), waiting for the log's thread: the watches
// started, their samples and rule events, the watches stopped, in the order the fleet emitted
// them. Bounded by the memory its rows hold (an estimate, rowBytes()): when the disk cannot keep
// up with the polls, the samples and events that do not fit are dropped and counted by watch
// (takeDropped()), so memory stays flat however long it lasts. Started and stopped always fit.
//
// Thread-safe: the fleet's thread pushes, the log's thread takes. A push returns true when the
// queue was empty, so the taker needs waking once per run of entries, not once per entry:
//
//   if (queue.pushSamples(samples)) QMetaObject::invokeMethod(writer, &Writer::drain);
//   ... while (std::optional<WatchLogQueue::Entry> e = queue.take()) write(*e);
class WatchLogQueue
{
public:
    // 32 MiB: at 20 watches of 125 registers every 100 ms (about 4 MiB of samples a second) the
    // disk may stall for eight seconds before a row is lost.
    static constexpr qint64 kDefaultCapacityBytes = qint64(32) * 1024 * 1024;

    struct Entry {
        enum class Kind : quint8 { Started, Samples, RuleEvent, Stopped };
        Kind kind = Kind::Samples;
        SessionWatches watches;     // Started
        QList<WatchSample> samples; // Samples
        WatchRuleEvent event;       // RuleEvent
        qint64 bytes = 0;           // held against the capacity until taken
    };

    explicit WatchLogQueue(qint64 capacityBytes = kDefaultCapacityBytes);

    bool pushStarted(const SessionWatches &watches);
    // The samples that fit, in order; from the first that does not, the rest are dropped.
    bool pushSamples(const QList<WatchSample> &samples);
    bool pushEvent(const WatchRuleEvent &event);
    bool pushStopped();

    // The oldest entry, its bytes given back; nullopt when the queue is empty.
    [[nodiscard]] std::optional<Entry> take();
    // Rows dropped since the last call, by watch index (empty when none were).
    [[nodiscard]] QMap<int, quint64> takeDropped();

    [[nodiscard]] qint64 capacityBytes() const { return m_capacity; }
    [[nodiscard]] qsizetype size() const;
    [[nodiscard]] bool isEmpty() const { return size() == 0; }
    // The bytes the entries waiting hold (the estimate).
    [[nodiscard]] qint64 bytes() const;
    // The memory a sample holds while it waits: the struct, its strings, words and values.
    [[nodiscard]] static qint64 rowBytes(const WatchSample &sample);
    [[nodiscard]] static qint64 rowBytes(const WatchRuleEvent &event);

private:
    bool push(Entry entry);

    mutable QMutex m_mutex;
    std::deque<Entry> m_entries;
    qint64 m_capacity;
    qint64 m_bytes = 0;
    QMap<int, quint64> m_dropped;
};

} // namespace mbscope
