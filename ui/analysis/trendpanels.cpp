#include "trendpanels.h"

#include "analysisdock.h"
#include "latencytimepanel.h"
#include "link/linkcontroller.h"
#include "registertrendpanel.h"
#include "sweeppanel.h"

namespace mbscope {

TrendPanels::TrendPanels(AnalysisDock *dock, LinkController *link, RegisterTable *registers,
                         std::function<QByteArray()> requestSource, QObject *parent)
    : QObject(parent)
    , m_latency(new LatencyTimePanel)
    , m_trends(new RegisterTrendPanel)
    , m_sweep(new SweepPanel)
{
    m_latency->setObjectName(QStringLiteral("latencyTimePanel"));
    m_trends->setObjectName(QStringLiteral("registerTrendPanel"));
    m_sweep->setObjectName(QStringLiteral("sweepPanel"));
    dock->addPanel(m_latency, tr("Latency over time"));
    dock->addPanel(m_trends, tr("Register trends"));
    dock->addPanel(m_sweep, tr("Sweep"));

    m_trends->setRegisterTable(registers);
    m_trends->setFraming(link->url().framing());
    m_sweep->setController(link);
    m_sweep->setRequestSource(std::move(requestSource));
    // Latency over time is fed by the LatencySource (LatencyAnalysis::feedTimePanel): the bench or a watch.
    connect(link, &LinkController::transactionsFinished, m_trends, &RegisterTrendPanel::addTransactions);
    // Another target starts another time axis: points of two devices do not share one.
    connect(link, &LinkController::stateChanged, this, [this, link](LinkController::State state) {
        if (state != LinkController::State::Ready)
            return;
        m_trends->setFraming(link->url().framing());
        m_latency->clear();
        m_trends->clear();
    });
}

void TrendPanels::setProfile(const UnitProfile &unit, const QString &profileName)
{
    m_trends->setProfile(unit, profileName);
}

} // namespace mbscope
