#include "udplink.h"

#include "monotonicclock.h"

#include <QtNetwork/QHostAddress>
#include <QtNetwork/QUdpSocket>

namespace mbscope {

UdpLink::UdpLink(const LinkUrl &url, QObject *parent)
    : NetworkLink(url, parent)
{
}

UdpLink::~UdpLink()
{
    teardown();
}

void UdpLink::startOpen()
{
    if (m_socket)
        return;
    m_socket = new QUdpSocket(this);
    connect(m_socket, &QAbstractSocket::connected, this, [this] {
        stopConnectTimer();
        noteEndpoints(*m_socket);
        setState(State::Open);
        Q_EMIT opened();
    });
    connect(m_socket, &QIODevice::readyRead, this, &UdpLink::onReadyRead);
    connect(m_socket, &QAbstractSocket::errorOccurred, this, &UdpLink::onSocketError);
    startConnectTimer();
    m_socket->connectToHost(url().host, url().port);
}

void UdpLink::teardown()
{
    stopConnectTimer();
    if (!m_socket)
        return;
    QUdpSocket *socket = m_socket;
    m_socket = nullptr;
    disconnect(socket, nullptr, this, nullptr);
    socket->abort();
    socket->deleteLater();
}

bool UdpLink::write(const QByteArray &bytes)
{
    if (refuseWriteWhenListening(bytes.size()))
        return false;
    if (state() != State::Open || !m_socket) {
        reportError(LinkError::Kind::Closed,
                    QStringLiteral("cannot send %1 bytes: the link is not open").arg(bytes.size()));
        return false;
    }
    // On a connected UDP socket a write is one datagram, sent at once (Qt does not buffer UDP).
    const qint64 sent = m_socket->write(bytes);
    if (sent != bytes.size()) {
        // An error also comes through errorOccurred; say here what was lost.
        reportError(LinkError::Kind::Io, QStringLiteral("sending a %1-byte datagram to %2 failed (%3)")
                                             .arg(bytes.size())
                                             .arg(where(), osAnswer(m_socket->errorString())));
        return false;
    }
    deliverWritten(monotonicNowNs());
    return true;
}

void UdpLink::onReadyRead()
{
    // Bounded: at most what was queued when the handler started plus what comes meanwhile; a
    // socket that keeps failing (an ICMP error pending) ends the loop.
    for (int i = 0; i < 4096 && m_socket && m_socket->hasPendingDatagrams(); ++i) {
        const qint64 size = m_socket->pendingDatagramSize();
        if (size < 0)
            break;
        QByteArray datagram(qMax<qint64>(size, 1), Qt::Uninitialized);
        const qint64 got = m_socket->readDatagram(datagram.data(), datagram.size());
        if (got < 0)
            break;
        // Stamped per datagram, right after it was read: the engine may write the next request
        // from inside bytesReceived, and a datagram queued behind must not carry a time taken
        // before that write (it would be refused as arriving before its request).
        const qint64 now = monotonicNowNs();
        datagram.truncate(got);
        if (!datagram.isEmpty())
            deliverReceived(datagram, now, now);
    }
}

QString UdpLink::where() const
{
    QString text = url().address();
    if (m_socket && !m_socket->peerAddress().isNull()) {
        const QString peer = m_socket->peerAddress().toString();
        if (peer != url().host)
            text += QStringLiteral(" (") + peer + QLatin1Char(')');
    }
    return text;
}

void UdpLink::onSocketError(QAbstractSocket::SocketError error)
{
    if (!m_socket)
        return;
    const QString os = osAnswer(m_socket->errorString());
    using Kind = LinkError::Kind;
    if (state() == State::Opening) {
        const bool notFound = error == QAbstractSocket::HostNotFoundError;
        const QString what = notFound ? QStringLiteral("host '%1' not found (%2)").arg(url().host, os)
                                      : QStringLiteral("cannot open a UDP socket to %1 (%2)").arg(where(), os);
        teardown();
        setState(State::Closed);
        reportError(notFound ? Kind::NotFound : Kind::Io, what);
        return;
    }
    // Once open, errors leave the link open: a datagram that met "port unreachable" does not stop
    // the next one (the device may be starting), and the engine counts the timeouts.
    if (error == QAbstractSocket::ConnectionRefusedError) {
        reportError(Kind::Refused, QStringLiteral("%1 answered 'port unreachable': nothing listens on UDP port %2 (%3)")
                                       .arg(where())
                                       .arg(url().port)
                                       .arg(os));
        return;
    }
    reportError(Kind::Io, QStringLiteral("UDP to %1 failed (%2)").arg(where(), os));
}

void UdpLink::onConnectTimeout()
{
    if (!m_socket)
        return;
    const QString what = QStringLiteral("looking up host '%1' took longer than %2 ms (connect timeout)")
                             .arg(url().host)
                             .arg(url().connectTimeoutMs);
    teardown();
    setState(State::Closed);
    reportError(LinkError::Kind::Timeout, what);
}

} // namespace mbscope

#include "moc_udplink.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
