#include "asciiframer.h"

#include "hexformat.h"

namespace mbscope {

AsciiFramer::AsciiFramer(char endCharacter)
    : m_end(endCharacter)
{
}

void AsciiFramer::process()
{
    for (;;) {
        const QByteArrayView bytes = pending();
        if (bytes.isEmpty())
            return;
        if (bytes[0] != ':') {
            const qsizetype start = bytes.indexOf(':');
            skip(start < 0 ? bytes.size() : start, SkipReason::NoFrameStart);
            continue;
        }
        bool decided = false;
        for (qsizetype i = qMax<qsizetype>(1, m_scanned); i < bytes.size() && !decided; ++i) {
            const char c = bytes[i];
            if (c == ':') {
                skip(i, SkipReason::Abandoned);
                decided = true;
            } else if (c == m_end) {
                emitChecked(i + 1);
                decided = true;
            } else if (i + 1 >= kMaxFrameSize) {
                skip(i + 1, SkipReason::TooLong);
                decided = true;
            }
        }
        if (!decided) {
            m_scanned = bytes.size();
            return;
        }
        m_scanned = 0;
    }
}

void AsciiFramer::emitChecked(qsizetype length)
{
    const QByteArrayView frame = pending().first(length);
    const bool hasCr = length >= 3 && frame[length - 2] == '\r';
    const qsizetype digitsEnd = hasCr ? length - 2 : length - 1;
    const qsizetype digits = digitsEnd - 1;

    // One pass: check the digits and sum the bytes; with the LRC included the sum is 0 (2.5.2.1).
    QString problem;
    quint8 sum = 0;
    quint8 lastByte = 0;
    for (qsizetype i = 1; i < digitsEnd; i += 2) {
        const int high = hexDigitValue(frame[i]);
        const int low = i + 1 < digitsEnd ? hexDigitValue(frame[i + 1]) : 0;
        if (high < 0 || low < 0) {
            const qsizetype bad = high < 0 ? i : i + 1;
            problem = QStringLiteral("character %1 (%2) is not a hex digit").arg(bad).arg(hexByte(quint8(frame[bad])));
            break;
        }
        lastByte = quint8(high << 4 | low);
        sum = quint8(sum + lastByte);
    }
    if (problem.isEmpty()) {
        if (!hasCr)
            problem = QStringLiteral("no CR before the end character");
        else if (digits % 2 != 0)
            problem = QStringLiteral("odd number of hex digits (%1)").arg(digits);
        else if (digits < 6)
            problem = QStringLiteral("%1 hex digits: a frame needs at least 6 (unit id, function code, LRC)")
                          .arg(digits);
        else if (sum != 0)
            problem = QStringLiteral("LRC %1 does not match %2 computed over the unit id and PDU")
                          .arg(hexByte(lastByte), hexByte(quint8(lastByte - sum)));
    }
    emitFrame(length, problem.isEmpty() ? FrameStatus::Valid : FrameStatus::Malformed, problem);
}

} // namespace mbscope
