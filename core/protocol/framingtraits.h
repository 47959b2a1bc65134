#pragma once

#include "framing.h"

namespace mbscope {

// What each framing adds to a PDU and how, in one table (docs/architecture.md, core/protocol):
// code that needs to know whether a framing is a serial line's, carries an MBAP header, how long
// its frames may be or what its check is called asks here instead of switching on Framing.
struct FramingTraits {
    const char *title;      // "RTU", "ASCII", "Modbus TCP", "Modbus UDP", "PDU", "Frame" (Auto)
    // RTU and ASCII: one master on a line, unit 0 is a broadcast nobody answers (Serial Line
    // V1.02, 2.2), an answer is matched by unit and function, not by a transaction id.
    bool serialLine;
    bool mbap;              // TCP and UDP: the MBAP header, answers matched by transaction id
    int headerBytes;        // bytes before the PDU once decoded: MBAP 7, RTU and ASCII 1 (the unit)
    int checkBytes;         // bytes after the PDU once decoded: RTU 2 (CRC-16), ASCII 1 (LRC), 0
    const char *checkName;  // "CRC", "LRC", or nullptr
    // The largest frame (V1.1b3 4.1; Serial Line V1.02 2.5.1.1 and 2.5.2.1; TCP/IP V1.0b 4.1):
    // in bytes as the frame travels (ASCII: characters), the rule in words and its clause.
    int maxFrameBytes;
    const char *maxFrameRule;
    const char *maxFrameClause;
};

[[nodiscard]] const FramingTraits &framingTraits(Framing framing);
[[nodiscard]] inline bool isSerialLine(Framing framing) { return framingTraits(framing).serialLine; }

} // namespace mbscope
