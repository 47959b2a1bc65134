#pragma once

#include "buildresult.h"
#include "modiconreference.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringView>

#include <optional>

namespace mbscope {

// Which write function a table edit uses. The choice is the user's: a device may implement only
// 06 or only 10 (the RosRao module lists 03, 06 and 10; many PLCs accept 10 alone).
enum class WriteChoice : quint8 {
    Automatic, // holding registers: 06 for a one-register value, 10 for a wider one; coils: 05
    Single,    // 06 (05 for coils); a value wider than one register is refused
    Multiple,  // 10 (0F for coils), even for one register or one coil
};

struct TableWriteResult {
    QByteArray pdu;       // function code first
    quint8 functionCode = 0;
    QString description;  // "10 Write Multiple Registers: 2 registers from 40122 (PDU address 121)"
    QString error;        // what is wrong, for the user; empty when ok
    bool ok = false;
};

// Builds the request that writes one edited value into a table (V1.1b3, 6.5, 6.6, 6.11, 6.12),
// through RequestBuilder so every limit is checked in one place.
class TableWrite
{
public:
    // The function a choice gives for a value of registerCount registers (1 for a coil); 0 when
    // the table is read-only or the choice cannot write it (Single with more than one register).
    [[nodiscard]] static quint8 functionFor(ModbusTable table, int registerCount, WriteChoice choice);
    // Holding registers from address, words in wire order.
    [[nodiscard]] static TableWriteResult registers(int address, const QList<quint16> &words, WriteChoice choice);
    [[nodiscard]] static TableWriteResult coil(int address, bool on, WriteChoice choice);
    // "1", "on", "true" and "0", "off", "false" in any case; nothing for anything else.
    [[nodiscard]] static std::optional<bool> coilFromText(QStringView text);
};

} // namespace mbscope
