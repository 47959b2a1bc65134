// Temporary: families shown raw until their dissectors land (being written now).
#include "pdudissector.h"

namespace mbscope::pdu {
void dissectReadBits(const PduContext &ctx) { dissectRawData(ctx); }
void dissectReadRegisters(const PduContext &ctx) { dissectRawData(ctx); }
void dissectWriteSingleCoil(const PduContext &ctx) { dissectRawData(ctx); }
void dissectWriteSingleRegister(const PduContext &ctx) { dissectRawData(ctx); }
void dissectWriteMultipleCoils(const PduContext &ctx) { dissectRawData(ctx); }
void dissectWriteMultipleRegisters(const PduContext &ctx) { dissectRawData(ctx); }
void dissectReadFileRecord(const PduContext &ctx) { dissectRawData(ctx); }
void dissectWriteFileRecord(const PduContext &ctx) { dissectRawData(ctx); }
void dissectMaskWriteRegister(const PduContext &ctx) { dissectRawData(ctx); }
void dissectReadWriteRegisters(const PduContext &ctx) { dissectRawData(ctx); }
void dissectReadFifoQueue(const PduContext &ctx) { dissectRawData(ctx); }
} // namespace mbscope::pdu
