#include "sweeptablemodel.h"

namespace mbscope {

namespace {

QString milliseconds(double ms)
{
    return QString::number(ms, 'f', 3);
}

} // namespace

SweepRow SweepRow::of(const PollRun &run)
{
    const Statistics &s = run.statistics.overall();
    const LatencySamples &latency = s.latency();
    SweepRow row;
    row.intervalNs = run.intervalNs;
    row.cycles = run.cycles;
    row.count = s.count();
    row.ok = s.ok();
    row.failed = s.failed();
    row.timeouts = s.timeouts();
    row.errorRatePercent = 100.0 * s.errorRate();
    row.answered = !latency.isEmpty();
    row.medianMs = double(latency.medianNs()) / 1e6;
    row.p95Ms = double(latency.percentileNs(95)) / 1e6;
    row.maxMs = double(latency.maxNs()) / 1e6;
    row.stopped = run.stopped;
    return row;
}

SweepTableModel::SweepTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void SweepTableModel::setReport(const PollReport &report)
{
    beginResetModel();
    m_rows.clear();
    for (const PollRun &run : report.runs)
        m_rows.append(SweepRow::of(run));
    endResetModel();
}

void SweepTableModel::clear()
{
    beginResetModel();
    m_rows.clear();
    endResetModel();
}

int SweepTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int SweepTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SweepTableModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const SweepRow &row = m_rows.at(index.row());
    if (role == Qt::TextAlignmentRole)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole && row.stopped)
        return tr("Stopped before its count: the figures cover the part that ran");
    if (role != Qt::DisplayRole)
        return {};
    switch (Column(index.column())) {
    case IntervalColumn: {
        const QString ms = QString::number(double(row.intervalNs) / 1e6, 'g', 6);
        return row.stopped ? tr("%1 (stopped)").arg(ms) : ms;
    }
    case CyclesColumn: return QString::number(row.cycles);
    case CountColumn: return QString::number(row.count);
    case OkColumn: return QString::number(row.ok);
    case FailedColumn: return QString::number(row.failed);
    case TimeoutsColumn: return QString::number(row.timeouts);
    case ErrorRateColumn: return QString::number(row.errorRatePercent, 'f', 2);
    case MedianColumn: return row.answered ? milliseconds(row.medianMs) : QString();
    case P95Column: return row.answered ? milliseconds(row.p95Ms) : QString();
    case MaxColumn: return row.answered ? milliseconds(row.maxMs) : QString();
    case ColumnCount: break;
    }
    return {};
}

QVariant SweepTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole)
        return {};
    if (orientation == Qt::Vertical)
        return section + 1;
    switch (Column(section)) {
    case IntervalColumn: return tr("Interval (ms)");
    case CyclesColumn: return tr("Cycles");
    case CountColumn: return tr("Transactions");
    case OkColumn: return tr("OK");
    case FailedColumn: return tr("Failed");
    case TimeoutsColumn: return tr("Timeouts");
    case ErrorRateColumn: return tr("Error rate (%)");
    case MedianColumn: return tr("Median (ms)");
    case P95Column: return tr("p95 (ms)");
    case MaxColumn: return tr("Max (ms)");
    case ColumnCount: break;
    }
    return {};
}

} // namespace mbscope
