#include "sweep.h"

#include "enginecore.h"
#include "poller.h"

namespace mbscope {

Sweep::Sweep(EngineCore *core, const SweepSettings &settings, bool isSweep, QObject *parent)
    : QObject(parent)
    , m_core(core)
    , m_settings(settings)
{
    m_report.sweep = isSweep;
}

Sweep::~Sweep()
{
    if (m_poller && !m_poller->isFinished())
        m_poller->stop();
}

void Sweep::start()
{
    m_next = 0;
    startRun();
}

void Sweep::stop()
{
    if (m_finished)
        return;
    m_stopping = true;
    m_report.stopped = true;
    if (m_poller)
        m_poller->stop(); // finished() of the run follows at once
    else
        onRunFinished();
}

void Sweep::startRun()
{
    if (m_stopping || m_next >= m_settings.intervalsNs.size()) {
        m_finished = true;
        m_core->progressState().polling = false;
        m_core->recorder()->flushBatch(); // every record reaches observers before the report
        Q_EMIT finished(m_report);
        return;
    }
    PollSettings poll = m_settings.poll;
    poll.intervalNs = m_settings.intervalsNs.at(m_next);
    EngineProgress &p = m_core->progressState();
    p.run = m_next;
    p.runs = int(m_settings.intervalsNs.size());
    ++m_next;
    m_poller = new Poller(m_core, poll, m_core->reserveId(), this);
    connect(m_poller, &Poller::finished, this, &Sweep::onRunFinished, Qt::QueuedConnection);
    m_poller->start();
}

void Sweep::onRunFinished()
{
    if (m_poller) {
        m_report.runs.append(m_poller->run());
        m_poller->deleteLater();
        m_poller = nullptr;
    }
    startRun();
}

} // namespace mbscope

#include "moc_sweep.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
