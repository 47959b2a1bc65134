#include "tcplink.h"

#include "directsocketnotifier.h"
#include "monotonicclock.h"
#include "reverselistener.h"
#include "time/duration.h"

#include <QtNetwork/QHostAddress>
#include <QtNetwork/QTcpSocket>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>
#include <utility>

namespace mbscope {

namespace {

// What one recv() may take. A Modbus answer is at most 260 bytes (and a pipelined turn a few
// of them); a larger read is taken by further recv() calls in the same handler.
constexpr qsizetype kReceiveChunk = 64 * 1024;

} // namespace

// The link's read and write notifiers call its handlers directly.
class TcpLink::DescriptorNotifier final : public DirectSocketNotifier
{
public:
    DescriptorNotifier(Type type, TcpLink *link, void (TcpLink::*handler)())
        : DirectSocketNotifier(type, link)
        , m_link(link)
        , m_handler(handler)
    {
    }

    void activate() override { (m_link->*m_handler)(); }

private:
    TcpLink *m_link;
    void (TcpLink::*m_handler)();
};

TcpLink::TcpLink(const LinkUrl &url, QObject *parent)
    : NetworkLink(url, parent)
    , m_readNotifier(new DescriptorNotifier(QSocketNotifier::Read, this, &TcpLink::onReadable))
    , m_writeNotifier(new DescriptorNotifier(QSocketNotifier::Write, this, &TcpLink::onWritable))
{
    m_readNotifier->setEnabled(false);
    m_writeNotifier->setEnabled(false);
}

TcpLink::~TcpLink()
{
    teardown();
}

void TcpLink::startOpen()
{
    if (m_socket)
        return;
    if (const Failure failure = prepare(); failure.kind != LinkError::Kind::None) {
        setState(State::Closed);
        reportError(failure.kind, failure.what);
        return;
    }
    m_submitted = 0;
    m_marks.clear();
    if (url().listen) {
        startWaiting();
        return;
    }
    m_socket = createSocket();
    watchSocket();
    startConnectTimer();
    startConnecting();
}

void TcpLink::watchSocket()
{
    connect(m_socket, &QAbstractSocket::connected, this, &TcpLink::onSocketConnected);
    connect(m_socket, &QIODevice::readyRead, this, &TcpLink::onReadyRead);
    connect(m_socket, &QAbstractSocket::errorOccurred, this, &TcpLink::onSocketError);
    connect(m_socket, &QAbstractSocket::disconnected, this, &TcpLink::onDisconnected);
    connect(m_socket, &QIODevice::bytesWritten, this, [this] {
        if (!m_inWrite)
            reportWritten();
    });
}

void TcpLink::onSocketConnected()
{
    m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    noteEndpoints(*m_socket);
    onTcpConnected();
}

QTcpSocket *TcpLink::createSocket()
{
    return new QTcpSocket(this);
}

void TcpLink::startConnecting()
{
    m_socket->connectToHost(url().host, url().port);
}

void TcpLink::onTcpConnected()
{
    if (takeDescriptor())
        establish();
}

bool TcpLink::takeDescriptor()
{
    const int socketFd = int(m_socket->socketDescriptor());
    // F_DUPFD_CLOEXEC: the duplicate shares the connection and its non-blocking mode; closing
    // the QTcpSocket's descriptor then only drops that reference (no FIN, no RST).
    const int fd = socketFd >= 0 ? ::fcntl(socketFd, F_DUPFD_CLOEXEC, 0) : -1;
    if (fd < 0) {
        const QString os = osAnswer(qt_error_string(errno));
        fail({LinkError::Kind::Io, QStringLiteral("connected to %1, but its descriptor could not be duplicated (%2)").arg(where(), os)});
        return false;
    }
    m_where = where();
    QTcpSocket *socket = std::exchange(m_socket, nullptr);
    disconnect(socket, nullptr, this, nullptr);
    // We are inside the socket's connected() signal: it closes its descriptor now and goes later.
    socket->abort();
    socket->deleteLater();
    m_fd = fd;
    m_unsent.clear();
    if (!m_recvBuffer)
        m_recvBuffer = std::make_unique<char[]>(kReceiveChunk);
    m_readNotifier->setSocket(fd);
    m_writeNotifier->setSocket(fd); // stays disabled until a write is left unfinished
    m_readNotifier->setEnabled(true);
    return true;
}

qintptr TcpLink::socketDescriptor() const
{
    if (m_fd >= 0)
        return m_fd;
    return m_socket ? m_socket->socketDescriptor() : -1;
}

void TcpLink::establish()
{
    stopConnectTimer();
    setState(State::Open);
    Q_EMIT opened();
}

void TcpLink::teardown()
{
    stopConnectTimer();
    m_awaitingDevice = false;
    if (m_listener)
        m_listener->setInUse(false);
    m_marks.clear();
    m_where.clear();
    if (m_fd >= 0) {
        // Disabled before the descriptor closes (the notifiers may be the caller: they stay).
        m_readNotifier->setEnabled(false);
        m_writeNotifier->setEnabled(false);
        m_unsent.clear();
        // An orderly close: the kernel sends what it holds, then FIN.
        ::close(std::exchange(m_fd, -1));
    }
    if (!m_socket)
        return;
    QTcpSocket *socket = m_socket;
    m_socket = nullptr;
    disconnect(socket, nullptr, this, nullptr);
    // An orderly close (FIN, TLS close_notify) when nothing is left to send; the destructor aborts
    // whatever is still pending.
    socket->disconnectFromHost();
    socket->deleteLater();
}

void TcpLink::closeOnRequest()
{
    // A reverse link lets go of its device's connection without ending it: the next open() takes
    // it again (TLS cannot hand its session over: it closes).
    if (m_listener && m_fd >= 0) {
        m_readNotifier->setEnabled(false);
        m_writeNotifier->setEnabled(false);
        m_unsent.clear();
        m_listener->park(std::exchange(m_fd, -1));
    }
    teardown();
}

void TcpLink::fail(const Failure &failure)
{
    teardown();
    setState(State::Closed);
    reportError(failure.kind, failure.what);
}

bool TcpLink::write(const QByteArray &bytes)
{
    if (refuseWriteWhenListening(bytes.size()))
        return false;
    if (state() != State::Open || (!m_socket && m_fd < 0)) {
        reportError(LinkError::Kind::Closed,
                    QStringLiteral("cannot write %1 bytes: the link is not open").arg(bytes.size()));
        return false;
    }
    if (m_fd >= 0)
        return writeToDescriptor(bytes);
    const qint64 written = m_socket->write(bytes);
    if (written != bytes.size()) {
        reportError(LinkError::Kind::Io, QStringLiteral("writing %1 bytes to %2 failed (%3)")
                                             .arg(bytes.size())
                                             .arg(where(), osAnswer(m_socket->errorString())));
        return false;
    }
    m_submitted += written;
    m_marks.append(m_submitted);
    // Hand the bytes to the kernel now rather than at the next turn of the event loop, so that the
    // request leaves and is timestamped without that delay.
    m_inWrite = true;
    m_socket->flush();
    m_inWrite = false;
    if (!m_socket)
        return false; // the flush met an error, already reported
    reportWritten();
    return true;
}

bool TcpLink::writeToDescriptor(const QByteArray &bytes)
{
    QByteArrayView rest(bytes);
    if (m_unsent.isEmpty()) {
        // The request's time is the clock read just before the send() that hands its last byte to
        // the kernel: the kernel puts the segment on the wire (loopback: through the capture
        // point) inside that call, and the call's return can come much later (on one core the
        // server may run, and even answer, before the client is scheduled again).
        const qint64 sentNs = monotonicNowNs();
        const qint64 sent = sendNow(rest);
        if (sent < 0) {
            loseDescriptor(errno);
            return false;
        }
        m_submitted += sent;
        if (sent == rest.size()) {
            deliverWritten(sentNs);
            return true;
        }
        rest = rest.sliced(sent);
    }
    // The kernel's buffer is full: the rest leaves when the descriptor is writable again, and the
    // write is reported once it has.
    m_unsent.append(rest.data(), rest.size());
    m_submitted += rest.size();
    m_marks.append(m_submitted);
    m_writeNotifier->setEnabled(true);
    return true;
}

void TcpLink::onWritable()
{
    if (m_fd < 0)
        return;
    const qint64 sent = sendNow(m_unsent);
    if (sent < 0) {
        loseDescriptor(errno);
        return;
    }
    m_unsent.remove(0, sent);
    if (m_unsent.isEmpty())
        m_writeNotifier->setEnabled(false);
    reportWritten();
}

qint64 TcpLink::sendNow(QByteArrayView bytes)
{
    for (;;) {
        // MSG_NOSIGNAL: a closed peer is an error to report, not a SIGPIPE.
        const ssize_t n = ::send(m_fd, bytes.data(), size_t(bytes.size()), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n >= 0)
            return qint64(n);
        if (errno == EAGAIN || errno == EWOULDBLOCK)
            return 0;
        if (errno != EINTR)
            return -1;
    }
}

void TcpLink::onReadable()
{
    if (m_fd < 0)
        return;
    // The clock first, then the bytes: they were all there when it was read.
    const qint64 now = monotonicNowNs();
    // One buffer for every read: no allocation per answer unless a receiver keeps the bytes (then
    // the next read detaches it).
    m_readBuffer.resize(0);
    int lost = -1; // errno of a failed recv(), 0 at the end of the stream
    for (;;) {
        const ssize_t n = ::recv(m_fd, m_recvBuffer.get(), size_t(kReceiveChunk), MSG_DONTWAIT);
        if (n > 0) {
            m_readBuffer.append(m_recvBuffer.get(), qsizetype(n));
            if (n < kReceiveChunk)
                break;
            continue; // maybe more
        }
        if (n == 0)
            lost = 0;
        else if (errno == EINTR)
            continue;
        else if (errno != EAGAIN && errno != EWOULDBLOCK)
            lost = errno;
        break;
    }
    if (!m_readBuffer.isEmpty()) {
        // Shared while the receivers run, so a read nested in them detaches instead of changing
        // these bytes under them.
        const QByteArray bytes = m_readBuffer;
        deliverReceived(bytes, now, now);
    }
    // The bytes that came before the end are delivered first: a server that closes mid-frame
    // has still sent them. (A receiver may have closed the link meanwhile.)
    if (lost >= 0 && m_fd >= 0 && state() == State::Open)
        loseDescriptor(lost);
}

void TcpLink::loseDescriptor(int err)
{
    Failure failure;
    switch (err) {
    case 0:
        failure = {LinkError::Kind::Closed, QStringLiteral("%1 closed the connection").arg(where())};
        break;
    case ECONNRESET:
    case EPIPE:
        failure = {LinkError::Kind::Closed,
                   QStringLiteral("%1 reset the connection (%2)").arg(where(), osAnswer(qt_error_string(err)))};
        break;
    default:
        failure = {LinkError::Kind::Io,
                   QStringLiteral("connection to %1 lost (%2)").arg(where(), osAnswer(qt_error_string(err)))};
        break;
    }
    teardown();
    reportLoss(failure.kind, failure.what);
}

qint64 TcpLink::acceptedBytes() const
{
    if (m_fd >= 0)
        return m_submitted - m_unsent.size();
    return m_socket ? m_submitted - m_socket->bytesToWrite() : 0;
}

void TcpLink::reportWritten()
{
    if ((!m_socket && m_fd < 0) || m_marks.isEmpty())
        return;
    const qint64 accepted = acceptedBytes();
    const qint64 now = monotonicNowNs();
    while (!m_marks.isEmpty() && m_marks.first() <= accepted) {
        m_marks.removeFirst();
        deliverWritten(now);
    }
}

void TcpLink::onReadyRead()
{
    if (!m_socket)
        return;
    // Qt has just read the socket into its buffer and signalled: the clock first, then the bytes.
    const qint64 now = monotonicNowNs();
    const qint64 available = m_socket->bytesAvailable();
    if (available <= 0)
        return;
    // One buffer for every read: no allocation per answer unless a receiver keeps the bytes (then
    // the next read detaches it).
    m_readBuffer.resize(available);
    const qint64 n = m_socket->read(m_readBuffer.data(), available);
    if (n <= 0)
        return;
    m_readBuffer.resize(n);
    // Shared while the receivers run, so a read nested in them (an error handler's) detaches
    // instead of changing these bytes under them.
    const QByteArray bytes = m_readBuffer;
    deliverReceived(bytes, now, now);
}

QString TcpLink::where() const
{
    if (!m_where.isEmpty())
        return m_where;
    if (url().listen) {
        if (m_socket && !m_socket->peerAddress().isNull())
            return QStringLiteral("the device at ") + endpointText(m_socket->peerAddress(), m_socket->peerPort());
        return QStringLiteral("the device");
    }
    QString text = url().address();
    if (m_socket && !m_socket->peerAddress().isNull()) {
        const QString peer = m_socket->peerAddress().toString();
        if (peer != url().host)
            text += QStringLiteral(" (") + peer + QLatin1Char(')');
    }
    return text;
}

TcpLink::Failure TcpLink::describe(QAbstractSocket::SocketError error, bool opening) const
{
    using Kind = LinkError::Kind;
    const QString os = osAnswer(m_socket ? m_socket->errorString() : QString());
    switch (error) {
    case QAbstractSocket::HostNotFoundError:
        return {Kind::NotFound, QStringLiteral("host '%1' not found (%2)").arg(url().host, os)};
    case QAbstractSocket::ConnectionRefusedError:
        return {Kind::Refused, QStringLiteral("connection refused by %1: the host answered, but nothing listens on port %2 (%3)")
                                   .arg(where())
                                   .arg(url().port)
                                   .arg(os)};
    case QAbstractSocket::SocketTimeoutError:
        return {Kind::Timeout, QStringLiteral("%1 did not answer in time (%2)").arg(where(), os)};
    case QAbstractSocket::RemoteHostClosedError:
        // Qt 6 maps a reset (ECONNRESET, EPIPE) to the same error as an orderly close, so the
        // message names both.
        return {Kind::Closed, opening ? QStringLiteral("%1 closed or reset the connection while it was being opened").arg(where())
                                      : QStringLiteral("%1 closed or reset the connection").arg(where())};
    case QAbstractSocket::NetworkError:
        return {Kind::Io, opening ? QStringLiteral("cannot reach %1 (%2)").arg(where(), os)
                                  : QStringLiteral("connection to %1 lost (%2)").arg(where(), os)};
    default:
        return {Kind::Io, opening ? QStringLiteral("cannot connect to %1 (%2)").arg(where(), os)
                                  : QStringLiteral("connection to %1 failed (%2)").arg(where(), os)};
    }
}

void TcpLink::onSocketError(QAbstractSocket::SocketError error)
{
    if (!m_socket)
        return;
    if (state() == State::Opening) {
        fail(describe(error, true));
        return;
    }
    // Bytes that came before the end are delivered first: a server that closes mid-frame has
    // still sent them.
    if (m_socket->bytesAvailable() > 0)
        onReadyRead();
    if (!m_socket || state() != State::Open)
        return;
    const Failure failure = describe(error, false);
    teardown();
    reportLoss(failure.kind, failure.what);
}

void TcpLink::onDisconnected()
{
    if (!m_socket)
        return;
    if (state() == State::Opening) {
        fail({LinkError::Kind::Closed, QStringLiteral("%1 closed the connection while it was being opened").arg(where())});
        return;
    }
    if (m_socket->bytesAvailable() > 0)
        onReadyRead();
    if (!m_socket || state() != State::Open)
        return;
    const QString what = QStringLiteral("%1 closed the connection").arg(where());
    teardown();
    reportLoss(LinkError::Kind::Closed, what);
}

void TcpLink::onConnectTimeout()
{
    const int ms = url().connectTimeoutMs;
    if (!m_socket && url().listen) {
        fail({LinkError::Kind::Timeout,
              QStringLiteral("no device connected to %1 within %2 (connect timeout): the device must connect to this address "
                             "and port")
                  .arg(url().address(), formatDuration(qint64(ms) * Duration::Millisecond))});
        return;
    }
    if (!m_socket)
        return;
    QString what;
    switch (m_socket->state()) {
    case QAbstractSocket::HostLookupState:
        what = QStringLiteral("looking up host '%1' took longer than %2 ms (connect timeout)").arg(url().host).arg(ms);
        break;
    case QAbstractSocket::ConnectedState:
        what = QStringLiteral("connected to %1, but the TLS handshake did not finish within %2 ms (connect timeout)")
                   .arg(where())
                   .arg(ms);
        break;
    default:
        what = QStringLiteral("no connection to %1 within %2 ms (connect timeout): the host did not answer")
                   .arg(where())
                   .arg(ms);
        break;
    }
    fail({LinkError::Kind::Timeout, what});
}

} // namespace mbscope

#include "moc_tcplink.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
