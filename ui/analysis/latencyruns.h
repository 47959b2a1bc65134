#pragma once

#include "exchange/statisticsset.h"
#include "exchange/transaction.h"

#include <QtCore/QList>
#include <QtCore/QObject>
#include <QtCore/QString>

#include <vector>

namespace mbscope {

// The runs the latency panels show, each the statistics of its transactions overall and per
// request item: the current one (the poll in progress or last finished, and single sends), a
// reference kept from it to compare later runs with, and an opened capture. Fed in batches;
// changed() says so once per batch and the panels redraw on their own timers.
class LatencyRuns : public QObject
{
    Q_OBJECT

public:
    // Indexes into the runs: Current always exists; Reference and Capture once kept or opened.
    enum Run : int { Current = 0, Reference = 1, Capture = 2 };
    Q_ENUM(Run)
    static constexpr int kRunCount = 3;

    explicit LatencyRuns(QObject *parent = nullptr);

    void addTransactions(const QList<Transaction> &transactions);
    void clearCurrent();
    // The current run becomes the reference (a copy: the current run goes on).
    void keepReference();
    // An opened capture's transactions replace the previous capture's.
    void setCapture(const QString &title, const QList<Transaction> &transactions);

    [[nodiscard]] bool has(Run run) const { return m_present[std::size_t(run)]; }
    [[nodiscard]] const StatisticsSet &statistics(Run run) const { return m_runs[std::size_t(run)]; }
    // "Current poll", "Reference", "Capture: plant.pcapng".
    [[nodiscard]] QString title(Run run) const;
    // "overall" or "item 2", for the choices and legends.
    [[nodiscard]] static QString itemTitle(int item);
    // The statistics of one item of a run, or overall for item -1.
    [[nodiscard]] const Statistics &statistics(Run run, int item) const;

Q_SIGNALS:
    // Counts of run changed (new transactions, cleared, replaced).
    void changed(mbscope::LatencyRuns::Run run);
    // Reference or Capture appeared or got a new title: the choices list them.
    void runsChanged();

private:
    std::vector<StatisticsSet> m_runs;
    bool m_present[kRunCount] = {true, false, false};
    QString m_captureTitle;
};

} // namespace mbscope
