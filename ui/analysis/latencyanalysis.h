#pragma once

#include "exchange/transaction.h"

#include <QtCore/QList>
#include <QtCore/QObject>

namespace mbscope {

class AnalysisDock;
class LatencyComparePanel;
class LatencyHistogramPanel;
class LatencyRuns;
class LatencySource;
class LatencyTimePanel;
class LinkController;

// The latency analysis of the window: the runs (fed by the link's transactions, the current run
// started afresh with each poll), the Latency histogram and Compare tabs of the Analysis dock.
// A LatencySource between the link and the runs lets the panels show a watch link or a watch
// instead (the workspace's samples, WatchWorkspace::sampled, go to source()->addWatchSamples).
class LatencyAnalysis : public QObject
{
    Q_OBJECT

public:
    LatencyAnalysis(AnalysisDock *dock, LinkController *link, QObject *parent = nullptr);

    [[nodiscard]] LatencyRuns *runs() const { return m_runs; }
    [[nodiscard]] LatencyHistogramPanel *histogramPanel() const { return m_histogram; }
    [[nodiscard]] LatencyComparePanel *comparePanel() const { return m_compare; }
    // Whose latency the panels show: the bench, a watch link or a watch.
    [[nodiscard]] LatencySource *source() const { return m_source; }
    // Latency over time (built with the trends) takes its transactions from the same source.
    void feedTimePanel(LatencyTimePanel *panel);

public Q_SLOTS:
    // An opened capture's transactions: the Capture run, shown in the histogram tab.
    void showTransactions(const QString &title, const QList<mbscope::Transaction> &transactions);

private:
    LatencySource *m_source;
    LatencyRuns *m_runs;
    LatencyHistogramPanel *m_histogram;
    LatencyComparePanel *m_compare;
};

} // namespace mbscope
