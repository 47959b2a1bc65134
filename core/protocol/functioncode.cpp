#include "functioncode.h"

namespace mbscope {

FunctionKind functionKind(quint8 code)
{
    if (code >= 0x80)
        return FunctionKind::Exception;
    switch (code) {
    case 0x01: case 0x02: case 0x03: case 0x04: case 0x05: case 0x06: case 0x07: case 0x08:
    case 0x0B: case 0x0C: case 0x0F: case 0x10: case 0x11: case 0x14: case 0x15: case 0x16:
    case 0x17: case 0x18: case 0x2B:
        return FunctionKind::Public;
    // V1.1b3, 5.1 and Annex A: reserved function codes.
    case 0x09: case 0x0A: case 0x0D: case 0x0E: case 0x29: case 0x2A: case 0x5A: case 0x5B:
    case 0x7D: case 0x7E: case 0x7F:
        return FunctionKind::Reserved;
    default:
        break;
    }
    if ((code >= 65 && code <= 72) || (code >= 100 && code <= 110))
        return FunctionKind::UserDefined;
    return FunctionKind::Unassigned;
}

const char *functionName(quint8 code)
{
    switch (code) {
    case 0x01: return "Read Coils";
    case 0x02: return "Read Discrete Inputs";
    case 0x03: return "Read Holding Registers";
    case 0x04: return "Read Input Registers";
    case 0x05: return "Write Single Coil";
    case 0x06: return "Write Single Register";
    case 0x07: return "Read Exception Status";
    case 0x08: return "Diagnostics";
    case 0x0B: return "Get Comm Event Counter";
    case 0x0C: return "Get Comm Event Log";
    case 0x0F: return "Write Multiple Coils";
    case 0x10: return "Write Multiple Registers";
    case 0x11: return "Report Server ID";
    case 0x14: return "Read File Record";
    case 0x15: return "Write File Record";
    case 0x16: return "Mask Write Register";
    case 0x17: return "Read/Write Multiple Registers";
    case 0x18: return "Read FIFO Queue";
    case 0x2B: return "Encapsulated Interface Transport";
    default: break;
    }
    switch (functionKind(code)) {
    case FunctionKind::UserDefined: return "User-defined function";
    case FunctionKind::Reserved: return "Reserved function code";
    case FunctionKind::Exception: return "Exception response";
    default: return "Unassigned function code";
    }
}

const char *exceptionName(quint8 code)
{
    switch (code) {
    case 0x01: return "Illegal Function";
    case 0x02: return "Illegal Data Address";
    case 0x03: return "Illegal Data Value";
    case 0x04: return "Server Device Failure";
    case 0x05: return "Acknowledge";
    case 0x06: return "Server Device Busy";
    case 0x07: return "Negative Acknowledge";
    case 0x08: return "Memory Parity Error";
    case 0x0A: return "Gateway Path Unavailable";
    case 0x0B: return "Gateway Target Device Failed to Respond";
    default: return "Unknown exception code";
    }
}

const char *exceptionMeaning(quint8 code)
{
    switch (code) {
    case 0x01:
        return "Illegal Function: the function code is not supported by the device, or not allowed in its current state";
    case 0x02:
        return "Illegal Data Address: the address range is not available in the device";
    case 0x03:
        return "Illegal Data Value: a value in the request is not allowed, such as a quantity or length out of range";
    case 0x04:
        return "Server Device Failure: an unrecoverable error occurred while the device was performing the action";
    case 0x05:
        return "Acknowledge: the device accepted the request but needs a long time to process it; poll it later";
    case 0x06:
        return "Server Device Busy: the device is processing a long-duration command; retry later";
    case 0x07:
        return "Negative Acknowledge: the device cannot perform the program function (legacy Modicon code)";
    case 0x08:
        return "Memory Parity Error: the device found a parity error in its extended file memory (function 20/21)";
    case 0x0A:
        return "Gateway Path Unavailable: the gateway could not allocate a path to the target, it is misconfigured or overloaded";
    case 0x0B:
        return "Gateway Target Device Failed to Respond: the gateway got no answer from the target device";
    case 0x09:
        return "Unassigned exception code: 0x09 is not defined by the Modbus specification";
    default:
        return "Unknown exception code: the Modbus specification defines 0x01-0x08, 0x0A and 0x0B";
    }
}

bool isKnownException(quint8 code)
{
    return (code >= 0x01 && code <= 0x08) || code == 0x0A || code == 0x0B;
}

} // namespace mbscope
