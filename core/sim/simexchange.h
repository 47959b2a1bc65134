#pragma once

#include "protocol/framing.h"
#include "sim/simreply.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// One request and the answer a unit made, as the fault hook (Simulator::setFaultHook, the
// FaultInjector) sees it before anything is sent. The hook returns the FaultPlan the endpoint
// executes; without a hook the plan is responseAdu after responseDelayNs.
struct SimExchange {
    QString endpoint;           // the endpoint's URL as bound ("rtu-tcp://127.0.0.1:4001")
    QString peer;               // "127.0.0.1:53122", a serial device, ...
    Framing framing = Framing::Tcp; // Tcp or Udp (MBAP), Rtu or Ascii
    quint8 unitId = 0;          // as addressed in the request
    // The unit that answers: unitId, or the endpoint's first unit for 0 and 0xFF on MBAP
    // framings (V1.0b 4.4.1.1); every per-unit setting (response delay, fault rules by unit)
    // follows it. unitId when no unit answers (exception 0B).
    quint8 routedUnitId = 0;
    quint16 transactionId = 0;  // MBAP framings
    bool delimited = false;     // a delimited protocol's frame (LineTable), not Modbus
    QByteArray requestAdu;      // the request as received
    QByteArray requestPdu;      // function code first
    SimReply reply;             // the unit's answer (reply.pdu: the response PDU)
    QByteArray responseAdu;     // reply.pdu framed like the request (same unit and transaction id)
    qint64 responseDelayNs = 0; // the unit's response delay
    bool responseDelayFixed = false; // set by the unit's script ({delay: ms}): no distribution drawn over it
    qint64 receivedNs = 0;      // monotonicNowNs() when the request's last byte arrived
    qint64 intervalNs = -1;     // since the previous request arrived on the same endpoint; -1: none
};

} // namespace mbscope
