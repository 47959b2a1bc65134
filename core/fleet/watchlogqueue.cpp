#include "watchlogqueue.h"

#include <QtCore/QMutexLocker>

#include <utility>

namespace mbscope {

namespace {

qint64 stringBytes(const QString &s)
{
    // A string's characters live in a block of their own (shared strings counted as if not:
    // an estimate that errs on the side of memory).
    return s.isEmpty() ? 0 : 32 + 2 * qint64(s.size());
}

} // namespace

WatchLogQueue::WatchLogQueue(qint64 capacityBytes)
    : m_capacity(capacityBytes)
{
}

qint64 WatchLogQueue::rowBytes(const WatchSample &sample)
{
    qint64 bytes = qint64(sizeof(WatchSample)) + stringBytes(sample.watchName) + stringBytes(sample.error)
        + 2 * qint64(sample.words.size()) + qint64(sample.bits.size());
    for (const WatchPointValue &v : sample.values) {
        bytes += qint64(sizeof(WatchPointValue)) + stringBytes(v.name) + stringBytes(v.unit) + stringBytes(v.text);
        for (const WatchBitFieldValue &f : v.bitFields)
            bytes += qint64(sizeof(WatchBitFieldValue)) + stringBytes(f.name) + stringBytes(f.state);
    }
    return bytes;
}

qint64 WatchLogQueue::rowBytes(const WatchRuleEvent &event)
{
    return qint64(sizeof(WatchRuleEvent)) + stringBytes(event.watchName) + stringBytes(event.colour) + stringBytes(event.point)
        + stringBytes(event.message);
}

bool WatchLogQueue::push(Entry entry)
{
    QMutexLocker lock(&m_mutex);
    const bool wasEmpty = m_entries.empty();
    m_bytes += entry.bytes;
    m_entries.push_back(std::move(entry));
    return wasEmpty;
}

bool WatchLogQueue::pushStarted(const SessionWatches &watches)
{
    Entry e;
    e.kind = Entry::Kind::Started;
    e.watches = watches;
    return push(std::move(e));
}

bool WatchLogQueue::pushStopped()
{
    Entry e;
    e.kind = Entry::Kind::Stopped;
    return push(std::move(e));
}

bool WatchLogQueue::pushSamples(const QList<WatchSample> &samples)
{
    // The sizes are reckoned outside the lock; the lock only decides what fits.
    QList<qint64> sizes;
    sizes.reserve(samples.size());
    for (const WatchSample &s : samples)
        sizes.append(rowBytes(s));
    QMutexLocker lock(&m_mutex);
    qsizetype fit = 0;
    qint64 bytes = 0;
    while (fit < samples.size() && m_bytes + bytes + sizes.at(fit) <= m_capacity) {
        bytes += sizes.at(fit);
        ++fit;
    }
    for (qsizetype i = fit; i < samples.size(); ++i)
        ++m_dropped[samples.at(i).watch];
    if (fit == 0)
        return false;
    const bool wasEmpty = m_entries.empty();
    Entry e;
    e.kind = Entry::Kind::Samples;
    e.samples = fit == samples.size() ? samples : samples.first(fit);
    e.bytes = bytes;
    m_bytes += bytes;
    m_entries.push_back(std::move(e));
    return wasEmpty;
}

bool WatchLogQueue::pushEvent(const WatchRuleEvent &event)
{
    const qint64 bytes = rowBytes(event);
    QMutexLocker lock(&m_mutex);
    if (m_bytes + bytes > m_capacity) {
        ++m_dropped[event.watch];
        return false;
    }
    const bool wasEmpty = m_entries.empty();
    Entry e;
    e.kind = Entry::Kind::RuleEvent;
    e.event = event;
    e.bytes = bytes;
    m_bytes += bytes;
    m_entries.push_back(std::move(e));
    return wasEmpty;
}

std::optional<WatchLogQueue::Entry> WatchLogQueue::take()
{
    QMutexLocker lock(&m_mutex);
    if (m_entries.empty())
        return std::nullopt;
    Entry e = std::move(m_entries.front());
    m_entries.pop_front();
    m_bytes -= e.bytes;
    return e;
}

QMap<int, quint64> WatchLogQueue::takeDropped()
{
    QMutexLocker lock(&m_mutex);
    return std::exchange(m_dropped, {});
}

qsizetype WatchLogQueue::size() const
{
    QMutexLocker lock(&m_mutex);
    return qsizetype(m_entries.size());
}

qint64 WatchLogQueue::bytes() const
{
    QMutexLocker lock(&m_mutex);
    return m_bytes;
}

} // namespace mbscope
