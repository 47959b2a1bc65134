#include "functioncode.h"

#include "functionspec.h"

namespace mbscope {

FunctionKind functionKind(quint8 code)
{
    // V1.1b3, 4.1: "Valid codes are in the range of 1 ... 255 decimal"; 0 is none of them.
    if (code == 0x00)
        return FunctionKind::Invalid;
    if (code >= 0x80)
        return FunctionKind::Exception;
    if (functionSpec(code))
        return FunctionKind::Public;
    switch (code) {
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
    if (const FunctionSpec *spec = functionSpec(code))
        return spec->name;
    switch (functionKind(code)) {
    case FunctionKind::UserDefined: return QT_TRANSLATE_NOOP("mbscope::Field", "User-defined function");
    case FunctionKind::Reserved: return QT_TRANSLATE_NOOP("mbscope::Field", "Reserved function code");
    case FunctionKind::Exception: return QT_TRANSLATE_NOOP("mbscope::Field", "Exception response");
    case FunctionKind::Invalid: return QT_TRANSLATE_NOOP("mbscope::Field", "Invalid function code");
    default: return QT_TRANSLATE_NOOP("mbscope::Field", "Unassigned function code");
    }
}

const char *exceptionName(quint8 code)
{
    switch (code) {
    case 0x01: return QT_TRANSLATE_NOOP("mbscope::Field", "Illegal Function");
    case 0x02: return QT_TRANSLATE_NOOP("mbscope::Field", "Illegal Data Address");
    case 0x03: return QT_TRANSLATE_NOOP("mbscope::Field", "Illegal Data Value");
    case 0x04: return QT_TRANSLATE_NOOP("mbscope::Field", "Server Device Failure");
    case 0x05: return QT_TRANSLATE_NOOP("mbscope::Field", "Acknowledge");
    case 0x06: return QT_TRANSLATE_NOOP("mbscope::Field", "Server Device Busy");
    case 0x07: return QT_TRANSLATE_NOOP("mbscope::Field", "Negative Acknowledge");
    case 0x08: return QT_TRANSLATE_NOOP("mbscope::Field", "Memory Parity Error");
    case 0x0A: return QT_TRANSLATE_NOOP("mbscope::Field", "Gateway Path Unavailable");
    case 0x0B: return QT_TRANSLATE_NOOP("mbscope::Field", "Gateway Target Device Failed to Respond");
    default: return QT_TRANSLATE_NOOP("mbscope::Field", "Unknown exception code");
    }
}

const char *exceptionMeaning(quint8 code)
{
    switch (code) {
    case 0x01:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Illegal Function: the function code is not supported by the device, or not allowed in its current state");
    case 0x02:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Illegal Data Address: the address range is not available in the device");
    case 0x03:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Illegal Data Value: a value in the request is not allowed, such as a quantity or length out of range");
    case 0x04:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Server Device Failure: an unrecoverable error occurred while the device was performing the action");
    case 0x05:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Acknowledge: the device accepted the request but needs a long time to process it; poll it later");
    case 0x06:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Server Device Busy: the device is processing a long-duration command; retry later");
    case 0x07:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Negative Acknowledge: the device cannot perform the program function (legacy Modicon code)");
    case 0x08:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Memory Parity Error: the device found a parity error in its extended file memory (function 20/21)");
    case 0x0A:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Gateway Path Unavailable: the gateway could not allocate a path to the target, it is misconfigured or overloaded");
    case 0x0B:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Gateway Target Device Failed to Respond: the gateway got no answer from the target device");
    case 0x09:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Unassigned exception code: 0x09 is not defined by the Modbus specification");
    default:
        return QT_TRANSLATE_NOOP("mbscope::Field", "Unknown exception code: the Modbus specification defines 0x01-0x08, 0x0A and 0x0B");
    }
}

bool isKnownException(quint8 code)
{
    return (code >= 0x01 && code <= 0x08) || code == 0x0A || code == 0x0B;
}

} // namespace mbscope
