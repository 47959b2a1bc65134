#pragma once

#include "fleet/watchcounters.h"
#include "fleet/watchlinkstate.h"
#include "fleet/watchsample.h"
#include "exchange/trafficentry.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QTimer>

namespace mbscope {

class TrafficLog;
class WatchLinkPoller;

// The runner's side in its own thread: a WatchLinkPoller per distinct link URL, and the batching
// of their samples (at most one batch every batchIntervalMs) for observers in other threads.
class WatchFleet : public QObject
{
    Q_OBJECT
public:
    explicit WatchFleet(QObject *parent = nullptr);
    ~WatchFleet() override;

    void start(const mbscope::SessionWatches &watches);
    void stop();
    void write(quint64 id, int watch, quint16 address, const QList<quint16> &words);
    // Every link's frames to log (WatchRunner::setTrafficLog); framesLogged() on or off.
    void setTrafficLog(TrafficLog *log);
    void setFramesPublished(bool published) { m_framesPublished = published; }

    // The settings of a link: its entry in SessionWatches::links, else the defaults.
    [[nodiscard]] static WatchLinkSettings linkSettings(const SessionWatches &watches, const QString &target);

Q_SIGNALS:
    // The watches of start(), before their first sample.
    void started(const mbscope::SessionWatches &watches);
    void sampled(const QList<mbscope::WatchSample> &samples, const QList<mbscope::WatchCounters> &counters);
    void ruleChanged(const mbscope::WatchRuleEvent &event);
    void linkStateChanged(const mbscope::WatchLinkState &state);
    void writeFinished(quint64 id, int watch, quint16 address, bool ok, const QString &message);
    void framesLogged(const QList<mbscope::TrafficFrame> &frames, const QString &link);
    void stopped();

private:
    void stopPollers();
    void onSampled(const WatchSample &sample, const WatchCounters &counters);
    void flush();

    QList<WatchLinkPoller *> m_pollers;
    QMap<int, WatchLinkPoller *> m_pollerOfWatch;
    QList<WatchSample> m_samples;
    QMap<int, WatchCounters> m_counters; // changed since the last batch
    QTimer m_batchTimer;
    int m_batchIntervalMs = 33;
    TrafficLog *m_log = nullptr;
    bool m_framesPublished = false;
};

} // namespace mbscope
