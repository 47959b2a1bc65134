#pragma once

#include "sim/simtrafficrecord.h"
#include "sim/simulatorhost.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>
#include <QtCore/QPointer>
#include <QtCore/QString>

namespace mbscope {


// The simulators running in the window, one row each (the first-run simulator and those the
// panel started). Columns:
//   Profile | Listening on | Requests | Faulted
// The counts come from the hosts' traffic batches (countRecords). A host that stops (from the
// panel or elsewhere) or is deleted leaves the list.
class SimRunListModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { ProfileColumn, EndpointColumn, RequestsColumn, FaultedColumn, ColumnCount };
    Q_ENUM(Column)

    explicit SimRunListModel(QObject *parent = nullptr);

    // label: the profile's name or file; builtIn: the first-run simulator (said in the list).
    void addHost(SimulatorHost *host, const QString &label, bool builtIn = false);
    void removeHost(SimulatorHost *host);
    [[nodiscard]] SimulatorHost *hostAt(int row) const;
    [[nodiscard]] int rowOf(const SimulatorHost *host) const;
    [[nodiscard]] bool isBuiltIn(int row) const;
    void countRecords(SimulatorHost *host, const QList<SimTrafficRecord> &records);

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    struct Run {
        QPointer<SimulatorHost> host;
        QString label;
        QString endpoints;
        bool builtIn = false;
        quint64 requests = 0;
        quint64 faulted = 0;
    };
    QList<Run> m_runs;
};

} // namespace mbscope
