#include "sim/simtcpstream.h"

#include "transport/directsocketnotifier.h"

#include <algorithm>
#include <cerrno>
#include <utility>
#include <sys/socket.h>
#include <unistd.h>

namespace mbscope {

namespace {

// What one recv() takes. A Modbus request is at most 260 bytes; a client that pipelines sends a
// few at once, and a larger read is taken by further recv() calls in the same turn.
constexpr qsizetype kReceiveChunk = 16 * 1024;

} // namespace

// Calls the stream's handler itself (DirectSocketNotifier), or through activated() under
// another dispatcher.
class SimTcpStream::Notifier final : public DirectSocketNotifier
{
public:
    Notifier(int fd, Type type, SimTcpStream *stream, void (SimTcpStream::*handler)())
        : DirectSocketNotifier(type, stream)
        , m_stream(stream)
        , m_handler(handler)
    {
        setSocket(fd);
    }

    void activate() override
    {
        if (m_handler)
            (m_stream->*m_handler)();
        else
            Q_EMIT m_stream->readyRead();
    }

private:
    SimTcpStream *m_stream;
    void (SimTcpStream::*m_handler)();
};

SimTcpStream::SimTcpStream(int fd, QObject *parent)
    : QObject(parent)
    , m_fd(fd)
    , m_readNotifier(new Notifier(fd, QSocketNotifier::Read, this, nullptr))
    , m_writeNotifier(new Notifier(fd, QSocketNotifier::Write, this, &SimTcpStream::onWritable))
{
    m_writeNotifier->setEnabled(false); // until a write is left unfinished
    m_readNotifier->setEnabled(true);
}

SimTcpStream::~SimTcpStream()
{
    closeNow();
}

QByteArray SimTcpStream::readAll(bool *ended)
{
    *ended = false;
    if (m_fd < 0) {
        *ended = true;
        return {};
    }
    m_buffer.resize(0);
    for (;;) {
        const qsizetype at = m_buffer.size();
        m_buffer.resize(at + kReceiveChunk);
        const ssize_t n = ::recv(m_fd, m_buffer.data() + at, size_t(kReceiveChunk), MSG_DONTWAIT);
        m_buffer.resize(at + std::max<qsizetype>(0, qsizetype(n)));
        if (n == kReceiveChunk)
            continue; // maybe more
        if (n > 0)
            break;
        if (n < 0 && errno == EINTR)
            continue;
        // 0: the peer closed its side; an error other than "nothing more now": the connection
        // is gone (reset).
        *ended = n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK);
        break;
    }
    // Shared with the caller: the next read detaches only if the caller kept the bytes.
    return m_buffer;
}

bool SimTcpStream::write(QByteArrayView bytes)
{
    if (m_fd < 0)
        return false;
    if (m_unsent.isEmpty()) {
        for (;;) {
            // MSG_NOSIGNAL: a closed peer is an error here, not a SIGPIPE.
            const ssize_t n = ::send(m_fd, bytes.data(), size_t(bytes.size()), MSG_NOSIGNAL | MSG_DONTWAIT);
            if (n >= 0) {
                bytes = bytes.sliced(n);
                break;
            }
            if (errno == EINTR)
                continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK)
                break;
            closeNow();
            // Said from the event loop, as QTcpSocket says it: the writer may be the owner's
            // answer queue in the middle of its work.
            QMetaObject::invokeMethod(this, &SimTcpStream::disconnected, Qt::QueuedConnection);
            return false;
        }
        if (bytes.isEmpty())
            return true;
    }
    // The kernel's buffer is full: the rest leaves when the descriptor is writable again.
    m_unsent.append(bytes.data(), bytes.size());
    m_writeNotifier->setEnabled(true);
    return true;
}

void SimTcpStream::onWritable()
{
    if (m_fd < 0)
        return;
    const QByteArray rest = std::exchange(m_unsent, {});
    if (!write(rest))
        return;
    if (m_unsent.isEmpty()) {
        m_writeNotifier->setEnabled(false);
        if (m_closeWhenSent) {
            closeNow();
            Q_EMIT disconnected();
        }
    }
}

void SimTcpStream::closeAfterWrites()
{
    if (m_fd < 0)
        return;
    if (!m_unsent.isEmpty()) {
        m_closeWhenSent = true;
        m_readNotifier->setEnabled(false);
        return;
    }
    closeNow();
    Q_EMIT disconnected();
}

void SimTcpStream::closeNow()
{
    if (m_fd < 0)
        return;
    // Disabled before the descriptor closes (a notifier may be the caller: it stays until the
    // stream goes).
    m_readNotifier->setEnabled(false);
    m_writeNotifier->setEnabled(false);
    m_unsent.clear();
    // An orderly close: the kernel sends what it holds, then FIN.
    ::close(m_fd);
    m_fd = -1;
}

} // namespace mbscope

#include "moc_simtcpstream.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
