#pragma once

#include "link.h"

#include <QtCore/QTimer>

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

protected:
    explicit NetworkLink(const LinkUrl &url, QObject *parent = nullptr);

    // Called once, queued after open(), with the state Opening.
    virtual void startOpen() = 0;
    // Drops the socket (and stops the connect timer); the state is the caller's to set.
    virtual void teardown() = 0;
    // The connect timeout ran out while the state was Opening.
    virtual void onConnectTimeout() = 0;

    void startConnectTimer() { m_connectTimer.start(url().connectTimeoutMs); }
    void stopConnectTimer() { m_connectTimer.stop(); }

private:
    QTimer m_connectTimer;
};

} // namespace mbscope
