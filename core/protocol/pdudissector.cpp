#include "pdudissector.h"

#include "functioncode.h"

namespace mbscope::pdu {

void dissect(const PduContext &ctx)
{
    if (ctx.length <= 0) {
        const int f = ctx.add("modbus.function_code", "Function code", 0, 0);
        ctx.tree.flag(f, Severity::Error, QStringLiteral("missing: the PDU is empty, a function code byte was expected"));
        return;
    }
    const quint8 code = ctx.function();
    const FunctionKind kind = functionKind(code);
    const quint8 base = kind == FunctionKind::Exception ? quint8(code & 0x7F) : code;
    const int f = ctx.add("modbus.function_code", "Function code", 0, 1, code, ValueFormat::Hex,
                          kind == FunctionKind::Exception ? "Exception response" : functionName(code));
    if (kind == FunctionKind::Exception) {
        dissectException(ctx);
        return;
    }
    if (ctx.hasRequest() && ctx.direction == Direction::Response && ctx.requestByte(0) != base) {
        ctx.tree.flag(f, Severity::Error,
                      QStringLiteral("does not match the request: the request's function code is 0x%1")
                          .arg(ctx.requestByte(0), 2, 16, QLatin1Char('0')).toUpper().replace(QStringLiteral("0X"), QStringLiteral("0x")));
    }
    switch (base) {
    case 0x01: case 0x02: dissectReadBits(ctx); return;
    case 0x03: case 0x04: dissectReadRegisters(ctx); return;
    case 0x05: dissectWriteSingleCoil(ctx); return;
    case 0x06: dissectWriteSingleRegister(ctx); return;
    case 0x07: dissectReadExceptionStatus(ctx); return;
    case 0x08: dissectDiagnostics(ctx); return;
    case 0x0B: dissectCommEventCounter(ctx); return;
    case 0x0C: dissectCommEventLog(ctx); return;
    case 0x0F: dissectWriteMultipleCoils(ctx); return;
    case 0x10: dissectWriteMultipleRegisters(ctx); return;
    case 0x11: dissectReportServerId(ctx); return;
    case 0x14: dissectReadFileRecord(ctx); return;
    case 0x15: dissectWriteFileRecord(ctx); return;
    case 0x16: dissectMaskWriteRegister(ctx); return;
    case 0x17: dissectReadWriteRegisters(ctx); return;
    case 0x18: dissectReadFifoQueue(ctx); return;
    case 0x2B: dissectEncapsulatedInterface(ctx); return;
    default: break;
    }
    if (kind == FunctionKind::UserDefined) {
        ctx.tree.flag(f, Severity::Info, QStringLiteral("user-defined function code (65-72, 100-110): its data is shown raw"));
    } else if (kind == FunctionKind::Reserved) {
        ctx.tree.flag(f, Severity::Warning, QStringLiteral("reserved function code: the Modbus specification reserves it for legacy products"));
    } else {
        ctx.tree.flag(f, Severity::Warning, QStringLiteral("unassigned public function code: the Modbus specification does not define it"));
    }
    dissectRawData(ctx);
}

void dissectRawData(const PduContext &ctx)
{
    if (ctx.length > 1)
        ctx.add("modbus.data", "Data", 1, ctx.length - 1, 0, ValueFormat::Bytes);
}

void dissectException(const PduContext &ctx)
{
    const quint8 base = ctx.function() & 0x7F;
    const int f = ctx.tree.size() - 1; // the function code field just added
    if (functionKind(base) != FunctionKind::Public) {
        ctx.tree.flag(f, Severity::Warning,
                      QStringLiteral("exception for function 0x%1, which is not a public function code")
                          .arg(QString::number(base, 16).toUpper().rightJustified(2, QLatin1Char('0'))));
    }
    ctx.add("modbus.request_function_code", "Function in error", 0, 1, base, ValueFormat::Hex, functionName(base));
    if (ctx.hasRequest() && ctx.requestByte(0) != base) {
        ctx.tree.flag(ctx.tree.size() - 1, Severity::Error,
                      QStringLiteral("does not match the request: the request's function code is 0x%1")
                          .arg(QString::number(ctx.requestByte(0), 16).toUpper().rightJustified(2, QLatin1Char('0'))));
    }
    if (ctx.direction == Direction::Request) {
        ctx.tree.flag(f, Severity::Error, QStringLiteral("an exception code (0x80 set) can only appear in a response"));
    }
    if (!ctx.has(1)) {
        const int e = ctx.add("modbus.exception_code", "Exception code", 1, 0);
        ctx.tree.flag(e, Severity::Error, QStringLiteral("missing: an exception response carries one exception code byte"));
        return;
    }
    const quint8 code = ctx.byte(1);
    const int e = ctx.add("modbus.exception_code", "Exception code", 1, 1, code, ValueFormat::Hex, exceptionMeaning(code));
    if (!isKnownException(code))
        ctx.tree.flag(e, Severity::Warning, QStringLiteral("not an exception code the specification defines (0x01-0x08, 0x0A, 0x0B)"));
    if (ctx.length > 2) {
        const int t = ctx.add("modbus.trailing", "Unexpected bytes", 2, ctx.length - 2, 0, ValueFormat::Bytes);
        ctx.tree.flag(t, Severity::Error,
                      QStringLiteral("%1 bytes after the exception code; an exception PDU is exactly 2 bytes").arg(ctx.length - 2));
    }
}

} // namespace mbscope::pdu
