#include "sim/simtrafficrecord.h"

namespace mbscope {

QByteArray SimTrafficRecord::sentBytes() const
{
    if (!plan)
        return entry.response;
    if (isDropped())
        return {};
    QByteArray sent;
    for (const ResponseChunk &chunk : plan->chunks)
        sent += chunk.bytes;
    return sent;
}

qint64 SimTrafficRecord::delayNs() const
{
    qint64 total = 0;
    if (plan) {
        for (const ResponseChunk &chunk : plan->chunks)
            total += chunk.delayNs;
    }
    return total;
}

} // namespace mbscope
