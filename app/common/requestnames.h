#pragma once

#include <QtCore/QString>

namespace mbscope::app {

// How the command line names a request it built: in its description, in statistics and journals.
class RequestNames
{
public:
    // "0079": an address as four hex digits.
    [[nodiscard]] static QString hex4(int address);
    // "unit 1, 22 registers at 121 (0x0079), 40122-40143"; counted from 1: "unit 1, 22 registers
    // at 122 (1-based; PDU address 121, 0x0079), 40122-40143".
    [[nodiscard]] static QString describeItems(quint8 functionCode, int unit, int address, int quantity,
                                               const char *items, bool oneBased);
    // "Read Holding Registers, " and describeItems.
    [[nodiscard]] static QString describe(quint8 functionCode, int unit, int address, int quantity, const char *items,
                                          bool oneBased);
    // A read's items: "register"/"registers", "coil"/"coils", "discrete input"/"discrete inputs".
    [[nodiscard]] static const char *readNoun(quint8 functionCode, int quantity);
    // A request's name in statistics and journals: "Read Holding Registers 121 x4", counted from 1
    // "Read Holding Registers 122 x4 (1-based)".
    [[nodiscard]] static QString itemName(quint8 functionCode, int address, int quantity, bool oneBased);
};

} // namespace mbscope::app
