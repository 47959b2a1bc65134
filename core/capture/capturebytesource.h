#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QString>

class QIODevice;

namespace mbscope {

// The bytes of a capture file seen through a window: the readers ask for the next n bytes
// (a record or block header, then its body) and move on. From a device it keeps one buffer of
// about a megabyte (more only for a larger block), so reading a capture of any size takes
// about that much memory; from memory it reads in place.
class CaptureByteSource
{
public:
    explicit CaptureByteSource(QByteArrayView memory);
    explicit CaptureByteSource(QIODevice *device);

    // The next n bytes from offset() on, or nullptr when the source ends first (remaining()
    // then says how many bytes are left). The pointer is valid until the next peek or advance.
    [[nodiscard]] const uchar *peek(qsizetype n);
    void advance(qsizetype n);
    [[nodiscard]] qint64 offset() const { return m_offset; }
    // Bytes from offset() to the end, as far as known (a device's size, or what was read).
    [[nodiscard]] qint64 remaining();
    [[nodiscard]] bool atEnd() { return remaining() <= 0; }
    [[nodiscard]] qint64 size() const { return m_size; }
    // The device's read error, empty when none.
    [[nodiscard]] const QString &error() const { return m_error; }

private:
    bool fill(qsizetype n);

    QByteArrayView m_memory;
    QIODevice *m_device = nullptr;
    QByteArray m_buffer;
    qsizetype m_position = 0; // of offset() in m_buffer
    qint64 m_offset = 0;
    qint64 m_size = 0;
    bool m_deviceEnded = false;
    QString m_error;
};

} // namespace mbscope
