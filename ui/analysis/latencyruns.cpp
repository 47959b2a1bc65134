#include "latencyruns.h"

namespace mbscope {

LatencyRuns::LatencyRuns(QObject *parent)
    : QObject(parent)
    , m_runs(kRunCount)
{
    // The current run goes on as long as the window polls: its latencies past the first 100,000
    // are binned (percentiles within 0.1 %), so the dock's memory stays flat all day.
    for (StatisticsSet &run : m_runs)
        run.setExactLatencyLimit(LatencySamples::kLongRunExactLimit);
}

void LatencyRuns::addTransactions(const QList<Transaction> &transactions)
{
    if (transactions.isEmpty())
        return;
    StatisticsSet &current = m_runs[Current];
    for (const Transaction &transaction : transactions)
        current.add(transaction);
    Q_EMIT changed(Current);
}

void LatencyRuns::clearCurrent()
{
    m_runs[Current].clear();
    Q_EMIT changed(Current);
}

void LatencyRuns::keepReference()
{
    m_runs[Reference] = m_runs[Current];
    const bool appeared = !m_present[Reference];
    m_present[Reference] = true;
    if (appeared)
        Q_EMIT runsChanged();
    Q_EMIT changed(Reference);
}

void LatencyRuns::setCapture(const QString &title, const QList<Transaction> &transactions)
{
    StatisticsSet capture;
    for (const Transaction &transaction : transactions)
        capture.add(transaction);
    m_runs[Capture] = std::move(capture);
    m_present[Capture] = true;
    m_captureTitle = title;
    Q_EMIT runsChanged();
    Q_EMIT changed(Capture);
}

QString LatencyRuns::title(Run run) const
{
    switch (run) {
    case Current:
        return tr("Current poll");
    case Reference:
        return tr("Reference");
    case Capture:
        return tr("Capture: %1").arg(m_captureTitle);
    }
    return {};
}

QString LatencyRuns::itemTitle(int item)
{
    return item < 0 ? tr("overall") : tr("item %1").arg(item);
}

const Statistics &LatencyRuns::statistics(Run run, int item) const
{
    const StatisticsSet &set = m_runs[std::size_t(run)];
    return item < 0 ? set.overall() : set.item(item);
}

} // namespace mbscope
