#pragma once

#include "fleet/watchcounters.h"
#include "fleet/watchlinkstate.h"
#include "fleet/watchsample.h"
#include "exchange/trafficentry.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QThread>

#include <optional>

namespace mbscope {

class TrafficLog;
class WatchFleet;
class WatchLogWriter;

// Runs a session's watches: an engine per distinct link URL, the watches of one link taking turns
// in order with the link's gap between requests, each at its own interval; reconnects after a
// link error with a backoff (WatchLinkSettings), counted. One link's dead device never stalls
// another link, and on one link a timeout costs only its own turn (WatchLinkPoller).
//
// The pollers and engines live in threads of their own; every public method posts its work and
// returns at once, so the GUI thread never waits on a device. Observers receive, in the thread
// that owns the runner: samples in batches (at most ~30 a second) with the counters of the
// watches they concern, rule events and link states as they happen, and write results.
//
// The CSV log (setLog) is written in a third thread (WatchLogWriter): samples and rule events go
// there straight from the pollers' thread, never through the runner's, so a window that logs
// does not wait on the disk. Its files open when the watches start and close before stopped().
// What waits for the disk is bounded (WatchLogQueue): a disk slower than the polls costs rows,
// said by logDropping() and logCaughtUp() and counted by logDroppedRows(), never memory.
//
//   WatchRunner runner(session.watches);
//   connect(&runner, &WatchRunner::sampled, ...);
//   runner.setLog(session.watches.log, sessionFolder);
//   runner.start();            // ... runner.stop(); stopped() follows once every link is closed
class WatchRunner : public QObject
{
    Q_OBJECT
public:
    explicit WatchRunner(const SessionWatches &watches, QObject *parent = nullptr);
    ~WatchRunner() override;

    [[nodiscard]] const SessionWatches &watches() const { return m_watches; }
    // Replaces the watches; running ones are stopped and the new ones started (counters anew).
    void setWatches(const SessionWatches &watches);

    void start();
    // Stops every link (requests in flight abandoned); the last samples, then stopped(), follow.
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }

    // Logs the watches to CSV as settings say while they run (nullopt or not enabled: no log); a
    // relative folder is baseDirectory's. May be called running or not; logOpened() or
    // logFailed() says how it went.
    void setLog(const std::optional<WatchLogSettings> &settings, const QString &baseDirectory = {});

    // Every frame in and out of every link goes to log (a command's --record, the window's
    // recording), each link's engine on a link id of its own, from now on: the log must be
    // shared (TrafficLog::setShared). setTrafficLog(nullptr) returns once no engine writes it
    // any more; until then log must live.
    void setTrafficLog(TrafficLog *log);
    // framesLogged() on or off (off by default: the copies cost a list entry per frame), from
    // the next start().
    void setFramesPublished(bool published);

    // Writes words to a point marked writable of a watch (holding registers: 06 or 10, the
    // point's registers in wire order; coils: 05, one word 0 or 1), before that link's next poll.
    // Returns an id that writeFinished() carries; a refused write is said there too.
    quint64 write(int watch, quint16 address, const QList<quint16> &words);

    // The counters last received for a watch (index in watches()), zero before its first poll.
    [[nodiscard]] WatchCounters counters(int watch) const;
    [[nodiscard]] QList<WatchCounters> allCounters() const { return m_counters; }

Q_SIGNALS:
    // The polls since the last batch, in the order they ended, and the counters of their watches.
    void sampled(const QList<mbscope::WatchSample> &samples, const QList<mbscope::WatchCounters> &counters);
    void ruleChanged(const mbscope::WatchRuleEvent &event);
    void linkStateChanged(const mbscope::WatchLinkState &state);
    void writeFinished(quint64 id, int watch, quint16 address, bool ok, const QString &message);
    // The CSV log: its files opened in directory; a file or row that cannot be written (said once
    // until writing works again); the files closed (the watches stopped or changed, or setLog),
    // with the files written and the rows lost.
    void logOpened(const QString &directory);
    void logFailed(const QString &message);
    // The log fell behind the polls and drops rows (said once), until it caught up (or closed):
    // the rows dropped meanwhile; and the rows of a watch dropped since the watches started.
    void logDropping(const QString &message);
    void logCaughtUp(quint64 rows, const QString &message);
    void logDroppedRows(int watch, quint64 rows);
    // lostRows: every row not written; droppedRows: those of them dropped while it fell behind.
    void logClosed(const QString &directory, const QStringList &files, quint64 lostRows, quint64 droppedRows);
    // With setFramesPublished(true): every frame of a link as its engine logs it
    // (TransactionEngine::framesLogged), link its URL.
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    // After stop(): every link closed, the last samples handed out and the CSV files closed.
    void stopped();

private:
    void onSampled(const QList<WatchSample> &samples, const QList<WatchCounters> &counters);
    void resetCounters();

    SessionWatches m_watches;
    QList<WatchCounters> m_counters;
    QThread m_thread;
    WatchFleet *m_fleet; // lives in m_thread
    QThread m_logThread;
    WatchLogWriter *m_writer; // lives in m_logThread
    bool m_running = false;
    quint64 m_nextWriteId = 0;
};

} // namespace mbscope
