#include "latencyanalysis.h"

#include "analysisdock.h"
#include "latencycomparepanel.h"
#include "latencyhistogrampanel.h"
#include "latencyruns.h"
#include "link/linkcontroller.h"

namespace mbscope {

LatencyAnalysis::LatencyAnalysis(AnalysisDock *dock, LinkController *link, QObject *parent)
    : QObject(parent)
    , m_runs(new LatencyRuns(this))
    , m_histogram(new LatencyHistogramPanel(m_runs))
    , m_compare(new LatencyComparePanel(m_runs))
{
    m_histogram->setObjectName(QStringLiteral("latencyHistogramPanel"));
    m_compare->setObjectName(QStringLiteral("latencyComparePanel"));
    dock->addPanel(m_histogram, tr("Latency histogram"));
    dock->addPanel(m_compare, tr("Compare"));
    connect(link, &LinkController::transactionsFinished, m_runs, &LatencyRuns::addTransactions);
    // "The current poll": a new poll starts a new run (single sends before it are forgotten).
    connect(link, &LinkController::pollingChanged, m_runs, [this](bool polling) {
        if (polling) {
            m_runs->clearCurrent();
            // A live poll is what the user watches now: the histogram leaves an opened capture for it.
            m_histogram->setRun(LatencyRuns::Current);
        }
    });
}

void LatencyAnalysis::showTransactions(const QString &title, const QList<Transaction> &transactions)
{
    m_histogram->showTransactions(title, transactions);
}

} // namespace mbscope
