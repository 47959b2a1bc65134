#include "mbapframer.h"

namespace mbscope {

void MbapFramer::process()
{
    for (;;) {
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
