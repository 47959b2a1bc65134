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
struct RecordedWrite {
    qsizetype index = 0;   // in the ReplayScript
    quint8 unitId = 0;
    quint8 function = 0;
    quint16 address = 0;
    quint16 quantity = 0;
    bool known = false;    // address and quantity read from the request

    [[nodiscard]] static bool isWriteFunction(quint8 function);
    // The write a request PDU makes (function code first); nullopt for any other request.
    [[nodiscard]] static std::optional<RecordedWrite> of(qsizetype index, quint8 unitId, const QByteArray &pdu);
    // "#4 unit 1 Write Single Register (06) address 0x007D quantity 1"
    [[nodiscard]] QString text() const;
    // {"request": 4, "unit": 1, "function": "0x06", "name": "Write Single Register", "address": 125, "quantity": 1}
    // (address and quantity null when the request is too short to say)
    [[nodiscard]] QJsonObject toJson() const;
    // Where writes go, by unit: "unit 1 at 0x007D (2 times), 0x0100-0x0103; unit 3 at 0x0010"
    // (a request too short to say: "an unknown address").
    [[nodiscard]] static QString placesText(const QList<RecordedWrite> &writes);
};

} // namespace mbscope
