#pragma once

#include "networklink.h"

#include <QtNetwork/QAbstractSocket>

QT_BEGIN_NAMESPACE
class QUdpSocket;
QT_END_NAMESPACE

namespace mbscope {

// Datagrams: udp:// (MBAP) and rtu-udp:// (RTU), one frame per datagram. The socket is connected
// to the peer, so the kernel drops datagrams from any other address. Open means the host name was
// resolved and the socket connected; UDP itself has no handshake, so a device that is off or a
// port nothing listens on is noticed by the engine's timeouts: the kernel's ICMP "port
// unreachable" is consumed by Qt 6.4's datagram check without a signal. Should Qt report it, it
// comes as a Refused error and the link stays open.
// bytesWritten(t) is emitted inside write(): the kernel has taken the whole datagram.
// Zero-length datagrams are not reported (no frame fits in them).
class UdpLink final : public NetworkLink
{
    Q_OBJECT
public:
    explicit UdpLink(const LinkUrl &url, QObject *parent = nullptr);
    ~UdpLink() override;

    [[nodiscard]] bool isDatagram() const override { return true; }

    bool write(const QByteArray &bytes) override;

private:
    void startOpen() override;
    void teardown() override;
    void onReadyRead();
    void onSocketError(QAbstractSocket::SocketError error);
    void onConnectTimeout() override;
    [[nodiscard]] QString where() const;

    QUdpSocket *m_socket = nullptr;
};

} // namespace mbscope
