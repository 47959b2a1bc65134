#include "watchrunner.h"

#include "fleet/watchfleet.h"
#include "fleet/watchlogwriter.h"

namespace mbscope {

WatchRunner::WatchRunner(const SessionWatches &watches, QObject *parent)
    : QObject(parent)
    , m_watches(watches)
    , m_fleet(new WatchFleet)
    , m_writer(new WatchLogWriter)
{
    qRegisterMetaType<mbscope::WatchSample>();
    qRegisterMetaType<QList<mbscope::WatchSample>>();
    qRegisterMetaType<mbscope::WatchCounters>();
    qRegisterMetaType<QList<mbscope::WatchCounters>>();
    qRegisterMetaType<mbscope::WatchRuleEvent>();
    qRegisterMetaType<mbscope::WatchLinkState>();
    qRegisterMetaType<mbscope::SessionWatches>();
    resetCounters();
    m_thread.setObjectName(QStringLiteral("mbscope watches"));
    m_fleet->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_fleet, &QObject::deleteLater);
    connect(m_fleet, &WatchFleet::sampled, this, &WatchRunner::onSampled);
    connect(m_fleet, &WatchFleet::ruleChanged, this, &WatchRunner::ruleChanged);
    connect(m_fleet, &WatchFleet::linkStateChanged, this, &WatchRunner::linkStateChanged);
    connect(m_fleet, &WatchFleet::writeFinished, this, &WatchRunner::writeFinished);
    connect(m_fleet, &WatchFleet::framesLogged, this, &WatchRunner::framesLogged);
    // The log takes what the fleet emits in the fleet's thread, in its order; stopped() waits for
    // its files to close.
    m_logThread.setObjectName(QStringLiteral("mbscope watch log"));
    m_writer->moveToThread(&m_logThread);
    connect(&m_logThread, &QThread::finished, m_writer, &QObject::deleteLater);
    // Direct: called in the fleet's thread, they queue for the log's thread in a bounded queue
    // of their own (WatchLogQueue), not in its event queue, which a slow disk would let grow.
    connect(m_fleet, &WatchFleet::started, m_writer, &WatchLogWriter::offerStarted, Qt::DirectConnection);
    connect(m_fleet, &WatchFleet::sampled, m_writer, &WatchLogWriter::offerSamples, Qt::DirectConnection);
    connect(m_fleet, &WatchFleet::ruleChanged, m_writer, &WatchLogWriter::offerEvent, Qt::DirectConnection);
    connect(m_fleet, &WatchFleet::stopped, m_writer, &WatchLogWriter::offerStopped, Qt::DirectConnection);
    connect(m_writer, &WatchLogWriter::opened, this, &WatchRunner::logOpened);
    connect(m_writer, &WatchLogWriter::failed, this, &WatchRunner::logFailed);
    connect(m_writer, &WatchLogWriter::dropping, this, &WatchRunner::logDropping);
    connect(m_writer, &WatchLogWriter::caughtUp, this, &WatchRunner::logCaughtUp);
    connect(m_writer, &WatchLogWriter::droppedRows, this, &WatchRunner::logDroppedRows);
    connect(m_writer, &WatchLogWriter::closed, this, &WatchRunner::logClosed);
    connect(m_writer, &WatchLogWriter::drained, this, [this] {
        if (!m_running)
            Q_EMIT stopped();
    });
    m_logThread.start();
    m_thread.start();
}

WatchRunner::~WatchRunner()
{
    // Nothing more reaches this runner; the log still takes the fleet's last samples.
    disconnect(m_fleet, nullptr, this, nullptr);
    disconnect(m_writer, nullptr, this, nullptr);
    QMetaObject::invokeMethod(m_fleet, [fleet = m_fleet] { fleet->stop(); }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
    // Queued after the fleet's last samples and its stop: written, then the files closed.
    QMetaObject::invokeMethod(m_writer, [writer = m_writer] { writer->configure(std::nullopt, QString()); },
                              Qt::BlockingQueuedConnection);
    m_logThread.quit();
    m_logThread.wait();
}

void WatchRunner::setLog(const std::optional<WatchLogSettings> &settings, const QString &baseDirectory)
{
    QMetaObject::invokeMethod(m_writer, [writer = m_writer, settings, baseDirectory] { writer->configure(settings, baseDirectory); },
                              Qt::QueuedConnection);
}

void WatchRunner::setTrafficLog(TrafficLog *log)
{
    QMetaObject::invokeMethod(m_fleet, [fleet = m_fleet, log] { fleet->setTrafficLog(log); }, Qt::BlockingQueuedConnection);
}

void WatchRunner::setFramesPublished(bool published)
{
    QMetaObject::invokeMethod(m_fleet, [fleet = m_fleet, published] { fleet->setFramesPublished(published); },
                              Qt::QueuedConnection);
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

#include "moc_watchrunner.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
