#include "reverselistener.h"

#include "networklink.h"

#include <QtNetwork/QHostAddress>
#include <QtNetwork/QTcpServer>

#include <arpa/inet.h>
#include <cerrno>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace mbscope {

// Hands each accepted descriptor to the listener as it is, without a QTcpSocket around it.
class ReverseListener::Server final : public QTcpServer
{
public:
    explicit Server(ReverseListener *owner)
        : QTcpServer(owner)
        , m_owner(owner)
    {
    }

protected:
    void incomingConnection(qintptr fd) override { m_owner->onIncoming(int(fd)); }

private:
    ReverseListener *m_owner;
};

ReverseListener::ReverseListener(BusyPolicy policy, QObject *parent)
    : QObject(parent)
    , m_policy(policy)
    , m_server(new Server(this))
{
}

ReverseListener::~ReverseListener()
{
    closeWaiting();
}

QString ReverseListener::listen(const QString &host, quint16 port)
{
    if (m_server->isListening())
        return {};
    const QHostAddress address(host);
    if (m_server->listen(address, port))
        return {};
    const QString where = (host.contains(u':') ? QLatin1Char('[') + host + QLatin1Char(']') : host) + QLatin1Char(':')
        + QString::number(port);
    switch (m_server->serverError()) {
    case QAbstractSocket::AddressInUseError:
        return QStringLiteral("address in use: another program listens on %1 already").arg(where);
    case QAbstractSocket::SocketAddressNotAvailableError:
        return QStringLiteral("%1 is not an address of this machine (0.0.0.0 listens on every IPv4 interface)").arg(host);
    case QAbstractSocket::SocketAccessError:
        return QStringLiteral("permission denied listening on %1 (ports below 1024 need root or CAP_NET_BIND_SERVICE)")
            .arg(where);
    default:
        return QStringLiteral("cannot listen on %1 (%2)").arg(where, m_server->errorString());
    }
}

bool ReverseListener::isListening() const
{
    return m_server->isListening();
}

void ReverseListener::onIncoming(int fd)
{
    switch (m_policy) {
    case BusyPolicy::Refuse:
        if (m_inUse || !m_waiting.isEmpty()) {
            ++m_turnedAway;
            ::close(fd);
            return;
        }
        break;
    case BusyPolicy::Queue:
        if (m_waiting.size() >= kMaxWaiting) {
            ++m_turnedAway;
            ::close(fd);
            return;
        }
        break;
    case BusyPolicy::Replace:
        m_turnedAway += quint64(m_waiting.size());
        closeWaiting();
        break;
    }
    m_waiting.append({fd, false});
    Q_EMIT connectionWaiting(peerOf(fd));
}

int ReverseListener::take()
{
    while (!m_waiting.isEmpty()) {
        const Waiting w = m_waiting.takeFirst();
        char scratch[512];
        bool alive = true;
        for (;;) {
            // A parked connection: read what came meanwhile and drop it. A new one: only look.
            const ssize_t n = ::recv(w.fd, scratch, w.parked ? sizeof scratch : 1, MSG_DONTWAIT | (w.parked ? 0 : MSG_PEEK));
            if (n > 0) {
                if (w.parked)
                    continue;
                break;
            }
            if (n == 0) {
                alive = false; // the device closed it while it waited
                break;
            }
            if (errno == EINTR)
                continue;
            if (errno != EAGAIN && errno != EWOULDBLOCK)
                alive = false; // reset
            break;
        }
        if (alive)
            return w.fd;
        ::close(w.fd);
    }
    return -1;
}

void ReverseListener::park(int fd)
{
    m_inUse = false;
    if (fd < 0)
        return;
    m_waiting.prepend({fd, true});
}

void ReverseListener::closeWaiting()
{
    for (const Waiting &w : std::as_const(m_waiting))
        ::close(w.fd);
    m_waiting.clear();
}

QString ReverseListener::peerOf(int fd)
{
    sockaddr_storage storage{};
    socklen_t length = sizeof storage;
    if (::getpeername(fd, reinterpret_cast<sockaddr *>(&storage), &length) != 0)
        return QStringLiteral("an unknown address");
    quint16 port = 0;
    if (storage.ss_family == AF_INET)
        port = ntohs(reinterpret_cast<const sockaddr_in *>(&storage)->sin_port);
    else if (storage.ss_family == AF_INET6)
        port = ntohs(reinterpret_cast<const sockaddr_in6 *>(&storage)->sin6_port);
    return NetworkLink::endpointText(QHostAddress(reinterpret_cast<const sockaddr *>(&storage)), port);
}

} // namespace mbscope

#include "moc_reverselistener.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
