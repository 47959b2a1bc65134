#pragma once

#include "streamframer.h"

namespace mbscope {

// MBAP frames (Modbus TCP, and Modbus UDP when datagrams are fed one by one) cut out by the
// header's length field (MODBUS Messaging on TCP/IP V1.0b, 3.1.3). A header is valid when the
// protocol id is 0 and the length, which counts the unit id and the PDU, is 2..254 (a PDU is at
// most 253 bytes, V1.1b3 4.1). On an invalid header one byte is skipped and the header looked for
// again at the next byte; the skipped bytes are reported as one InvalidHeader run.
//
// After restartAfterGap() the next byte may be anywhere in a frame, and register values full of
// zeros easily look like a header, so a start is trusted only when its header is plausible (also
// a function code 01..7F, or an exception 81..FF) and the bytes after its frame begin a plausible
// header too; a silence (flushOnSilence: the other side speaking, the connection closing) confirms
// a candidate that ends exactly at the last byte. Bytes passed over are one AfterGap run.
class MbapFramer final : public StreamFramer
{
public:
    static constexpr int kHeaderSize = 7;
    static constexpr int kMinLength = 2;
    static constexpr int kMaxLength = 254;

    [[nodiscard]] bool isSearching() const override { return m_searching; }

protected:
    void process() override;
    void resetState() override { m_searching = false; }
    void startSearch() override { m_searching = true; }
    void flushPending() override;

private:
    [[nodiscard]] bool search();

    bool m_searching = false;
};

} // namespace mbscope
