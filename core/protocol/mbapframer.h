#pragma once

#include "streamframer.h"

namespace mbscope {

// MBAP frames (Modbus TCP, and Modbus UDP when datagrams are fed one by one) cut out by the
// header's length field (MODBUS Messaging on TCP/IP V1.0b, 3.1.3). A header is valid when the
// protocol id is 0 and the length, which counts the unit id and the PDU, is 2..254 (a PDU is at
// most 253 bytes, V1.1b3 4.1). On an invalid header one byte is skipped and the header looked for
// again at the next byte; the skipped bytes are reported as one InvalidHeader run.
class MbapFramer final : public StreamFramer
{
public:
    static constexpr int kHeaderSize = 7;
    static constexpr int kMinLength = 2;
    static constexpr int kMaxLength = 254;

protected:
    void process() override;
};

} // namespace mbscope
