#include "watchfleet.h"

#include "fleet/watchlinkpoller.h"

#include <utility>

namespace mbscope {

WatchFleet::WatchFleet(QObject *parent)
    : QObject(parent)
    , m_batchTimer(this) // a child, so that it moves to the runner's thread with the fleet
{
    m_batchTimer.setSingleShot(true);
    connect(&m_batchTimer, &QTimer::timeout, this, &WatchFleet::flush);
}

WatchFleet::~WatchFleet()
{
    qDeleteAll(m_pollers);
}

WatchLinkSettings WatchFleet::linkSettings(const SessionWatches &watches, const QString &target)
{
    for (const WatchLinkSettings &link : watches.links) {
        if (link.target == target)
            return link;
    }
    WatchLinkSettings settings;
    settings.target = target;
    return settings;
}

void WatchFleet::start(const SessionWatches &watches)
{
    stopPollers();
    Q_EMIT started(watches);
    QList<QString> targets;
    QMap<QString, QList<WatchLinkPoller::Watch>> byTarget;
    for (int i = 0; i < watches.watches.size(); ++i) {
        const WatchDefinition &w = watches.watches.at(i);
        if (!w.enabled)
            continue;
        if (!byTarget.contains(w.target))
            targets.append(w.target);
        byTarget[w.target].append(WatchLinkPoller::Watch{i, w});
    }
    for (const QString &target : std::as_const(targets)) {
        auto *poller = new WatchLinkPoller(linkSettings(watches, target), byTarget.value(target), this);
        connect(poller, &WatchLinkPoller::sampled, this, &WatchFleet::onSampled);
        // Events go out after the samples before them, so that observers see them in order.
        connect(poller, &WatchLinkPoller::ruleChanged, this, [this](const WatchRuleEvent &event) {
            flush();
            Q_EMIT ruleChanged(event);
        });
        connect(poller, &WatchLinkPoller::linkStateChanged, this, [this](const WatchLinkState &state) {
            flush();
            Q_EMIT linkStateChanged(state);
        });
        connect(poller, &WatchLinkPoller::writeFinished, this, &WatchFleet::writeFinished);
        connect(poller, &WatchLinkPoller::framesLogged, this, &WatchFleet::framesLogged);
        poller->setTrafficLog(m_log);
        poller->setFramesPublished(m_framesPublished);
        m_pollers.append(poller);
        for (const WatchLinkPoller::Watch &w : byTarget.value(target))
            m_pollerOfWatch.insert(w.index, poller);
    }
    for (WatchLinkPoller *poller : std::as_const(m_pollers))
        poller->start();
}

void WatchFleet::stop()
{
    stopPollers();
    Q_EMIT stopped();
}

void WatchFleet::stopPollers()
{
    for (WatchLinkPoller *poller : std::as_const(m_pollers))
        poller->stop();
    flush();
    qDeleteAll(m_pollers);
    m_pollers.clear();
    m_pollerOfWatch.clear();
}

void WatchFleet::setTrafficLog(TrafficLog *log)
{
    m_log = log;
    for (WatchLinkPoller *poller : std::as_const(m_pollers))
        poller->setTrafficLog(log);
}

void WatchFleet::write(quint64 id, int watch, quint16 address, const QList<quint16> &words)
{
    WatchLinkPoller *poller = m_pollerOfWatch.value(watch);
    if (!poller) {
        Q_EMIT writeFinished(id, watch, address, false, QStringLiteral("watch %1 is not running").arg(watch));
        return;
    }
    poller->write(id, watch, address, words);
}

void WatchFleet::onSampled(const WatchSample &sample, const WatchCounters &counters)
{
    m_samples.append(sample);
    m_counters.insert(counters.watch, counters);
    if (!m_batchTimer.isActive())
        m_batchTimer.start(m_batchIntervalMs);
}

void WatchFleet::flush()
{
    m_batchTimer.stop();
    if (m_samples.isEmpty())
        return;
    Q_EMIT sampled(std::exchange(m_samples, {}), m_counters.values());
    m_counters.clear();
}

} // namespace mbscope

#include "moc_watchfleet.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
