#pragma once

#include "sim/simtrafficrecord.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// The simulator's own traffic: one row per request it received (with the answer as the fault
// plan sent it, or why there was none) and per connection event. Columns:
//   Time | Endpoint | Peer | Unit | Function | Outcome | Request | Sent
// Rows arrive in batches (appendRecords: a SimulatorHost's trafficRecorded), one
// beginInsertRows each; past the row limit the oldest rows go, in one beginRemoveRows, and are
// counted (droppedCount), with those the host could not hand over.
class SimTrafficModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { TimeColumn, EndpointColumn, PeerColumn, UnitColumn, FunctionColumn, OutcomeColumn, RequestColumn, SentColumn, ColumnCount };
    Q_ENUM(Column)
    enum Role {
        FaultedRole = Qt::UserRole + 1, // bool: a fault rule changed or dropped the answer
        ExceptionCodeRole,              // int: the exception code sent, or 0
    };
    Q_ENUM(Role)

    static constexpr int kDefaultRowLimit = 10000;

    explicit SimTrafficModel(QObject *parent = nullptr);

    void appendRecords(const QList<SimTrafficRecord> &records, int lost = 0);
    void clear();
    void setRowLimit(int rows);
    [[nodiscard]] int rowLimit() const { return m_rowLimit; }
    // Rows dropped for the limit plus records the host lost, since the last clear().
    [[nodiscard]] quint64 droppedCount() const { return m_dropped; }
    [[nodiscard]] const SimTrafficRecord &record(int row) const { return m_rows.at(row); }

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // What happened, in words: "answered", "exception 06 (server device busy), by fault rule
    // exception", "no answer: dropped by fault rule drop"...
    [[nodiscard]] QString outcomeText(const SimTrafficRecord &record) const;

private:
    void trimTo(int rows);
    [[nodiscard]] QString functionText(const SimTrafficRecord &record) const;
    [[nodiscard]] static int exceptionCodeOf(const SimTrafficRecord &record);

    QList<SimTrafficRecord> m_rows;
    int m_rowLimit = kDefaultRowLimit;
    quint64 m_dropped = 0;
    qint64 m_originNs = -1; // the first record's time: the Time column counts from it
};

} // namespace mbscope
