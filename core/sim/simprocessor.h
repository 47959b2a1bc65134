#pragma once

#include "sim/simreply.h"

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>

#include <memory>
#include <optional>

namespace mbscope {

class SimModbusServer;
class SimUnit;

// The request semantics of one unit: a request PDU in, a SimReply out, the unit's data, counters
// and event log updated. Knows nothing of framings: the endpoint strips and adds them.
//
// Function codes 01-06, 0F, 10 and 16 go to Qt SerialBus's QModbusServer::processRequest
// (through SimModbusServer, backed by the unit); the rest is mbscope's: 07, 08 with every
// sub-function and real counters, 0B, 0C, 11, 14, 15, 17, 18 and 2B/0E.
//
// Checks follow the order of the state diagrams of V1.1b3 (6.1-6.21) and its section 7:
// function code not supported -> 01; quantity, byte count or value wrong -> 03; address (or
// address + quantity) outside the unit's ranges -> 02; then the action (failures -> 04).
// Choices the specification leaves open:
// - a write into an address that exists but is read-only gets 02 (the address is not an
//   allowable address for this request, section 7), before anything is written;
// - a request longer than its function code needs gets 03 (its byte count or quantity does
//   not describe it);
// - 18 reads a FIFO without emptying it (the spec does not say it empties it);
// - the comm event counter (0B) counts normal responses except those to 0B and 0C;
// - a unit set busy answers 06 to everything but 08, 0B and 0C, which report the busy state.
class SimProcessor
{
public:
    explicit SimProcessor(SimUnit *unit);
    ~SimProcessor();
    SimProcessor(const SimProcessor &) = delete;
    SimProcessor &operator=(const SimProcessor &) = delete;

    [[nodiscard]] SimUnit *unit() const { return m_unit; }

    // One request addressed to this unit. A broadcast is processed and never answered.
    SimReply process(QByteArrayView pdu, bool broadcast = false);

    // Events seen by the endpoint the unit listens on (V1.1b3 6.8.1 counters, 6.10 event log).
    static void noteBusMessage(SimUnit &unit);
    static void noteCommError(SimUnit &unit);   // CRC/LRC error: counted and logged
    static void noteOverrun(SimUnit &unit);     // more characters than a frame can hold

private:
    SimReply dispatch(quint8 functionCode, QByteArrayView pdu);
    SimReply viaQt(quint8 functionCode, QByteArrayView pdu);
    SimReply readRegisters(quint8 functionCode, QByteArrayView pdu); // 03, 04
    [[nodiscard]] std::optional<SimReply> checkWritable(quint8 functionCode, QByteArrayView pdu) const;
    SimReply readExceptionStatus(QByteArrayView pdu);
    SimReply diagnostics(QByteArrayView pdu);
    SimReply commEventCounter(QByteArrayView pdu);
    SimReply commEventLog(QByteArrayView pdu);
    SimReply reportServerId(QByteArrayView pdu);
    SimReply readFileRecord(QByteArrayView pdu);
    SimReply writeFileRecord(QByteArrayView pdu);
    SimReply readWriteRegisters(QByteArrayView pdu);
    SimReply readFifo(QByteArrayView pdu);
    SimReply encapsulated(QByteArrayView pdu);
    SimReply deviceIdentification(QByteArrayView pdu);
    void account(quint8 functionCode, const SimReply &reply);
    void restart(bool clearEventLog);

    SimUnit *m_unit;
    std::unique_ptr<SimModbusServer> m_server;
    // 08/01 restarts after its answer has left (V1.1b3 6.8.1): the value is "clear the log".
    std::optional<bool> m_pendingRestart;
};

} // namespace mbscope
