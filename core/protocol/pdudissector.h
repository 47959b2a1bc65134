#pragma once

#include "pducontext.h"

namespace mbscope::pdu {

// Appends the fields of one PDU (function code, then its data) to ctx.tree. Never throws and
// never reads outside [ctx.offset, ctx.offset + ctx.length): a PDU that is short, too long or
// inconsistent gets every field that is present plus fields flagged with what is wrong.
void dissect(const PduContext &ctx);

// One function per family; each is called with the function code field already added.
// Data access (pdudataaccess*.cpp)
void dissectReadBits(const PduContext &ctx);             // 01, 02
void dissectReadRegisters(const PduContext &ctx);        // 03, 04
void dissectWriteSingleCoil(const PduContext &ctx);      // 05
void dissectWriteSingleRegister(const PduContext &ctx);  // 06
void dissectWriteMultipleCoils(const PduContext &ctx);   // 0F
void dissectWriteMultipleRegisters(const PduContext &ctx); // 10
void dissectReadFileRecord(const PduContext &ctx);       // 14
void dissectWriteFileRecord(const PduContext &ctx);      // 15
void dissectMaskWriteRegister(const PduContext &ctx);    // 16
void dissectReadWriteRegisters(const PduContext &ctx);   // 17
void dissectReadFifoQueue(const PduContext &ctx);        // 18
// Diagnostics and others (pdudiagnostics*.cpp, pdumisc*.cpp)
void dissectReadExceptionStatus(const PduContext &ctx);  // 07
void dissectDiagnostics(const PduContext &ctx);          // 08
void dissectCommEventCounter(const PduContext &ctx);     // 0B
void dissectCommEventLog(const PduContext &ctx);         // 0C
void dissectReportServerId(const PduContext &ctx);       // 11
void dissectEncapsulatedInterface(const PduContext &ctx); // 2B (0E device identification, 0D raw)
void dissectRawData(const PduContext &ctx);              // user-defined, reserved, unassigned codes
void dissectException(const PduContext &ctx);            // 0x80 + code

} // namespace mbscope::pdu
