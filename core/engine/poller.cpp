#include "poller.h"

#include "enginecore.h"

#include "transport/monotonicclock.h"

#include <algorithm>

namespace mbscope {

Poller::Poller(EngineCore *core, const PollSettings &settings, quint64 tag, QObject *parent)
    : QObject(parent)
    , m_core(core)
    , m_settings(settings)
    , m_tag(tag)
    , m_timer(this)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, [this] { advance(false); });
    m_core->recorder()->addRecordListener(this);
    m_listenedTo = m_core->recorder();
    m_run.intervalNs = settings.intervalNs;
    QStringList names;
    for (const RequestItem &item : settings.items)
        names.append(item.name);
    m_run.statistics.setItemNames(names);
    m_run.statistics.setExactLatencyLimit(settings.exactLatencyLimit);
}

Poller::~Poller()
{
    if (m_listenedTo)
        m_listenedTo->removeRecordListener(this);
}

void Poller::start()
{
    if (m_started)
        return;
    m_started = true;
    m_startNs = monotonicNowNs();
    m_nextDueNs = m_startNs;
    m_countersAtStart = m_core->counters();
    EngineProgress &p = m_core->progressState();
    p.polling = true;
    p.intervalNs = m_settings.intervalNs;
    p.cyclesPlanned = m_settings.count;
    p.durationNs = m_settings.durationNs;
    p.cycle = 0;
    p.ok = 0;
    p.failed = 0;
    if (m_settings.items.isEmpty()) {
        finish();
        return;
    }
    advance(false);
}

void Poller::stop()
{
    if (!m_started || m_finished)
        return;
    m_run.stopped = true;
    m_core->cancel(m_tag);
    finish();
}

bool Poller::moreCycles(qint64 nowNs) const
{
    if (m_settings.count > 0 && m_run.cycles >= m_settings.count)
        return false;
    if (m_settings.durationNs > 0 && nowNs - m_startNs >= m_settings.durationNs)
        return false;
    return true;
}

bool Poller::hasRoom() const
{
    return m_core->outstanding(m_tag) < m_core->pipelineDepth();
}

void Poller::advance(bool fromRecord)
{
    while (!m_finished) {
        const qint64 now = monotonicNowNs();
        if (!moreCycles(now)) {
            m_timer.stop();
            // The poll's time is up before the device's pace let the latest cycle's first request
            // out: that cycle never began (a cycle begins when its first request is written).
            const bool timeUp = m_settings.durationNs > 0 && now - m_startNs >= m_settings.durationNs;
            if (timeUp && m_run.cycles > 0 && m_core->isQueued(m_cycleFirstId)) {
                m_core->dropQueued(m_tag);
                --m_run.cycles;
                --m_core->counters().cycles;
            }
            if (m_core->outstanding(m_tag) == 0)
                finish();
            else if (m_settings.durationNs > 0 && m_settings.count == 0)
                updateProgress(now);
            return;
        }
        if (now < m_nextDueNs) {
            qint64 wakeNs = m_nextDueNs;
            if (m_settings.durationNs > 0)
                wakeNs = qMin(wakeNs, m_startNs + m_settings.durationNs);
            m_timer.start(int((wakeNs - now + 999999) / 1000000));
            return;
        }
        if (!hasRoom()) {
            // The next record calls again; and the end of the poll's time, should the device's
            // pace hold a request past it.
            if (m_settings.durationNs > 0 && !m_timer.isActive())
                m_timer.start(int(std::max<qint64>(0, m_startNs + m_settings.durationNs - now + 999999) / 1000000));
            return;
        }
        // Started by the end of the cycle before rather than by its own due time: that cycle
        // took longer than the interval.
        const bool late = fromRecord && m_settings.intervalNs > 0 && m_run.cycles > 0;
        if (late)
            countOverrun();
        m_cycleDueNs = m_nextDueNs;
        m_cycleOverrun = late;
        startCycle(now);
        // Loop: arm the timer for the next due time, or (back to back, pipelined) start
        // another cycle while the pipeline has room.
        fromRecord = false;
    }
}

void Poller::startCycle(qint64 nowNs)
{
    ++m_run.cycles;
    ++m_core->counters().cycles;
    m_nextDueNs = nowNs + m_settings.intervalNs;
    updateProgress(nowNs);
    for (qsizetype i = 0; i < m_settings.items.size(); ++i) {
        if (m_finished)
            return;
        const quint64 id = m_core->reserveId();
        if (i == 0)
            m_cycleFirstId = id;
        m_core->submit(m_settings.items.at(i), id, int(i), m_tag);
    }
}

void Poller::onRecord(const Transaction &transaction, quint64 tag)
{
    if (tag != m_tag || !m_started || m_finished)
        return;
    m_run.statistics.add(transaction);
    // The cycle actually began when its first request was written: a link still opening held it
    // (the second cycle followed the first by the interval less the opening time).
    if (transaction.id == m_cycleFirstId && transaction.attempt == 0 && transaction.writeNs > 0) {
        m_nextDueNs = std::max(m_nextDueNs, transaction.writeNs + m_settings.intervalNs);
        // Held past its due time by the device's pace (EngineOptions::requestGap, warmUp): the
        // interval asked for was not kept, which is what an overrun says. (The first cycle waits
        // for the link to open, as every poll's does.)
        const EngineOptions &o = m_core->options();
        const bool paced = o.requestGap.count() > 0 || o.warmUp.count() > 0;
        const qint64 slackNs = std::max<qint64>(1'000'000, m_settings.intervalNs / 20);
        if (paced && !m_cycleOverrun && m_run.cycles > 1 && m_settings.intervalNs > 0
            && transaction.writeNs - m_cycleDueNs > slackNs) {
            m_cycleOverrun = true;
            countOverrun();
        }
    }
    updateProgress(monotonicNowNs());
    advance(true);
}

void Poller::countOverrun()
{
    ++m_run.overruns;
    ++m_core->counters().overruns;
}

void Poller::updateProgress(qint64 nowNs)
{
    EngineProgress &p = m_core->progressState();
    p.cycle = m_run.cycles;
    p.elapsedNs = nowNs - m_startNs;
    p.ok = m_run.statistics.overall().ok();
    p.failed = m_run.statistics.overall().failed();
    m_core->recorder()->scheduleBatch();
}

void Poller::finish()
{
    if (m_finished)
        return;
    m_finished = true;
    m_timer.stop();
    const qint64 now = monotonicNowNs();
    m_run.elapsedNs = m_started ? now - m_startNs : 0;
    m_run.counters = m_core->counters() - m_countersAtStart;
    updateProgress(now);
    Q_EMIT finished();
}

} // namespace mbscope

#include "moc_poller.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
