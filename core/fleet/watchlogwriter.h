#pragma once

#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QSet>
#include <QtCore/QStringList>

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
// A failure (disk full, a folder that cannot be made) is said once by failed() while any watch's
// writes fail, and again only after every failing watch has written again; the rows lost are counted and said by closed().
class WatchLogWriter : public QObject
{
    Q_OBJECT
public:
    explicit WatchLogWriter(QObject *parent = nullptr);
    ~WatchLogWriter() override;

    // Logging as settings say (nullopt or not enabled: off); a relative folder is baseDirectory's.
    // The same settings again change nothing; other settings close the files and open new ones.
    void configure(const std::optional<mbscope::WatchLogSettings> &settings, const QString &baseDirectory);
    // The fleet started these watches (or changed to them).
    void watchesStarted(const mbscope::SessionWatches &watches);
    void append(const QList<mbscope::WatchSample> &samples);
    void appendEvent(const mbscope::WatchRuleEvent &event);
    // The fleet stopped: the files close, then drained().
    void watchesStopped();

Q_SIGNALS:
    void opened(const QString &directory);
    void failed(const QString &message);
    // Files written, oldest first; rows that could not be written.
    void closed(const QString &directory, const QStringList &files, quint64 lostRows);
    void drained();

private:
    void open();
    void close();
    void said(int watch, bool ok, const QString &error);

    std::optional<WatchLogSettings> m_settings;
    QString m_base;
    SessionWatches m_watches;
    bool m_running = false;
    QSet<int> m_failing; // watches whose last write failed
    std::unique_ptr<WatchCsvLog> m_log;
};

} // namespace mbscope
