#pragma once

#include "streamframer.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <bitset>

namespace mbscope {

// Checksum after the end byte of a delimited frame (?framing=delimited&checksum=...).
enum class DelimitedChecksum : quint8 {
    None,
    Sum, // BCC: the low byte of the sum of the bytes from the start byte to the end byte
    Xor, // the XOR of the same bytes
};

// A non-Modbus framing on any stream or serial link: frames run from a start byte to an end byte,
// optionally followed by one checksum byte (LG Master-K: ENQ ... EOT + BCC; home-made ASCII
// protocols: '$' ... '#'). Either end may be one of several bytes: a Master-K answer begins with
// ACK or NAK and ends with ETX (?start=06,15&end=03).
struct DelimitedFraming {
    bool enabled = false;
    QByteArray startBytes;         // any of these begins a frame; empty: frames run from the previous end
    QByteArray endBytes{1, '\n'}; // any of these ends a frame
    DelimitedChecksum checksum = DelimitedChecksum::None;
    bool textDisplay = true; // show frames as text (true) or hex

    friend bool operator==(const DelimitedFraming &, const DelimitedFraming &) = default;
};

// Frames of a delimited framing cut out of a byte stream ("the start byte" below: any of the
// start bytes, and so for the end).
// - With a start byte, bytes before it are skipped (NoFrameStart); a start byte inside a frame
//   restarts it and the abandoned part is skipped (Abandoned), as a lost end byte would leave it.
//   Without a start byte, a frame runs from the byte after the previous frame to the end byte.
// - A frame ends at the end byte, or one byte later when a checksum byte follows it. That byte is
//   taken as it is (it may equal the start or end byte). The checksum covers the bytes from the
//   start byte (or the frame's first byte) to the end byte, both included, as LG Master-K's BCC.
// - A frame whose ends were found is always emitted: Valid, or Malformed with the wrong checksum
//   said. kMaxFrameSize bytes without an end are skipped (TooLong).
// The bytes between the delimiters are not interpreted: text or binary, the framing does not know.
class DelimitedFramer final : public StreamFramer
{
public:
    static constexpr int kMaxFrameSize = 4096;

    explicit DelimitedFramer(const DelimitedFraming &framing);

    [[nodiscard]] const DelimitedFraming &framing() const { return m_framing; }

    // The checksum of bytes as the framing computes it (0 for None).
    [[nodiscard]] static quint8 checksum(DelimitedChecksum kind, QByteArrayView bytes);
    // Appends the checksum byte when the framing has one: a frame from start to end made complete.
    [[nodiscard]] static QByteArray complete(const DelimitedFraming &framing, QByteArrayView frame);
    // Frame bytes for a person: printable ASCII as it is, control characters by name ("<ENQ>",
    // "<EOT>", "<CR>"), other bytes as "\xHH". "$01 293 295 #" stays as it is.
    [[nodiscard]] static QString toText(QByteArrayView bytes);
    [[nodiscard]] static QString checksumName(DelimitedChecksum kind); // "none", "sum", "xor"

protected:
    void process() override;
    void resetState() override { m_scanned = 0; }

private:
    void emitChecked(qsizetype length);

    DelimitedFraming m_framing;
    std::bitset<256> m_isStart;
    std::bitset<256> m_isEnd;
    qsizetype m_scanned = 0; // pending bytes of the open frame already searched for the end byte
};

} // namespace mbscope
