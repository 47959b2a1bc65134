#pragma once

#include "fleet/watchlogqueue.h"
#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QSet>
#include <QtCore/QStringList>

#include <atomic>
#include <memory>
#include <optional>

namespace mbscope {

class WatchCsvLog;

// The CSV log of a WatchRunner (core/watch's WatchCsvLog), in a thread of its own so that neither
// the GUI thread nor the pollers' wait on the disk. It follows the runner's fleet: the files open
// when the watches start (and open anew when they change), take every sample and rule event in
// the order the fleet emitted them, and close once the fleet has stopped and its last samples are
// written. configure() turns logging on, off or elsewhere at any time, running or not.
//
// What the fleet hands over waits in a bounded queue (WatchLogQueue, offer*() from the fleet's
// thread). When the disk, or the writing, cannot keep up with the polls, the rows that do not fit
// are dropped, not held: memory stays flat. That is said once while it lasts (dropping()), in the
// events file of each watch that lost rows (an "overflow" row when it starts, a "dropped" row with
// the count when the log caught up or closed: caughtUp()), and counted by watch (droppedRows()).
//
// A failure (disk full, a folder that cannot be made) is said once by failed() while any watch's
// writes fail, and again only after every failing watch has written again; the rows lost are counted and said by closed().
class WatchLogWriter : public QObject
{
    Q_OBJECT
public:
    explicit WatchLogWriter(qint64 queueBytes = WatchLogQueue::kDefaultCapacityBytes, QObject *parent = nullptr);
    ~WatchLogWriter() override;

    // Thread-safe, for the fleet's thread: queued, and written in the writer's thread in this order.
    // The fleet started these watches (or changed to them).
    void offerStarted(const mbscope::SessionWatches &watches);
    // Samples and events are dropped at once (not queued) while logging is off.
    void offerSamples(const QList<mbscope::WatchSample> &samples);
    void offerEvent(const mbscope::WatchRuleEvent &event);
    // The fleet stopped: the files close, then drained().
    void offerStopped();

    // In the writer's thread. Logging as settings say (nullopt or not enabled: off); a relative
    // folder is baseDirectory's. The same settings again change nothing; other settings close the
    // files and open new ones. What was queued before is written first.
    void configure(const std::optional<mbscope::WatchLogSettings> &settings, const QString &baseDirectory);
    // Writes what the queue holds now (in the writer's thread; offer*() has it done).
    void drain();

    [[nodiscard]] const WatchLogQueue &queue() const { return m_queue; }

Q_SIGNALS:
    void opened(const QString &directory);
    void failed(const QString &message);
    // The log fell behind the polls and rows are being dropped; said once until caughtUp().
    void dropping(const QString &message);
    // It caught up (or its files closed while it was behind): rows dropped meanwhile, and a line saying so.
    void caughtUp(quint64 rows, const QString &message);
    // The rows of a watch (index) dropped since the watches started, when that grows.
    void droppedRows(int watch, quint64 rows);
    // Files written, oldest first; rows that could not be written, of them dropped ones.
    void closed(const QString &directory, const QStringList &files, quint64 lostRows, quint64 droppedRows);
    void drained();

private:
    void watchesStarted(const SessionWatches &watches);
    void append(const QList<WatchSample> &samples);
    void appendEvent(const WatchRuleEvent &event);
    void watchesStopped();
    void onQueued();
    // Writes up to entries entries; true when the queue is then empty.
    bool write(qsizetype entries);
    void takeDrops();
    void endDropping(const QString &why);
    void open();
    void close();
    void said(int watch, bool ok, const QString &error);
    void wake();

    WatchLogQueue m_queue;
    std::atomic<bool> m_logging{false}; // read by offer*() in the fleet's thread
    std::optional<WatchLogSettings> m_settings;
    QString m_base;
    SessionWatches m_watches;
    bool m_running = false;
    QSet<int> m_failing; // watches whose last write failed
    std::unique_ptr<WatchCsvLog> m_log;
    // Dropped rows: by watch since the watches started; in the current shortfall, by watch; since
    // the files opened.
    QMap<int, quint64> m_dropped;
    QMap<int, quint64> m_droppingNow;
    qint64 m_droppingSinceMs = 0;
    quint64 m_droppedSinceOpen = 0;
};

} // namespace mbscope
