#pragma once

#include "buildresult.h"
#include "requestbuilder.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>

namespace mbscope {

// One object of a Read Device Identification response (V1.1b3, 6.21): 0x00 VendorName,
// 0x01 ProductCode, 0x02 MajorMinorRevision, 0x03-0x06 regular, 0x80-0xFF private.
struct DeviceIdObject {
    int id = 0;
    QByteArray value; // at most 255 bytes (one length byte)
};

// Builds normal and exception response PDUs (function code first) from values, for the
// simulator and for tests. Like RequestBuilder, each function checks its values against the
// MODBUS Application Protocol Specification V1.1b3 and returns the PDU or every problem found.
// Responses that echo the request (05, 06, 0F, 10, 15, 16) take the request's parameters.
class ResponseBuilder
{
public:
    // Data access (V1.1b3, 6.1-6.6, 6.11, 6.12, 6.14-6.18).
    [[nodiscard]] static BuildResult readCoils(const QList<bool> &values);          // 1-2000
    [[nodiscard]] static BuildResult readDiscreteInputs(const QList<bool> &values); // 1-2000
    [[nodiscard]] static BuildResult readHoldingRegisters(const QList<quint16> &values); // 1-125
    [[nodiscard]] static BuildResult readInputRegisters(const QList<quint16> &values);   // 1-125
    [[nodiscard]] static BuildResult writeSingleCoil(int address, bool on);
    static BuildResult writeSingleCoil(int address, int value) = delete; // see writeSingleCoilValue
    [[nodiscard]] static BuildResult writeSingleCoilValue(int address, int value); // 0xFF00 or 0x0000
    [[nodiscard]] static BuildResult writeSingleRegister(int address, int value);
    [[nodiscard]] static BuildResult writeMultipleCoils(int startAddress, int quantity);     // 1-1968
    [[nodiscard]] static BuildResult writeMultipleRegisters(int startAddress, int quantity); // 1-123
    [[nodiscard]] static BuildResult maskWriteRegister(int address, int andMask, int orMask);
    [[nodiscard]] static BuildResult readWriteMultipleRegisters(const QList<quint16> &readValues); // 1-125
    [[nodiscard]] static BuildResult readFifoQueue(const QList<quint16> &values); // 0-31 queued registers
    // One list of register values per sub-request, in the request's order (1-35 sub-responses).
    [[nodiscard]] static BuildResult readFileRecord(const QList<QList<quint16>> &records);
    [[nodiscard]] static BuildResult writeFileRecord(const QList<FileRecordWrite> &subRequests); // the echo

    // Serial line diagnostics (V1.1b3, 6.7-6.10, 6.13).
    [[nodiscard]] static BuildResult readExceptionStatus(int outputs); // 0-255, output 0 in the low bit
    // Diagnostics (0x08, V1.1b3 6.8.1) with the data its sub-function returns: the echo for 00, 01,
    // 03, 0A and 14; the 16-bit register (02) or counter (0B-12). 04 has no response and is refused.
    [[nodiscard]] static BuildResult diagnostics(int subFunction, const QByteArray &data);
    // The same with a 16-bit data word (value 0-65535).
    [[nodiscard]] static BuildResult diagnosticsValue(int subFunction, int value);
    // Status word 0xFFFF while busy, 0x0000 otherwise (V1.1b3, 6.9).
    [[nodiscard]] static BuildResult getCommEventCounter(bool busy, int eventCount);
    [[nodiscard]] static BuildResult getCommEventLog(bool busy, int eventCount, int messageCount,
                                                     const QByteArray &events); // 0-64 event bytes
    // The server ID's length is device specific (at least one byte); the run indicator is 0xFF
    // (ON) or 0x00 (OFF).
    [[nodiscard]] static BuildResult reportServerId(const QByteArray &serverId, bool running,
                                                    const QByteArray &additionalData = {});

    // Encapsulated Interface Transport (0x2B, V1.1b3 6.19-6.21).
    // conformityLevel: 0x01-0x03 (stream access only) or 0x81-0x83 (stream and individual).
    // nextObjectId must be 0 unless moreFollows; an individual access (code 4) returns one object.
    [[nodiscard]] static BuildResult readDeviceIdentification(int readDeviceIdCode, int conformityLevel,
                                                              bool moreFollows, int nextObjectId,
                                                              const QList<DeviceIdObject> &objects);
    [[nodiscard]] static BuildResult canopenGeneralReference(const QByteArray &data); // 2B/0D, raw
    [[nodiscard]] static BuildResult encapsulatedInterface(int meiType, const QByteArray &data);

    [[nodiscard]] static BuildResult userDefined(int functionCode, const QByteArray &data);
    // functionCode 1-127 (the 0x80 bit is added); any exception code 0-255, so that codes the
    // specification does not define (0x09, 0x0C...) can be simulated too.
    [[nodiscard]] static BuildResult exception(int functionCode, int exceptionCode);
    [[nodiscard]] static BuildResult raw(int functionCode, const QByteArray &data);
};

} // namespace mbscope
