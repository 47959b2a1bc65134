#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// A request as a device script's onRequest(request) sees it: the PDU taken apart for the
// functions that address a table (V1.1b3, 6.1-6.17), the rest given as bytes. Pure and total:
// any PDU (a short one, a wrong byte count) gives a request; what could not be read stays -1 or empty.
struct ScriptRequest {
    int unit = 0;
    int function = -1;       // the function code, -1 for an empty PDU
    int address = -1;        // start address (17: the read's), -1 when the function has none
    int quantity = -1;       // 01-04, 0F, 10, 17 (the read's); 05, 06 and 16: 1
    int writeAddress = -1;   // 17 only: the write's start address
    QList<quint16> values;   // written values: 05 as 0/1, 06 one, 0F bits as 0/1, 10 and 17 registers, 16 and/or masks
    QByteArray pdu;          // function code first
    QString endpoint;        // "tcp://127.0.0.1:1502"
    QString peer;            // "127.0.0.1:53122"
    int transactionId = -1;  // MBAP framings; -1 on serial framings
    double timeMs = 0;       // since the script was loaded

    // Fills function, address, quantity, writeAddress and values from pdu.
    [[nodiscard]] static ScriptRequest fromPdu(const QByteArray &pdu);
};

} // namespace mbscope
