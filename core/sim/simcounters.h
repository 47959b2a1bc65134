#pragma once

#include <QtCore/QtGlobal>

namespace mbscope {

// The diagnostic counters of one unit (V1.1b3, 6.8.1 sub-functions 0B-12, and 6.9 for the comm
// event counter). All counters are 16-bit and wrap; sub-function 0A (and 01 restart) clear them.
struct SimCounters {
    quint16 busMessages = 0;        // 0B: messages the unit saw on the bus (any unit id, not CRC-bad)
    quint16 busCommErrors = 0;      // 0C: CRC/LRC errors (counted by the endpoint)
    quint16 exceptionErrors = 0;    // 0D: exception responses returned
    quint16 serverMessages = 0;     // 0E: messages addressed to this unit (or broadcast)
    quint16 serverNoResponse = 0;   // 0F: messages to which it sent no response (broadcasts...)
    quint16 serverNak = 0;          // 10: NAK exceptions (07) returned
    quint16 serverBusy = 0;         // 11: Server Device Busy exceptions (06) returned
    quint16 busCharacterOverrun = 0; // 12: character overruns (counted by the endpoint)
    quint16 commEventCounter = 0;   // 0B (function): successful message completions (V1.1b3 6.9)

    void clear() { *this = SimCounters{}; }
};

} // namespace mbscope
