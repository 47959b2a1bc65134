#pragma once

#include <QtCore/QtGlobal>

#include <array>

namespace mbscope {

// When the bytes of a stream arrived, chunk by chunk (one link read each, with the times of its
// first and last byte), so that a frame or a skipped run cut out later gets the time of its own
// first and last byte. Keeps the most recent kCapacity chunks; older offsets get the oldest time
// kept (a frame longer than that many reads is timed from its last reads).
class ChunkStamps
{
public:
    static constexpr int kCapacity = 512;

    void add(qint64 offset, qint64 size, qint64 firstNs, qint64 lastNs);
    void clear() { m_count = 0; }

    // When the byte at this stream offset arrived: the chunk's first-byte time for its first byte,
    // its last-byte time for the others (a read does not say when the bytes between came).
    [[nodiscard]] qint64 firstNs(qint64 offset) const;
    // When the byte at this offset had surely arrived: its chunk's last-byte time.
    [[nodiscard]] qint64 lastNs(qint64 offset) const;

private:
    struct Chunk {
        qint64 offset = 0;
        qint64 size = 0;
        qint64 firstNs = 0;
        qint64 lastNs = 0;
    };
    [[nodiscard]] const Chunk *find(qint64 offset) const;

    std::array<Chunk, kCapacity> m_chunks{};
    int m_head = 0;  // next slot to write
    int m_count = 0;
};

} // namespace mbscope
