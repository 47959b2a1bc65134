#pragma once

#include "watch/watchdefinition.h"

#include <QtWidgets/QTableWidget>

namespace mbscope {

// The points of a watch as an editable table: address, name, format, unit, scale, offset and
// whether the window may write it. Bit fields are kept as they came (the dialog does not edit
// them), matched by address.
class WatchPointTable : public QTableWidget
{
    Q_OBJECT
public:
    enum Column { AddressColumn, NameColumn, FormatColumn, UnitColumn, ScaleColumn, OffsetColumn, WritableColumn, ColumnCount };

    explicit WatchPointTable(QWidget *parent = nullptr);

    void setPoints(const QList<WatchPoint> &points);
    // The points typed, or problems ("point 2: 'f33' is not a register format ...").
    [[nodiscard]] QList<WatchPoint> points(QStringList *problems) const;
    void addPoint(quint16 address);
    void removeCurrent();

private:
    void setRow(int row, const WatchPoint &point);
    QList<WatchPoint> m_original;
};

} // namespace mbscope
