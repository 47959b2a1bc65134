#pragma once

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QVariant>

namespace mbscope {

class Statistics;

// The statistics table beside a latency histogram: one row per figure (transactions, ok,
// exceptions and each exception code seen, timeouts, CRC errors, malformed, unexpected, late,
// link errors, answers faster than their serial line (when there are any), then latency min, mean, median, p90, p95, p99, max and standard deviation), the
// figure's name in column 0 and one column per run shown (two side by side in Compare).
//
// The figures are taken when setColumns() is called (the panels do it on their redraw timer),
// so the model holds plain numbers, not the statistics. DisplayRole: the text (latencies in one
// unit for the whole table); UserRole: the number (counts, latencies in nanoseconds).
class LatencyStatisticsModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    struct Column {
        QString title;
        const Statistics *statistics = nullptr; // read during setColumns() only
    };

    explicit LatencyStatisticsModel(QObject *parent = nullptr);

    void setColumns(const QList<Column> &columns);

    // The row of a figure by its key ("count", "ok", "exceptions", "exception 0x02", "timeouts",
    // "crc_errors", "malformed", "unexpected", "late", "link_errors", "outran_line", "latency_min", ...,
    // "latency_stddev"); -1 when there is no such row.
    [[nodiscard]] int rowOf(const QString &key) const;
    // The number in a row (by key) and run column (0 for the first run); invalid when absent.
    [[nodiscard]] QVariant value(const QString &key, int run = 0) const;

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    struct Row {
        QString key;
        QString name;
        bool latency = false;        // a time in nanoseconds, shown in the table's unit
        QList<QVariant> values;      // one per column; invalid when the run has none (no answers)
    };

    [[nodiscard]] static QList<Row> rowsFor(const QList<Column> &columns);

    QStringList m_titles;
    QList<Row> m_rows;
    double m_unitNs = 1e6;
    QString m_unitName;
};

} // namespace mbscope
