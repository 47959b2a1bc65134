#pragma once

#include "exchange/transaction.h"

#include <QtCore/QList>
#include <QtCore/QObject>

namespace mbscope {

class AnalysisDock;
class LatencyComparePanel;
class LatencyHistogramPanel;
class LatencyRuns;
class LinkController;

// The latency analysis of the window: the runs (fed by the link's transactions, the current run
// started afresh with each poll), the Latency histogram and Compare tabs of the Analysis dock.
class LatencyAnalysis : public QObject
{
    Q_OBJECT

public:
    LatencyAnalysis(AnalysisDock *dock, LinkController *link, QObject *parent = nullptr);

    [[nodiscard]] LatencyRuns *runs() const { return m_runs; }
    [[nodiscard]] LatencyHistogramPanel *histogramPanel() const { return m_histogram; }
    [[nodiscard]] LatencyComparePanel *comparePanel() const { return m_compare; }

public Q_SLOTS:
    // An opened capture's transactions: the Capture run, shown in the histogram tab.
    void showTransactions(const QString &title, const QList<mbscope::Transaction> &transactions);

private:
    LatencyRuns *m_runs;
    LatencyHistogramPanel *m_histogram;
    LatencyComparePanel *m_compare;
};

} // namespace mbscope
