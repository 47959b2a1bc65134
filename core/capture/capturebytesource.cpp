#include "capturebytesource.h"

#include <QtCore/QIODevice>

#include <cstring>

namespace mbscope {

namespace {
constexpr qsizetype kReadSize = 1 << 20;
}

CaptureByteSource::CaptureByteSource(QByteArrayView memory) : m_memory(memory), m_size(memory.size()) {}

CaptureByteSource::CaptureByteSource(QIODevice *device) : m_device(device), m_size(device->size()) {}

const uchar *CaptureByteSource::peek(qsizetype n)
{
    if (!m_device) {
        if (m_offset + n > m_memory.size())
            return nullptr;
        return reinterpret_cast<const uchar *>(m_memory.data()) + m_offset;
    }
    if (m_buffer.size() - m_position < n && !fill(n))
        return nullptr;
    return reinterpret_cast<const uchar *>(m_buffer.constData()) + m_position;
}

void CaptureByteSource::advance(qsizetype n)
{
    m_offset += n;
    if (m_device)
        m_position += n;
}

qint64 CaptureByteSource::remaining()
{
    if (!m_device)
        return m_memory.size() - m_offset;
    if (m_buffer.size() == m_position && !m_deviceEnded)
        fill(1);
    // A pipe or a file still growing may hold more than its size said: what was read counts.
    return std::max<qint64>(m_size - m_offset, m_buffer.size() - m_position);
}

bool CaptureByteSource::fill(qsizetype n)
{
    const qsizetype kept = m_buffer.size() - m_position;
    if (m_position > 0) {
        std::memmove(m_buffer.data(), m_buffer.constData() + m_position, std::size_t(kept));
        m_buffer.resize(kept);
        m_position = 0;
    }
    while (m_buffer.size() < n && !m_deviceEnded) {
        const qsizetype want = std::max(n - m_buffer.size(), kReadSize);
        const qsizetype before = m_buffer.size();
        m_buffer.resize(before + want);
        const qint64 got = m_device->read(m_buffer.data() + before, want);
        if (got < 0) {
            m_error = m_device->errorString();
            m_deviceEnded = true;
            m_buffer.resize(before);
            break;
        }
        m_buffer.resize(before + qsizetype(got));
        if (got == 0)
            m_deviceEnded = true;
    }
    return m_buffer.size() >= n;
}

} // namespace mbscope
