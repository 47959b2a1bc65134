#pragma once

#include "profile/deviceprofile.h"
#include "profile/simtable.h"
#include "sim/simvalueupdate.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QHash>
#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// Every address of one simulated unit, all four tables, as the simulator holds them now: one row
// per coil, discrete input or register. Columns:
//   Table | Address | Name (from the profile) | Value | Hex
// The values arrive in batches (applyUpdates: a SimulatorHost's valuesUpdated), one dataChanged
// per batch; the rows of the latest batch are marked (ChangedRole, a background).
//
// Editing a value never changes the model: it emits valueEdited, the simulator sets the value,
// and the next batch shows it (what a client then reads). Bad text is refused with editRefused
// saying what and where.
class SimRegisterModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { TableColumn, AddressColumn, NameColumn, ValueColumn, HexColumn, ColumnCount };
    Q_ENUM(Column)
    enum Role {
        AddressRole = Qt::UserRole + 1, // int: the row's address
        TableRole,                      // int: the row's SimTable
        ChangedRole,                    // bool: changed in the latest batch
    };
    Q_ENUM(Role)

    explicit SimRegisterModel(QObject *parent = nullptr);

    // The rows of one unit from a snapshot (SimulatorHost::snapshot), named by its profile.
    void setUnit(quint8 unit, const QList<SimValueUpdate> &snapshot, const std::optional<UnitProfile> &profile);
    void clear();
    [[nodiscard]] bool hasUnit() const { return m_hasUnit; }
    [[nodiscard]] quint8 unit() const { return m_unit; }
    // Updates for other units are ignored.
    void applyUpdates(const QList<SimValueUpdate> &updates);

    [[nodiscard]] int rowOf(SimTable table, int address) const;
    [[nodiscard]] std::optional<quint16> value(SimTable table, int address) const;

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

Q_SIGNALS:
    void valueEdited(quint8 unit, mbscope::SimTable table, int address, quint16 value);
    void editRefused(const QString &message);

private:
    struct Row {
        SimTable table = SimTable::HoldingRegisters;
        quint16 address = 0;
        quint16 value = 0;
    };
    [[nodiscard]] static quint32 keyOf(SimTable table, int address) { return (quint32(table) << 16) | quint32(address); }
    [[nodiscard]] QString nameOf(const Row &row) const;
    [[nodiscard]] QString descriptionOf(const Row &row) const;
    [[nodiscard]] QString tableText(SimTable table) const;

    bool m_hasUnit = false;
    quint8 m_unit = 0;
    std::optional<UnitProfile> m_profile;
    QList<Row> m_rows;
    QHash<quint32, int> m_rowOf;
    QList<int> m_changed; // rows of the latest batch
};

} // namespace mbscope
