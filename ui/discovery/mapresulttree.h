#pragma once

#include "discovery/registermap.h"

#include <QtWidgets/QTreeWidget>

namespace mbscope {

// A register map as a tree: a row per table (its largest quantity and the requests it took) with
// a row per block of addresses found (range, count, the first values), then the optional
// functions and what each did, the exception status (07) and the server id (11).
class MapResultTree : public QTreeWidget
{
    Q_OBJECT
public:
    enum Column { ItemColumn, FindingColumn, DetailColumn, ColumnCount };

    explicit MapResultTree(QWidget *parent = nullptr);

    void showMap(const RegisterMap &map);
    // Addresses found in every table: what the dialog's status line sums up.
    [[nodiscard]] static int addressCount(const RegisterMap &map);
    [[nodiscard]] static QString tableName(quint8 function);
};

} // namespace mbscope
