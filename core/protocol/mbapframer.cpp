#include "mbapframer.h"

#include <algorithm>

namespace mbscope {

namespace {

constexpr qsizetype kProbeSize = MbapFramer::kHeaderSize + 1; // the header and the function code

// Whether the bytes present (up to kProbeSize) can begin an MBAP frame: protocol id 0, a length
// of 2..254, any transaction id and unit, and a function code that is not 00 or 80.
bool fitsHeader(QByteArrayView bytes)
{
    const qsizetype n = std::min(bytes.size(), kProbeSize);
    for (qsizetype i = 0; i < n; ++i) {
        const quint8 b = quint8(bytes[i]);
        switch (i) {
        case 2:
        case 3:
        case 4:
            if (b != 0)
                return false;
            break;
        case 5:
            if (b < MbapFramer::kMinLength || b > MbapFramer::kMaxLength)
                return false;
            break;
        case 7:
            if ((b & 0x7f) == 0)
                return false;
            break;
        default:
            break;
        }
    }
    return true;
}

qsizetype frameSize(QByteArrayView header)
{
    return 6 + (quint8(header[4]) << 8 | quint8(header[5]));
}

} // namespace

bool MbapFramer::search()
{
    const QByteArrayView bytes = pending();
    if (!fitsHeader(bytes)) {
        skip(1, SkipReason::AfterGap, true);
        return true;
    }
    if (bytes.size() < kProbeSize)
        return false;
    const qsizetype end = frameSize(bytes);
    if (bytes.size() <= end)
        return false;
    const QByteArrayView next = bytes.sliced(end);
    if (!fitsHeader(next)) {
        skip(1, SkipReason::AfterGap, true);
        return true;
    }
    if (next.size() < kProbeSize)
        return false;
    m_searching = false;
    emitFrame(end);
    return true;
}

void MbapFramer::flushPending()
{
    if (!m_searching) {
        StreamFramer::flushPending();
        return;
    }
    while (pendingSize() > 0) {
        const QByteArrayView bytes = pending();
        if (bytes.size() >= kProbeSize && fitsHeader(bytes) && frameSize(bytes) == bytes.size()) {
            m_searching = false;
            emitFrame(bytes.size());
            return;
        }
        skip(1, SkipReason::AfterGap, true);
    }
}

void MbapFramer::process()
{
    for (;;) {
        if (m_searching) {
            if (!search())
                return;
            continue;
        }
        const QByteArrayView bytes = pending();
        // Each header field is judged as soon as it has arrived, so garbage is skipped early; the
        // decision depends only on the bytes, never on how they were chunked.
        if (bytes.size() >= 4 && (bytes[2] != 0 || bytes[3] != 0)) {
            skip(1, SkipReason::InvalidHeader);
            continue;
        }
        if (bytes.size() < 6)
            return;
        const int length = quint8(bytes[4]) << 8 | quint8(bytes[5]);
        if (length < kMinLength || length > kMaxLength) {
            skip(1, SkipReason::InvalidHeader);
            continue;
        }
        if (bytes.size() < 6 + length)
            return;
        emitFrame(6 + length);
    }
}

} // namespace mbscope
