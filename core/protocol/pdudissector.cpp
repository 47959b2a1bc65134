#include "pdudissector.h"

#include "functioncode.h"
#include "hexformat.h"
#include "pduchecks.h"

#include <cstring>

namespace mbscope::pdu {

namespace {

// Modicon references number the four tables from 1: 0xxxx coils, 1xxxx discrete inputs,
// 3xxxx input registers, 4xxxx holding registers. The five-digit form reaches PDU address
// 9998 (reference x9999), the six-digit form the whole 0-65535 range.
void addReferences(const PduContext &ctx, quint8 function, int first)
{
    int table = -1;
    const char *meaning = nullptr;
    switch (function) {
    case 0x01: case 0x05: case 0x0F:
        table = 0;
        meaning = QT_TRANSLATE_NOOP("mbscope::Field", "(coil 0xxxx, numbered from 1: PDU address + 1)");
        break;
    case 0x02:
        table = 1;
        meaning = QT_TRANSLATE_NOOP("mbscope::Field", "(discrete input 1xxxx, numbered from 1: PDU address + 1)");
        break;
    case 0x04:
        table = 3;
        meaning = QT_TRANSLATE_NOOP("mbscope::Field", "(input register 3xxxx, numbered from 1: PDU address + 1)");
        break;
    case 0x03: case 0x06: case 0x10: case 0x16: case 0x17:
        table = 4;
        meaning = QT_TRANSLATE_NOOP("mbscope::Field", "(holding register 4xxxx, numbered from 1: PDU address + 1)");
        break;
    default:
        return;
    }
    // Address fields sit in the fixed header (PDU offsets 1-6: 17's write address is at 5), so
    // the scan stops there instead of comparing keys on every register value.
    const int end = ctx.tree.size();
    for (int i = first; i < end; ++i) {
        const Field &f = ctx.tree.at(i);
        if (f.offset > ctx.offset + 6)
            break;
        if (f.length != 2 || f.severity == Severity::Error)
            continue;
        const char *key = f.key;
        if (std::strcmp(key, "modbus.start_address") != 0 && std::strcmp(key, "modbus.address") != 0
            && std::strcmp(key, "modbus.read_start_address") != 0 && std::strcmp(key, "modbus.write_start_address") != 0)
            continue;
        const quint64 address = f.value;
        const bool five = address <= 9998;
        const quint64 reference = quint64(table) * (five ? 10000 : 100000) + address + 1;
        ctx.tree.add(i, "modbus.reference", QT_TRANSLATE_NOOP("mbscope::Field", "Modicon reference"), f.offset, 2, reference,
                     five ? ValueFormat::Reference5 : ValueFormat::Reference6, meaning);
    }
}

} // namespace

void dissect(const PduContext &ctx)
{
    if (ctx.length <= 0) {
        const int f = ctx.add("modbus.function_code", QT_TRANSLATE_NOOP("mbscope::Field", "Function code"), 0, 0);
        ctx.tree.flag(f, Severity::Error, QStringLiteral("missing: the PDU is empty, a function code byte was expected"));
        return;
    }
    const quint8 code = ctx.function();
    const FunctionKind kind = functionKind(code);
    const quint8 base = kind == FunctionKind::Exception ? quint8(code & 0x7F) : code;
    const int f = ctx.add("modbus.function_code", QT_TRANSLATE_NOOP("mbscope::Field", "Function code"), 0, 1, code, ValueFormat::Hex,
                          kind == FunctionKind::Exception ? QT_TRANSLATE_NOOP("mbscope::Field", "Exception response") : functionName(code));
    if (kind == FunctionKind::Exception) {
        dissectException(ctx);
        return;
    }
    if (ctx.hasRequest() && ctx.direction == Direction::Response && ctx.requestByte(0) != base) {
        ctx.tree.flag(f, Severity::Error,
                      QStringLiteral("does not match the request: the request's function code is %1")
                          .arg(hexByte(ctx.requestByte(0))));
    }
    const int first = ctx.tree.size();
    bool handled = true;
    switch (base) {
    case 0x01: case 0x02: dissectReadBits(ctx); break;
    case 0x03: case 0x04: dissectReadRegisters(ctx); break;
    case 0x05: dissectWriteSingleCoil(ctx); break;
    case 0x06: dissectWriteSingleRegister(ctx); break;
    case 0x07: dissectReadExceptionStatus(ctx); return;
    case 0x08: dissectDiagnostics(ctx); return;
    case 0x0B: dissectCommEventCounter(ctx); return;
    case 0x0C: dissectCommEventLog(ctx); return;
    case 0x0F: dissectWriteMultipleCoils(ctx); break;
    case 0x10: dissectWriteMultipleRegisters(ctx); break;
    case 0x11: dissectReportServerId(ctx); return;
    case 0x14: dissectReadFileRecord(ctx); return;
    case 0x15: dissectWriteFileRecord(ctx); return;
    case 0x16: dissectMaskWriteRegister(ctx); break;
    case 0x17: dissectReadWriteRegisters(ctx); break;
    case 0x18: dissectReadFifoQueue(ctx); return;
    case 0x2B: dissectEncapsulatedInterface(ctx); return;
    default:
        handled = false;
        break;
    }
    if (handled) {
        addReferences(ctx, base, first);
        return;
    }
    if (kind == FunctionKind::UserDefined) {
        ctx.tree.flag(f, Severity::Info, QStringLiteral("user-defined function code (65-72, 100-110): its data is shown raw"));
    } else if (kind == FunctionKind::Reserved) {
        ctx.tree.flag(f, Severity::Warning, QStringLiteral("reserved function code: the Modbus specification reserves it for legacy products"));
    } else if (kind == FunctionKind::Invalid) {
        ctx.tree.flag(f, Severity::Error, QStringLiteral("function code 0 is not valid: valid codes are 1-255 (MODBUS Application Protocol V1.1b3, 4.1)"));
    } else {
        ctx.tree.flag(f, Severity::Warning, QStringLiteral("unassigned public function code: the Modbus specification does not define it"));
    }
    dissectRawData(ctx);
}

void dissectRawData(const PduContext &ctx)
{
    checks::rawData(ctx, 1);
}

// An exception response (V1.1b3, 7): the function code with bit 7 set, then one exception code.
void dissectException(const PduContext &ctx)
{
    const quint8 base = ctx.function() & 0x7F;
    const int f = ctx.tree.size() - 1; // the function code field just added
    switch (functionKind(base)) {
    case FunctionKind::Public:
        break;
    case FunctionKind::UserDefined:
        // A device may well reject its own user-defined functions with an exception.
        ctx.tree.flag(f, Severity::Info,
                      QStringLiteral("exception for user-defined function %1 (65-72, 100-110)").arg(hexByte(base)));
        break;
    case FunctionKind::Reserved:
        ctx.tree.flag(f, Severity::Warning,
                      QStringLiteral("exception for function %1, a reserved function code").arg(hexByte(base)));
        break;
    case FunctionKind::Invalid:
        ctx.tree.flag(f, Severity::Error,
                      QStringLiteral("exception for function 0x00, which is not a valid function code (V1.1b3, 4.1: valid codes are 1-255)"));
        break;
    default:
        ctx.tree.flag(f, Severity::Warning,
                      QStringLiteral("exception for function %1, which the specification does not assign").arg(hexByte(base)));
        break;
    }
    const int r = ctx.add("modbus.request_function_code", QT_TRANSLATE_NOOP("mbscope::Field", "Function in error"), 0, 1, base, ValueFormat::Hex, functionName(base));
    if (ctx.hasRequest() && ctx.requestByte(0) != base) {
        ctx.tree.flag(r, Severity::Error,
                      QStringLiteral("does not match the request: the request's function code is %1, the exception is for %2")
                          .arg(hexByte(ctx.requestByte(0)), hexByte(base)));
    }
    if (ctx.direction == Direction::Request) {
        ctx.tree.flag(f, Severity::Error, QStringLiteral("an exception code (0x80 set) can only appear in a response"));
    }
    static const checks::Slot layout[] = {
        {"modbus.exception_code", QT_TRANSLATE_NOOP("mbscope::Field", "Exception code"), 1, ValueFormat::Hex, "exception code"},
    };
    int e = -1;
    if (!checks::addFixed(ctx, ctx.parent, 1, layout, 1, &e, 2, false))
        return;
    const quint8 code = ctx.byte(1);
    ctx.tree.setMeaning(e, exceptionMeaning(code));
    if (!isKnownException(code)) {
        ctx.tree.flag(e, Severity::Warning,
                      QStringLiteral("%1 is not an exception code the specification defines (0x01-0x08, 0x0A, 0x0B)")
                          .arg(hexByte(code)));
    } else if (code == 0x07) {
        ctx.tree.flag(e, Severity::Info,
                      QStringLiteral("0x07 Negative Acknowledge is a legacy Modicon code, not in V1.1b3's table (7)"));
    } else if (code == 0x08 && base != 0x14 && base != 0x15) {
        ctx.tree.flag(e, Severity::Info,
                      QStringLiteral("V1.1b3 (7) defines Memory Parity Error for Read/Write File Record (0x14, 0x15), "
                                     "this exception is for %1").arg(hexByte(base)));
    }
    checks::trailing(ctx, 2);
}

} // namespace mbscope::pdu
