// 03 Read Holding Registers and 04 Read Input Registers (MODBUS Application Protocol
// Specification V1.1b3, 6.3 and 6.4): request start address + quantity (1-125); response byte
// count (2 x quantity) + registers.
#include "pduchecks.h"
#include "quantitylimits.h"
#include "pdudissector.h"

namespace mbscope::pdu {

using namespace checks;

void dissectReadRegisters(const PduContext &ctx)
{
    constexpr int kMaxRegisters = QuantityLimits::kReadRegisters; // V1.1b3 6.3/6.4
    if (isResponse(ctx))
        registerReadResponse(ctx, "quantity", "byte count and register values");
    else
        startAndQuantity(ctx, kMaxRegisters);
}

} // namespace mbscope::pdu
