#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QByteArrayView>
#include <QtCore/QObject>

namespace mbscope {

class DirectSocketNotifier;

// A plain TCP client connection of the simulator, read and written on its descriptor directly.
// QTcpSocket costs each answer more than the answer itself: an ioctl(FIONREAD) before every read
// and, for every write, its write notifier enabled and disabled again (with Qt's GLib dispatcher,
// two wake-ups of the event loop: two more write() calls). Under 50 libmodbus clients that was
// six system calls per request against libmodbus's server's three (issue 15); here it is one
// recv() and one send(). TLS connections keep their QSslSocket (SimConnection).
//
// Writes go out at once; what the kernel cannot take yet waits for the descriptor to be writable,
// in order. Owns the descriptor (closed by close() or the destructor).
class SimTcpStream : public QObject
{
    Q_OBJECT
public:
    // fd: a connected, non-blocking stream socket, taken over.
    explicit SimTcpStream(int fd, QObject *parent = nullptr);
    ~SimTcpStream() override;

    [[nodiscard]] bool isOpen() const { return m_fd >= 0; }
    // Everything the kernel holds for us now (empty when nothing). *ended: the peer closed its
    // side (or the connection failed) after these bytes.
    [[nodiscard]] QByteArray readAll(bool *ended);
    // Sends bytes now, or in order once the descriptor is writable. False when the connection
    // is lost (disconnected() follows from the event loop, never inside this call).
    bool write(QByteArrayView bytes);
    // Closes once what is written has left (at once when nothing waits), then disconnected().
    void closeAfterWrites();

Q_SIGNALS:
    void readyRead();
    // The connection is closed: by closeAfterWrites(), or lost (the peer reset it, a write failed).
    void disconnected();

private:
    class Notifier;
    void onWritable();
    void closeNow();

    int m_fd = -1;
    Notifier *m_readNotifier;  // children: they move with the stream to another thread
    Notifier *m_writeNotifier;
    QByteArray m_unsent;
    QByteArray m_buffer; // reused by every read
    bool m_closeWhenSent = false;
};

} // namespace mbscope
