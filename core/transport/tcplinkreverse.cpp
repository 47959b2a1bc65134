// TcpLink's reverse connection (mode=listen): waiting for a device, taking its connection, and
// parking it on close(). See tcplink.h.

#include "tcplink.h"

#include "reverselistener.h"

#include <QtNetwork/QTcpSocket>

#include <unistd.h>
#include <utility>

namespace mbscope {

void TcpLink::startWaiting()
{
    if (!m_listener) {
        m_listener = new ReverseListener(url().busy, this);
        connect(m_listener, &ReverseListener::connectionWaiting, this, &TcpLink::onDeviceWaiting);
    }
    if (const QString error = m_listener->listen(url().host, url().port); !error.isEmpty()) {
        setState(State::Closed);
        reportError(LinkError::Kind::Io, QStringLiteral("cannot wait for a device to connect: %1").arg(error));
        return;
    }
    m_awaitingDevice = true;
    startConnectTimer();
    acceptWaiting();
}

void TcpLink::acceptWaiting()
{
    // Only once startWaiting() has run for this open(): files prepared, the timer running.
    if (!m_awaitingDevice || state() != State::Opening || m_socket || m_fd >= 0)
        return;
    const int fd = m_listener->take();
    if (fd < 0)
        return;
    m_awaitingDevice = false;
    m_socket = createSocket();
    watchSocket();
    if (!m_socket->setSocketDescriptor(fd)) {
        const QString what = QStringLiteral("a device connected from %1, but its connection cannot be used (%2)")
                                 .arg(ReverseListener::peerOf(fd), osAnswer(m_socket->errorString()));
        ::close(fd);
        fail({LinkError::Kind::Io, what});
        return;
    }
    m_listener->setInUse(true);
    onSocketConnected();
}

void TcpLink::onDeviceWaiting(const QString &peer)
{
    if (state() == State::Opening) {
        acceptWaiting();
        return;
    }
    if (state() != State::Open || url().busy != BusyPolicy::Replace)
        return;
    const QString what = QStringLiteral("%1 is replaced by a new connection from %2 (busy=replace); the next request uses it")
                             .arg(where(), peer);
    teardown();
    reportLoss(LinkError::Kind::Closed, what);
}

} // namespace mbscope
