#include "watchrunner.h"

#include "fleet/watchfleet.h"

namespace mbscope {

WatchRunner::WatchRunner(const SessionWatches &watches, QObject *parent)
    : QObject(parent)
    , m_watches(watches)
    , m_fleet(new WatchFleet)
{
    qRegisterMetaType<mbscope::WatchSample>();
    qRegisterMetaType<QList<mbscope::WatchSample>>();
    qRegisterMetaType<mbscope::WatchCounters>();
    qRegisterMetaType<QList<mbscope::WatchCounters>>();
    qRegisterMetaType<mbscope::WatchRuleEvent>();
    qRegisterMetaType<mbscope::WatchLinkState>();
    resetCounters();
    m_thread.setObjectName(QStringLiteral("mbscope watches"));
    m_fleet->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_fleet, &QObject::deleteLater);
    connect(m_fleet, &WatchFleet::sampled, this, &WatchRunner::onSampled);
    connect(m_fleet, &WatchFleet::ruleChanged, this, &WatchRunner::ruleChanged);
    connect(m_fleet, &WatchFleet::linkStateChanged, this, &WatchRunner::linkStateChanged);
    connect(m_fleet, &WatchFleet::writeFinished, this, &WatchRunner::writeFinished);
    connect(m_fleet, &WatchFleet::stopped, this, [this] {
        if (!m_running)
            Q_EMIT stopped();
    });
    m_thread.start();
}

WatchRunner::~WatchRunner()
{
    QMetaObject::invokeMethod(m_fleet, [fleet = m_fleet] {
        disconnect(fleet, nullptr, nullptr, nullptr);
        fleet->stop();
    }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void WatchRunner::resetCounters()
{
    m_counters.clear();
    for (int i = 0; i < m_watches.watches.size(); ++i) {
        WatchCounters c;
        c.watch = i;
        c.watchName = m_watches.watches.at(i).name;
        m_counters.append(c);
    }
}

void WatchRunner::setWatches(const SessionWatches &watches)
{
    const bool wasRunning = m_running;
    if (wasRunning)
        stop();
    m_watches = watches;
    resetCounters();
    if (wasRunning)
        start();
}

void WatchRunner::start()
{
    m_running = true;
    resetCounters();
    QMetaObject::invokeMethod(m_fleet, [fleet = m_fleet, watches = m_watches] { fleet->start(watches); },
                              Qt::QueuedConnection);
}

void WatchRunner::stop()
{
    m_running = false;
    QMetaObject::invokeMethod(m_fleet, [fleet = m_fleet] { fleet->stop(); }, Qt::QueuedConnection);
}

quint64 WatchRunner::write(int watch, quint16 address, const QList<quint16> &words)
{
    const quint64 id = ++m_nextWriteId;
    QMetaObject::invokeMethod(m_fleet, [fleet = m_fleet, id, watch, address, words] { fleet->write(id, watch, address, words); },
                              Qt::QueuedConnection);
    return id;
}

WatchCounters WatchRunner::counters(int watch) const
{
    return watch >= 0 && watch < m_counters.size() ? m_counters.at(watch) : WatchCounters{};
}

void WatchRunner::onSampled(const QList<WatchSample> &samples, const QList<WatchCounters> &counters)
{
    for (const WatchCounters &c : counters) {
        if (c.watch >= 0 && c.watch < m_counters.size())
            m_counters[c.watch] = c;
    }
    Q_EMIT sampled(samples, counters);
}

} // namespace mbscope
