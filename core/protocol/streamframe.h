#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtCore/qglobal.h>

namespace mbscope {

// What a stream framer could verify about a frame it cut out of a byte stream.
enum class FrameStatus : quint8 {
    Valid,      // boundaries verified: MBAP header and length, RTU length rule and CRC, ASCII digits and LRC
    Unverified, // RTU only: a code without a length rule, ended by a silence, CRC not matching
    Truncated,  // RTU only: the silence came before the length that the function code predicts
    Malformed,  // ASCII only: ':' ... CR LF found, but bad digits, odd digit count, too short or wrong LRC
};

// Why bytes were skipped instead of being framed.
enum class SkipReason : quint8 {
    NoFrameStart,       // ASCII: bytes outside ':' ... CR LF
    InvalidHeader,      // MBAP: protocol id not 0 or length outside 2..254
    ChecksumMismatch,   // RTU: the frame the length rule predicted has a wrong CRC
    ImpossibleFunction, // RTU: a function code that cannot start a frame in this direction
    NoLengthRule,       // RTU: a code without a length rule met while resynchronising
    Abandoned,          // ASCII: a ':' inside a frame restarted it
    TooLong,            // ASCII: 513 characters without CR LF; RTU: 256 bytes without a valid CRC
    Incomplete,         // bytes of an unfinished frame dropped at a silence
    AfterGap,           // after lost bytes (a capture's gap): the rest of the frame they cut, up to the next frame
};

[[nodiscard]] const char *skipReasonName(SkipReason reason);

// A frame cut out of a stream. Timestamps are those given to feed() with the chunks holding the
// first and the last byte (0 when none were given).
struct StreamFrame {
    QByteArray bytes;
    qint64 offset = 0; // stream offset of the first byte (bytes fed since construction or reset)
    qint64 firstByteNs = 0;
    qint64 lastByteNs = 0;
    FrameStatus status = FrameStatus::Valid;
    QString problem; // empty when Valid
};

// A run of bytes that no frame could use: consecutive skipped bytes with the same reason, or all
// the bytes of one RTU resynchronisation (with the reason of the first), at most 256 bytes
// (longer runs are split, so that garbage is reported while it lasts).
struct SkippedBytes {
    QByteArray bytes;
    qint64 offset = 0;
    SkipReason reason = SkipReason::NoFrameStart;
    [[nodiscard]] qsizetype count() const { return bytes.size(); }
};

} // namespace mbscope
