#pragma once

#include "profile/simtable.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// One block of consecutive addresses in one table of a unit. A unit's table is the union of its
// ranges; addresses outside every range do not exist (a request touching one gets exception 02,
// V1.1b3 7). Ranges of one table never overlap.
struct SimRange {
    SimTable table = SimTable::HoldingRegisters;
    quint16 start = 0;
    int count = 1;          // 1..65536-start
    bool writable = true;   // clients may write here (coils and holding registers only; the
                            // other tables have no write function code but are always settable
                            // locally, by generators and the GUI)
    QString name;           // optional label for views and logs
    QList<quint16> values;  // count values (bits as 0/1); shorter lists are padded with 0

    [[nodiscard]] int end() const { return int(start) + count; } // one past the last address
    [[nodiscard]] bool contains(int address) const { return address >= start && address < end(); }
};

} // namespace mbscope
