#pragma once

#include "link.h"

#include <QtCore/QTimer>

class QAbstractSocket;
class QHostAddress;

namespace mbscope {

// What TcpLink (and TlsLink) and UdpLink share: opening goes on after open() returns (so that
// every outcome is signalled the same way), bounded by the URL's connect timeout, and close()
// tears the socket down at once.
class NetworkLink : public Link
{
    Q_OBJECT
public:
    void open() final;
    void close() final;

    // The two ends of the connection as its socket had them once connected ("127.0.0.1:40312",
    // "[::1]:502"): kept until the next open, so that a journal can say which connection its
    // frames went over (trafficjournal.h, the endpoints note).
    [[nodiscard]] const QString &localEndpoint() const { return m_localEndpoint; }
    [[nodiscard]] const QString &peerEndpoint() const { return m_peerEndpoint; }
    // "127.0.0.1:40312" (an IPv4-mapped IPv6 address as IPv4), "[::1]:502".
    [[nodiscard]] static QString endpointText(const QHostAddress &address, quint16 port);

protected:
    explicit NetworkLink(const LinkUrl &url, QObject *parent = nullptr);

    // Called once, queued after open(), with the state Opening.
    virtual void startOpen() = 0;
    // Drops the socket (and stops the connect timer); the state is the caller's to set.
    virtual void teardown() = 0;
    // The connect timeout ran out while the state was Opening.
    virtual void onConnectTimeout() = 0;
    // close() on request: teardown(), unless the link keeps something for its next open (a
    // reverse link parks its device's connection, see TcpLink).
    virtual void closeOnRequest() { teardown(); }

    void startConnectTimer() { m_connectTimer.start(url().connectTimeoutMs); }
    void stopConnectTimer() { m_connectTimer.stop(); }
    // Once the socket is connected, before opened().
    void noteEndpoints(const QAbstractSocket &socket);

private:
    QTimer m_connectTimer;
    QString m_localEndpoint;
    QString m_peerEndpoint;
};

} // namespace mbscope
