#include "framingtraits.h"

namespace mbscope {

namespace {

// A PDU is at most 253 bytes (V1.1b3, 4.1), so an RTU ADU at most 256, an MBAP ADU at most 260
// and an ASCII frame (two characters a byte, ':' and CR LF) at most 513 characters.
constexpr FramingTraits kRtu{"RTU", true, false, 1, 2, "CRC", 256, "an RTU ADU is at most 256 bytes",
                             "MODBUS over Serial Line V1.02, 2.5.1.1"};
constexpr FramingTraits kAscii{"ASCII", true, false, 1, 1, "LRC", 513, "an ASCII frame is at most 513 characters",
                               "MODBUS over Serial Line V1.02, 2.5.2.1"};
constexpr FramingTraits kTcp{"Modbus TCP", false, true, 7, 0, nullptr, 260, "an MBAP ADU is at most 260 bytes",
                             "MODBUS Messaging on TCP/IP V1.0b, 4.1"};
constexpr FramingTraits kUdp{"Modbus UDP", false, true, 7, 0, nullptr, 260, "an MBAP ADU is at most 260 bytes",
                             "MODBUS Messaging on TCP/IP V1.0b, 4.1"};
constexpr FramingTraits kPdu{"PDU", false, false, 0, 0, nullptr, 253, "a PDU is at most 253 bytes",
                             "MODBUS Application Protocol V1.1b3, 4.1"};
constexpr FramingTraits kAuto{"Frame", false, false, 0, 0, nullptr, 253, "a PDU is at most 253 bytes",
                              "MODBUS Application Protocol V1.1b3, 4.1"};

} // namespace

const FramingTraits &framingTraits(Framing framing)
{
    switch (framing) {
    case Framing::Rtu: return kRtu;
    case Framing::Ascii: return kAscii;
    case Framing::Tcp: return kTcp;
    case Framing::Udp: return kUdp;
    case Framing::Pdu: return kPdu;
    case Framing::Auto: break;
    }
    return kAuto;
}

} // namespace mbscope
