#include "poll/pollrunner.h"

#include "time/duration.h"
#include "common/framelog.h"
#include "common/interruptwatcher.h"
#include "poll/polltranscript.h"
#include "common/transactionreport.h"

#include "engine/transactionengine.h"

#include <QtCore/QEventLoop>

namespace mbscope::app {

PollRunner::PollRunner(const TargetSettings &target, const EngineOptions &options, QObject *parent)
    : QObject(parent)
    , m_target(target)
    , m_engine(new TransactionEngine(this))
{
    m_engine->setTarget(target.url, options);
    connect(m_engine, &TransactionEngine::progress, this, &PollRunner::onProgress);
    connect(m_engine, &TransactionEngine::transactionsFinished, this, &PollRunner::onTransactions);
}

PollRunner::~PollRunner() = default;

PollOutcome PollRunner::run(const SweepSettings &settings, bool sweep)
{
    m_sweep = sweep;
    PollOutcome outcome;
    QEventLoop loop;
    InterruptWatcher interrupts;
    connect(&interrupts, &InterruptWatcher::interrupted, this, [this] {
        m_interrupted = true;
        m_line.show(QStringLiteral("stopping..."));
        m_engine->stop();
    });
    bool finished = false;
    connect(m_engine, &TransactionEngine::finished, &loop, [&](const PollReport &report) {
        outcome.report = report;
        finished = true;
        loop.quit();
    });
    if (m_log)
        m_engine->setTrafficLog(m_log);
    if (m_frameLog) {
        m_engine->setFramesPublished(true);
        connect(m_engine, &TransactionEngine::framesLogged, this, [this](const QList<TrafficFrame> &frames) {
            m_line.clear(); // the progress line comes back with the next progress
            m_frameLog->add(frames);
        });
    }
    if (sweep)
        m_engine->startSweep(settings);
    else
        m_engine->startPoll(settings.poll);
    if (!finished)
        loop.exec();
    if (m_frameLog)
        m_engine->deliverPending(); // the last frames reach the log
    // The engine's last batch of frames reaches the journal, and the log is the caller's again.
    if (m_log)
        m_engine->setTrafficLog(nullptr);
    m_line.clear();
    outcome.interrupted = m_interrupted;
    outcome.linkFailed = m_linkFailed;
    outcome.linkMessage = m_linkMessage;
    return outcome;
}

void PollRunner::onTransactions(const QList<Transaction> &transactions)
{
    if (m_transcript) {
        m_line.clear();
        m_transcript->add(transactions);
    }
    for (const Transaction &t : transactions) {
        if (t.status == TransactionStatus::Late)
            continue;
        if (t.status != TransactionStatus::LinkError) {
            m_sawAnswer = true;
            if (t.latencyNs() >= 0)
                m_lastLatencyNs = t.latencyNs();
        } else if (!m_sawAnswer && !m_linkFailed) {
            // Nothing has ever reached the device: a wrong port, host or device, not a flaky link.
            m_linkFailed = true;
            m_linkMessage = t.problem;
            m_engine->stop();
        }
    }
}

void PollRunner::onProgress(const EngineProgress &p)
{
    if (!m_line.isEnabled() || !p.polling || m_interrupted)
        return;
    QString text;
    if (m_sweep && p.runs > 1)
        text += QStringLiteral("interval %1/%2 (%3)  ").arg(p.run + 1).arg(p.runs).arg(formatDuration(p.intervalNs));
    text += QStringLiteral("cycle %1").arg(p.cycle);
    if (p.cyclesPlanned > 0)
        text += QStringLiteral("/%1").arg(p.cyclesPlanned);
    text += QStringLiteral("  ok %1  failed %2").arg(p.ok).arg(p.failed);
    if (m_lastLatencyNs >= 0)
        text += QStringLiteral("  last %1").arg(latencyText(m_lastLatencyNs));
    text += QStringLiteral("  %1").arg(QString::number(double(p.elapsedNs) / 1e9, 'f', 1));
    if (p.durationNs > 0)
        text += QStringLiteral("/%1").arg(QString::number(double(p.durationNs) / 1e9, 'f', 1));
    text += QStringLiteral(" s  (Ctrl-C stops)");
    m_line.show(text);
}

} // namespace mbscope::app
