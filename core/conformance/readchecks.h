#pragma once

#include "conformancecheck.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>

namespace mbscope {

// The read functions (01-04): a normal answer, quantity 0 and above the maximum (exception 03),
// the maximum itself, a block past the address space and an address the device lacks
// (exception 02), coils and inputs packed first item in the lowest bit; and exception 01 for a
// function code no device implements. One table of the four functions, every check made from it.
class ReadChecks
{
public:
    [[nodiscard]] static QList<ConformanceCheck> checks();
    // fc, address, quantity: a read request PDU sent as built (any quantity, on purpose).
    [[nodiscard]] static QByteArray readPdu(quint8 function, int address, int quantity);
    // The table a read function reads (01 coils, 02 discrete inputs, 03 holding, 04 input), -1 for others.
    [[nodiscard]] static int tableOf(quint8 function);
};

} // namespace mbscope
