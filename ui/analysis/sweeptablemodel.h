#pragma once

#include "engine/pollreport.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>

namespace mbscope {

// The figures of one interval of a sweep, taken from its PollRun once (Statistics sorts its
// latencies to answer percentiles, so the model keeps numbers, not the statistics).
struct SweepRow {
    qint64 intervalNs = 0;
    quint64 cycles = 0;
    quint64 count = 0;
    quint64 ok = 0;
    quint64 failed = 0;
    quint64 timeouts = 0;
    double errorRatePercent = 0; // Statistics::errorRate() x 100
    bool answered = false;       // at least one latency: the latency figures mean something
    double medianMs = 0;
    double p95Ms = 0;
    double maxMs = 0;
    bool stopped = false;        // the run was cut short by Stop

    [[nodiscard]] static SweepRow of(const PollRun &run);
};

// A sweep's table: one row per interval run, in the order they ran. Columns:
//   Interval (ms) | Cycles | Transactions | OK | Failed | Timeouts | Error rate (%) | Median (ms) | p95 (ms) | Max (ms)
// Latency columns are empty for an interval where nothing was answered. Exported as CSV.
class SweepTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { IntervalColumn, CyclesColumn, CountColumn, OkColumn, FailedColumn, TimeoutsColumn,
                  ErrorRateColumn, MedianColumn, P95Column, MaxColumn, ColumnCount };
    Q_ENUM(Column)

    explicit SweepTableModel(QObject *parent = nullptr);

    void setReport(const PollReport &report);
    void clear();
    [[nodiscard]] const QList<SweepRow> &rows() const { return m_rows; }

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    QList<SweepRow> m_rows;
};

} // namespace mbscope
