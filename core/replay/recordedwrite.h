#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// A recorded request that writes to the device: what a replay to a live device would change
// there if it re-sent it (its outputs, set points, files). Replay sends none of these unless the
// user asks (`mbscope replay --send-writes`, the window's question before a replay).
//
// The writing functions (MODBUS Application Protocol V1.1b3, 6): 05 Write Single Coil, 06 Write
// Single Register, 0F Write Multiple Coils, 10 Write Multiple Registers, 15 Write File Record,
// 16 Mask Write Register, 17 Read/Write Multiple Registers (its write half). Address and quantity
// are the request's (0F, 10: its starting address and quantity; 05, 06, 16: its address and 1;
// 17: the write starting address and quantity; 15: the first sub-request's record number and
// record length). A request too short to hold them is still a write: known says so.
//
// Diagnostics (08) sub-functions that change the device's state are held back the same way
// (6.8.1): 01 Restart Communications Option (restarts the port, may clear the event log), 03
// Change ASCII Input Delimiter, 04 Force Listen Only Mode (the device stops answering until
// restarted), 0A Clear Counters and Diagnostic Register, 14 Clear Overrun Counter and Flag; the
// other sub-functions only read and are replayed. A Diagnostics request too short to name its
// sub-function is held back too.
struct RecordedWrite {
    qsizetype index = 0;   // in the ReplayScript
    quint8 unitId = 0;
    quint8 function = 0;
    quint16 address = 0;
    quint16 quantity = 0;
    bool known = false;    // address and quantity (08: the sub-function) read from the request
    int subFunction = -1;  // 08 only: the sub-function; -1 for every other function

    [[nodiscard]] static bool isWriteFunction(quint8 function);
    // A Diagnostics (08) sub-function that changes the device's state (the list above).
    [[nodiscard]] static bool isChangingDiagnostic(int subFunction);
    // The write a request PDU makes (function code first); nullopt for any other request.
    [[nodiscard]] static std::optional<RecordedWrite> of(qsizetype index, quint8 unitId, const QByteArray &pdu);
    // "#4 unit 1 Write Single Register (06) address 0x007D quantity 1",
    // "#2 unit 1 Diagnostics (08) sub-function 0x0001 Restart Communications Option"
    [[nodiscard]] QString text() const;
    // {"request": 4, "unit": 1, "function": "0x06", "name": "Write Single Register", "address": 125, "quantity": 1}
    // (address and quantity null when the request is too short to say; 08: "subFunction" and
    // "subFunctionName" instead of address and quantity)
    [[nodiscard]] QJsonObject toJson() const;
    // Where writes go, by unit: "unit 1 at 0x007D (2 times), 0x0100-0x0103; unit 3 at 0x0010"
    // (a request too short to say: "an unknown address"; a diagnostic: "Restart Communications
    // Option").
    [[nodiscard]] static QString placesText(const QList<RecordedWrite> &writes);
};

} // namespace mbscope
