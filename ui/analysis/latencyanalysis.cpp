#include "latencyanalysis.h"

#include "analysisdock.h"
#include "latencycomparepanel.h"
#include "latencyhistogrampanel.h"
#include "latencyruns.h"
#include "latencysource.h"
#include "latencytimepanel.h"
#include "link/linkcontroller.h"

namespace mbscope {

LatencyAnalysis::LatencyAnalysis(AnalysisDock *dock, LinkController *link, QObject *parent)
    : QObject(parent)
    , m_source(new LatencySource(this))
    , m_runs(new LatencyRuns(this))
    , m_histogram(new LatencyHistogramPanel(m_runs))
    , m_compare(new LatencyComparePanel(m_runs))
{
    m_histogram->setObjectName(QStringLiteral("latencyHistogramPanel"));
    m_compare->setObjectName(QStringLiteral("latencyComparePanel"));
    dock->addPanel(m_histogram, tr("Latency histogram"));
    dock->addPanel(m_compare, tr("Compare"));
    m_histogram->addSourceChoice(m_source->makeChoiceBox(m_histogram));
    connect(link, &LinkController::transactionsFinished, m_source, &LatencySource::addBenchTransactions);
    // Another connection: the bench's history and panels start again (the time axis at its first request).
    connect(link, &LinkController::stateChanged, m_source, [this](LinkController::State state) {
        if (state == LinkController::State::Ready)
            m_source->restartBench();
    });
    connect(m_source, &LatencySource::transactionsChosen, m_runs, &LatencyRuns::addTransactions);
    connect(m_source, &LatencySource::reset, m_runs, [this] {
        m_runs->clearCurrent();
        m_histogram->setRun(LatencyRuns::Current);
    });
    // "The current poll": a new poll starts a new run (single sends before it are forgotten).
    connect(link, &LinkController::pollingChanged, m_runs, [this](bool polling) {
        if (polling && m_source->isBench()) {
            m_runs->clearCurrent();
            // A live poll is what the user watches now: the histogram leaves an opened capture for it.
            m_histogram->setRun(LatencyRuns::Current);
        }
    });
}

void LatencyAnalysis::feedTimePanel(LatencyTimePanel *panel)
{
    panel->addSourceChoice(m_source->makeChoiceBox(panel));
    connect(m_source, &LatencySource::transactionsChosen, panel, &LatencyTimePanel::addTransactions);
    connect(m_source, &LatencySource::reset, panel, &LatencyTimePanel::clear);
}

void LatencyAnalysis::showTransactions(const QString &title, const QList<Transaction> &transactions)
{
    m_histogram->showTransactions(title, transactions);
}

} // namespace mbscope
