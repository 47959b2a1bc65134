#pragma once

#include "streamframer.h"

namespace mbscope {

// ASCII frames (MODBUS over Serial Line V1.02, 2.5.2): ':' starts a frame, CR LF ends it.
// - Bytes outside a frame are skipped (NoFrameStart); a ':' inside a frame restarts it and the
//   abandoned part is skipped (Abandoned); 513 characters without the end are skipped (TooLong).
// - A frame whose ends were found is always emitted, since its boundaries are certain: Valid when
//   it holds an even number (at least 6) of hex digits, CR before LF and a matching LRC; otherwise
//   Malformed, with the first problem said. The dissector then explains it field by field.
// The LF can be replaced by another end character (Diagnostics 08/0003, V1.1b3 6.8.1).
class AsciiFramer final : public StreamFramer
{
public:
    // ':' + 2 * (unit id + 253-byte PDU + LRC) + CR LF (Serial Line V1.02, 2.5.2.1)
    static constexpr int kMaxFrameSize = 513;

    explicit AsciiFramer(char endCharacter = '\n');
    [[nodiscard]] char endCharacter() const { return m_end; }

protected:
    void process() override;
    void resetState() override { m_scanned = 0; }

private:
    void emitChecked(qsizetype length);

    char m_end;
    qsizetype m_scanned = 0; // pending bytes of the open frame already searched for its end
};

} // namespace mbscope
