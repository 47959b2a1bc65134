#pragma once

#include "discovery/unitprobe.h"

#include <QtCore/QAbstractTableModel>
#include <QtCore/QList>

namespace mbscope {

// The unit scan's results as a table: a thin adapter over the scanner's UnitProbe values, one row
// per id asked, appended as they come.
class ScanResultModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { UnitColumn, ResultColumn, LatencyColumn, DetailColumn, ColumnCount };
    // The probe of a row, for views and actions.
    static constexpr int ProbeRole = Qt::UserRole + 1;

    explicit ScanResultModel(QObject *parent = nullptr);

    void clear();
    void append(const UnitProbe &probe);
    [[nodiscard]] const QList<UnitProbe> &probes() const { return m_probes; }
    // The window's words for a kind ("answers", "gateway: no path (0A)"), translated.
    [[nodiscard]] static QString kindText(UnitProbeKind kind);

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    [[nodiscard]] static QString detailText(const UnitProbe &probe);

    QList<UnitProbe> m_probes;
};

} // namespace mbscope
