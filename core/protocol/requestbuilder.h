#pragma once

#include "buildresult.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>

namespace mbscope {

// One sub-request of Read File Record (0x14, V1.1b3 6.14).
struct FileRecordRead {
    int fileNumber = 1;   // 1-65535
    int recordNumber = 0; // 0-9999 (0x270F): a file holds 10000 records
    int recordLength = 1; // registers to read, at least 1
    int referenceType = 6; // must be 6
};

// One sub-request of Write File Record (0x15, V1.1b3 6.15); the record length is values.size().
struct FileRecordWrite {
    int fileNumber = 1;
    int recordNumber = 0;
    QList<quint16> values;
    int referenceType = 6;
};

// Builds request PDUs (function code first) from parameters. Each function checks its
// parameters against the MODBUS Application Protocol Specification V1.1b3 and returns either
// the PDU or every problem found (BuildResult). Scalars are taken as int so that a value typed
// out of range (an address of 70000, a quantity of -1) is reported instead of wrapped.
// To send bytes the specification forbids, on purpose, use raw().
class RequestBuilder
{
public:
    // Data access (V1.1b3, 6.1-6.6, 6.11, 6.12, 6.16-6.18).
    [[nodiscard]] static BuildResult readCoils(int startAddress, int quantity);          // 1-2000
    [[nodiscard]] static BuildResult readDiscreteInputs(int startAddress, int quantity); // 1-2000
    [[nodiscard]] static BuildResult readHoldingRegisters(int startAddress, int quantity); // 1-125
    [[nodiscard]] static BuildResult readInputRegisters(int startAddress, int quantity);   // 1-125
    [[nodiscard]] static BuildResult writeSingleCoil(int address, bool on);
    // An int would silently become true or false: say which coil value is meant instead.
    static BuildResult writeSingleCoil(int address, int value) = delete;
    // value must be 0xFF00 (ON) or 0x0000 (OFF).
    [[nodiscard]] static BuildResult writeSingleCoilValue(int address, int value);
    [[nodiscard]] static BuildResult writeSingleRegister(int address, int value);
    [[nodiscard]] static BuildResult writeMultipleCoils(int startAddress, const QList<bool> &values); // 1-1968
    [[nodiscard]] static BuildResult writeMultipleRegisters(int startAddress, const QList<quint16> &values); // 1-123
    [[nodiscard]] static BuildResult maskWriteRegister(int address, int andMask, int orMask);
    [[nodiscard]] static BuildResult readWriteMultipleRegisters(int readStartAddress, int readQuantity,
                                                                int writeStartAddress,
                                                                const QList<quint16> &writeValues); // 1-125, 1-121
    [[nodiscard]] static BuildResult readFifoQueue(int fifoAddress);
    [[nodiscard]] static BuildResult readFileRecord(const QList<FileRecordRead> &subRequests);
    [[nodiscard]] static BuildResult writeFileRecord(const QList<FileRecordWrite> &subRequests);

    // Serial line diagnostics (V1.1b3, 6.7-6.10, 6.13): these requests carry no data but 08's.
    [[nodiscard]] static BuildResult readExceptionStatus();
    [[nodiscard]] static BuildResult getCommEventCounter();
    [[nodiscard]] static BuildResult getCommEventLog();
    [[nodiscard]] static BuildResult reportServerId();
    // Diagnostics (0x08, V1.1b3 6.8.1) with the data its sub-function prescribes: 00 any whole
    // number of 16-bit words, 01 00 00 or FF 00, 03 CHAR 00, the others 00 00.
    // Sub-functions 05-09, 13 and 21-65535 are reserved and refused.
    [[nodiscard]] static BuildResult diagnostics(int subFunction, const QByteArray &data);
    // The same with the data most sub-functions take: 00 00 (00 takes 00 00 too here).
    [[nodiscard]] static BuildResult diagnostics(int subFunction);
    [[nodiscard]] static BuildResult restartCommunications(bool clearEventLog); // 08/01
    [[nodiscard]] static BuildResult changeAsciiInputDelimiter(int character);  // 08/03

    // Encapsulated Interface Transport (0x2B, V1.1b3 6.19-6.21).
    // readDeviceIdCode: 1 basic, 2 regular, 3 extended (stream access), 4 one object.
    [[nodiscard]] static BuildResult readDeviceIdentification(int readDeviceIdCode, int objectId);
    [[nodiscard]] static BuildResult canopenGeneralReference(const QByteArray &data); // 2B/0D, raw
    [[nodiscard]] static BuildResult encapsulatedInterface(int meiType, const QByteArray &data);

    // User-defined function codes 65-72 and 100-110 (V1.1b3, 5.1) with raw data.
    [[nodiscard]] static BuildResult userDefined(int functionCode, const QByteArray &data);
    // Any function code 0-255 with any data: only the 253-byte PDU limit is enforced.
    [[nodiscard]] static BuildResult raw(int functionCode, const QByteArray &data);
};

} // namespace mbscope
