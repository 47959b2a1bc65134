#pragma once

#include "profile/simtable.h"

#include <QtCore/QList>
#include <QtCore/QMetaType>

namespace mbscope {

// Consecutive values of one table of one unit as they are now (a view's batch: SimulatorHost
// gathers the changes of a few hundred milliseconds into one list of these).
struct SimValueUpdate {
    quint8 unit = 1;
    SimTable table = SimTable::HoldingRegisters;
    quint16 start = 0;
    QList<quint16> values; // bits as 0/1

    friend bool operator==(const SimValueUpdate &, const SimValueUpdate &) = default;
};

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::SimValueUpdate)
