#pragma once

#include "exchange/transaction.h"
#include "protocol/framing.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// The few fields of an exchange that a table row shows (CSV, JSON lines): unit, function, the
// first address and quantity, and the values read or written, taken straight from the PDUs
// (V1.1b3, 6.1-6.17). A code without addresses leaves them out; an exception or a malformed
// PDU leaves the values out. The dissector remains the one that explains frames.
struct ExchangeFields {
    bool valid = false; // the request (or the lone answer) carries a unit and a function code
    quint8 unit = 0;
    quint8 function = 0;      // the request's function code (bit 7 clear)
    bool exception = false;   // the answer is an exception
    bool hasAddress = false;
    quint16 address = 0;      // the first (read) address, as in the PDU (0-based)
    quint16 quantity = 0;     // registers or bits; 1 for single writes
    QString values;           // registers in decimal, bits as 0/1, space-separated

    [[nodiscard]] static ExchangeFields of(const Transaction &transaction, Framing framing);
    // The PDU of an ADU in a framing (ASCII decoded from its hex digits); the unit id in *unit.
    // Empty when the ADU is too short for its framing.
    [[nodiscard]] static QByteArray pduOf(const QByteArray &adu, Framing framing, quint8 *unit);
};

} // namespace mbscope
