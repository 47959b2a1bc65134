#include "networklink.h"

#include <QtNetwork/QAbstractSocket>
#include <QtNetwork/QHostAddress>

namespace mbscope {

NetworkLink::NetworkLink(const LinkUrl &url, QObject *parent)
    : Link(url, parent)
    , m_connectTimer(this) // a child, so that moveToThread() takes it along
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        if (state() == State::Opening)
            onConnectTimeout();
    });
}

void NetworkLink::open()
{
    if (state() != State::Closed)
        return;
    setState(State::Opening);
    m_localEndpoint.clear();
    m_peerEndpoint.clear();
    QMetaObject::invokeMethod(this, [this] {
        if (state() == State::Opening)
            startOpen();
    }, Qt::QueuedConnection);
}

void NetworkLink::close()
{
    if (state() == State::Closed)
        return;
    closeOnRequest();
    setClosed(QStringLiteral("closed on request"));
}

QString NetworkLink::endpointText(const QHostAddress &address, quint16 port)
{
    bool v4 = false;
    const quint32 ipv4 = address.toIPv4Address(&v4); // an IPv4-mapped IPv6 address as IPv4
    if (v4)
        return QStringLiteral("%1:%2").arg(QHostAddress(ipv4).toString()).arg(port);
    return QStringLiteral("[%1]:%2").arg(address.toString()).arg(port);
}

void NetworkLink::noteEndpoints(const QAbstractSocket &socket)
{
    m_localEndpoint = endpointText(socket.localAddress(), socket.localPort());
    m_peerEndpoint = endpointText(socket.peerAddress(), socket.peerPort());
}

} // namespace mbscope

#include "moc_networklink.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
