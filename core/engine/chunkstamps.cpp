#include "chunkstamps.h"

namespace mbscope {

void ChunkStamps::add(qint64 offset, qint64 size, qint64 firstNs, qint64 lastNs)
{
    if (size <= 0)
        return;
    m_chunks[size_t(m_head)] = Chunk{offset, size, firstNs, lastNs};
    m_head = (m_head + 1) % kCapacity;
    if (m_count < kCapacity)
        ++m_count;
}

const ChunkStamps::Chunk *ChunkStamps::find(qint64 offset) const
{
    // Newest first: frames are cut out of the latest chunks.
    const Chunk *oldest = nullptr;
    for (int i = 0; i < m_count; ++i) {
        const Chunk &c = m_chunks[size_t((m_head - 1 - i + kCapacity) % kCapacity)];
        if (offset >= c.offset && offset < c.offset + c.size)
            return &c;
        oldest = &c;
    }
    return oldest;
}

qint64 ChunkStamps::firstNs(qint64 offset) const
{
    const Chunk *c = find(offset);
    if (!c)
        return 0;
    return offset == c->offset ? c->firstNs : c->lastNs;
}

qint64 ChunkStamps::lastNs(qint64 offset) const
{
    const Chunk *c = find(offset);
    return c ? c->lastNs : 0;
}

} // namespace mbscope
