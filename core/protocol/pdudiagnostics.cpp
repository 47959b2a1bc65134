// Temporary: families shown raw until their dissectors land (being written now).
#include "pdudissector.h"

namespace mbscope::pdu {
void dissectReadExceptionStatus(const PduContext &ctx) { dissectRawData(ctx); }
void dissectDiagnostics(const PduContext &ctx) { dissectRawData(ctx); }
void dissectCommEventCounter(const PduContext &ctx) { dissectRawData(ctx); }
void dissectCommEventLog(const PduContext &ctx) { dissectRawData(ctx); }
void dissectReportServerId(const PduContext &ctx) { dissectRawData(ctx); }
void dissectEncapsulatedInterface(const PduContext &ctx) { dissectRawData(ctx); }
} // namespace mbscope::pdu
