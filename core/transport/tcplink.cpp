#include "tcplink.h"

#include "monotonicclock.h"

#include <QtNetwork/QHostAddress>
#include <QtNetwork/QTcpSocket>

#include <cerrno>
#include <sys/socket.h>

namespace mbscope {

TcpLink::TcpLink(const LinkUrl &url, QObject *parent)
    : Link(url, parent)
    , m_connectTimer(this) // a child, so that moveToThread() takes it along
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, &TcpLink::onConnectTimeout);
}

TcpLink::~TcpLink()
{
    teardown();
}

void TcpLink::open()
{
    if (state() != State::Closed)
        return;
    setState(State::Opening);
    // Opening goes on after open() returns, so that every outcome is signalled the same way.
    QMetaObject::invokeMethod(this, &TcpLink::startOpen, Qt::QueuedConnection);
}

void TcpLink::startOpen()
{
    if (state() != State::Opening || m_socket)
        return;
    if (const Failure failure = prepare(); failure.kind != LinkError::Kind::None) {
        setState(State::Closed);
        reportError(failure.kind, failure.what);
        return;
    }
    m_socket = createSocket();
    m_submitted = 0;
    m_marks.clear();
    connect(m_socket, &QAbstractSocket::connected, this, [this] {
        m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        onTcpConnected();
    });
    connect(m_socket, &QIODevice::readyRead, this, &TcpLink::onReadyRead);
    connect(m_socket, &QAbstractSocket::errorOccurred, this, &TcpLink::onSocketError);
    connect(m_socket, &QAbstractSocket::disconnected, this, &TcpLink::onDisconnected);
    connect(m_socket, &QIODevice::bytesWritten, this, [this] {
        if (!m_inWrite)
            reportWritten();
    });
    m_connectTimer.start(url().connectTimeoutMs);
    startConnecting();
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
    establish();
}

void TcpLink::establish()
{
    m_connectTimer.stop();
    setState(State::Open);
    emit opened();
}

void TcpLink::close()
{
    if (state() == State::Closed)
        return;
    teardown();
    setClosed(QStringLiteral("closed on request"));
}

void TcpLink::teardown()
{
    m_connectTimer.stop();
    m_marks.clear();
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

void TcpLink::fail(const Failure &failure)
{
    teardown();
    setState(State::Closed);
    reportError(failure.kind, failure.what);
}

bool TcpLink::write(const QByteArray &bytes)
{
    if (state() != State::Open || !m_socket) {
        reportError(LinkError::Kind::Closed,
                    QStringLiteral("cannot write %1 bytes: the link is not open").arg(bytes.size()));
        return false;
    }
    QByteArrayView rest(bytes);
    if (writesToDescriptor() && m_marks.isEmpty() && m_socket->bytesToWrite() == 0) {
        // The request's time is the clock read just before the send() that hands its last byte to
        // the kernel: the kernel puts the segment on the wire (loopback: through the capture
        // point) inside that call, and the call's return can come much later (on one core the
        // server may run, and even answer, before the client is scheduled again).
        const qint64 sentNs = monotonicNowNs();
        const qint64 sent = sendNow(rest);
        if (sent == rest.size()) {
            m_submitted += sent;
            deliverWritten(sentNs);
            return true;
        }
        // Partly taken (the kernel's buffer is full) or refused: Qt's buffer and error handling
        // take the rest, and the write is reported once it has left.
        if (sent > 0) {
            m_submitted += sent;
            rest = rest.sliced(sent);
        }
    }
    const qint64 written = m_socket->write(rest.data(), rest.size());
    if (written != rest.size()) {
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

qint64 TcpLink::sendNow(QByteArrayView bytes)
{
    const int fd = int(m_socket->socketDescriptor());
    if (fd < 0)
        return 0;
    for (;;) {
        // MSG_NOSIGNAL: a closed peer is an error to report, not a SIGPIPE.
        const ssize_t n = ::send(fd, bytes.data(), size_t(bytes.size()), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n >= 0)
            return qint64(n);
        if (errno != EINTR)
            return 0;
    }
}

qint64 TcpLink::acceptedBytes() const
{
    return m_socket ? m_submitted - m_socket->bytesToWrite() : 0;
}

void TcpLink::reportWritten()
{
    if (!m_socket || m_marks.isEmpty())
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
    if (state() != State::Opening || !m_socket)
        return;
    const int ms = url().connectTimeoutMs;
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
