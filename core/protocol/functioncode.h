#pragma once

#include <QtCore/qglobal.h>

namespace mbscope {

// Public function codes (MODBUS Application Protocol Specification V1.1b3, 5.1 and 6).
enum class FunctionCode : quint8 {
    ReadCoils = 0x01,
    ReadDiscreteInputs = 0x02,
    ReadHoldingRegisters = 0x03,
    ReadInputRegisters = 0x04,
    WriteSingleCoil = 0x05,
    WriteSingleRegister = 0x06,
    ReadExceptionStatus = 0x07,
    Diagnostics = 0x08,
    GetCommEventCounter = 0x0B,
    GetCommEventLog = 0x0C,
    WriteMultipleCoils = 0x0F,
    WriteMultipleRegisters = 0x10,
    ReportServerId = 0x11,
    ReadFileRecord = 0x14,
    WriteFileRecord = 0x15,
    MaskWriteRegister = 0x16,
    ReadWriteMultipleRegisters = 0x17,
    ReadFifoQueue = 0x18,
    EncapsulatedInterfaceTransport = 0x2B,
};

// Exception codes (V1.1b3, 7). 07 and 09 are not in V1.1b3's table; 07 is Modicon's legacy
// Negative Acknowledge, 09 is unassigned.
enum class ExceptionCode : quint8 {
    IllegalFunction = 0x01,
    IllegalDataAddress = 0x02,
    IllegalDataValue = 0x03,
    ServerDeviceFailure = 0x04,
    Acknowledge = 0x05,
    ServerDeviceBusy = 0x06,
    NegativeAcknowledge = 0x07,
    MemoryParityError = 0x08,
    GatewayPathUnavailable = 0x0A,
    GatewayTargetNoResponse = 0x0B,
};

enum class FunctionKind : quint8 {
    Invalid,     // 0: not a function code at all (V1.1b3, 4.1: valid codes are 1-255)
    Public,      // defined by the spec and decoded field by field
    UserDefined, // 65-72 and 100-110 (V1.1b3, 5.1): shown as raw data
    Reserved,    // reserved for legacy products or other uses (9, 10, 13, 14, 41, 42, 90, 91, 125-127)
    Unassigned,  // a public code the spec leaves unassigned
    Exception,   // 0x80 + function code: an exception response
};

[[nodiscard]] FunctionKind functionKind(quint8 code);
// "Read Holding Registers"; for kinds other than Public a description of the kind.
[[nodiscard]] const char *functionName(quint8 code);
// "Illegal Data Address"; "Unknown exception code" for codes outside 01-0B.
[[nodiscard]] const char *exceptionName(quint8 code);
// "Illegal Data Address: the address range is not available in the device"
[[nodiscard]] const char *exceptionMeaning(quint8 code);
[[nodiscard]] bool isKnownException(quint8 code);

} // namespace mbscope
