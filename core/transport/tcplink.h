#pragma once

#include "networklink.h"

#include <QtCore/QList>
#include <QtCore/QTimer>
#include <QtNetwork/QAbstractSocket>

#include <memory>

QT_BEGIN_NAMESPACE
class QTcpSocket;
QT_END_NAMESPACE

namespace mbscope {

class ReverseListener;

// A TCP stream: tcp://, rtu-tcp://, ascii-tcp:// (and the base of tls://). Nagle's algorithm is
// off (TCP_NODELAY), so that a request leaves at once instead of waiting for more bytes.
// QTcpSocket looks the host up and connects (its errors and timeouts name what went wrong); once
// connected, plain TCP takes over a duplicate of the socket's descriptor and lets the QTcpSocket
// go: the link then reads with one non-blocking recv() when a socket notifier says the descriptor
// is readable, and writes with send(), without QAbstractSocket's buffers, ioctl(FIONREAD) and
// signals in between (they were a measurable share of the engine's work per transaction, issue 3).
// A request is handed to the kernel inside write() by one send(), and bytesWritten(t) carries the
// clock read just before that call (the segment leaves within it); should the kernel take only
// part, the rest waits in the link until the descriptor is writable, and bytesWritten(t) comes
// when the kernel has accepted the last byte (TCP gives no later moment to an application).
// Received bytes carry the clock read just before the recv() that took them.
// TLS keeps its QSslSocket throughout (its bytes must go through the TLS layer).
// A new socket is made at each open(), so that nothing of a lost connection leaks into the next.
//
// Reverse connection (mode=listen): open() listens on the URL's address (from the first open()
// until the link is destroyed, see ReverseListener) and the link opens when a device connects
// there; the connect timeout bounds the wait ("no device connected to 0.0.0.0:5020 within 3 s").
// From then on the link is master on that connection as on any other. A lost connection closes
// the link as usual; the next open() takes the next connection the device makes (one that came
// meanwhile at once). close() on request does not end the device's connection (it dials out at
// its own pace, and a scan or a watch closes and opens again between its phases): the
// connection is parked for the next open(), which first discards any bytes that came meanwhile.
// TLS connections are closed instead (their session cannot be parked). A connection that comes
// while one is held follows the URL's busy= policy (BusyPolicy); with replace, the one in use is
// lost (errorOccurred, closed) and the next open() takes the new one.
class TcpLink : public NetworkLink
{
    Q_OBJECT
public:
    explicit TcpLink(const LinkUrl &url, QObject *parent = nullptr);
    ~TcpLink() override;

    bool write(const QByteArray &bytes) override;

    // The descriptor the link reads and writes while open (plain TCP), or its socket's; -1 when
    // there is none. For tests and diagnostics (socket options).
    [[nodiscard]] qintptr socketDescriptor() const;

protected:
    struct Failure {
        LinkError::Kind kind = LinkError::Kind::Io;
        QString what;
    };

    // TlsLink: load files before connecting; returns a Config failure when they cannot be used.
    [[nodiscard]] virtual Failure prepare() { return {LinkError::Kind::None, {}}; }
    [[nodiscard]] virtual QTcpSocket *createSocket();
    virtual void startConnecting();
    // Called once TCP is connected; the link is open at once, or later (TLS: after the handshake).
    virtual void onTcpConnected();
    // Bytes of the writes so far that the kernel has accepted.
    [[nodiscard]] virtual qint64 acceptedBytes() const;
    // What a socket error means, while opening (opening = true) or once open.
    [[nodiscard]] virtual Failure describe(QAbstractSocket::SocketError error, bool opening) const;

    [[nodiscard]] QTcpSocket *socket() const { return m_socket; }
    [[nodiscard]] qint64 submittedBytes() const { return m_submitted; }
    // "127.0.0.1:502", or "localhost:502 (127.0.0.1)" once a name was resolved.
    [[nodiscard]] QString where() const;
    void establish();
    void reportWritten();

private:
    class DescriptorNotifier;

    void startOpen() override;
    void teardown() override;
    void closeOnRequest() override;
    // The signals of a new socket (connecting, or accepted).
    void watchSocket();
    void onSocketConnected();
    // Reverse connection: listen, and take a waiting connection if there is one.
    void startWaiting();
    void acceptWaiting();
    void onDeviceWaiting(const QString &peer);
    void fail(const Failure &failure);
    // Plain TCP once connected: a duplicate of the socket's descriptor replaces the QTcpSocket.
    [[nodiscard]] bool takeDescriptor();
    bool writeToDescriptor(const QByteArray &bytes);
    // One non-blocking send() of as much as the kernel takes now; -1 (errno set) when it fails.
    [[nodiscard]] qint64 sendNow(QByteArrayView bytes);
    void onReadable();
    void onWritable();
    // The descriptor failed (errno err) or the peer closed it (err 0): the link is lost.
    void loseDescriptor(int err);
    void onReadyRead();
    void onSocketError(QAbstractSocket::SocketError error);
    void onDisconnected();
    void onConnectTimeout() override;

    QTcpSocket *m_socket = nullptr; // while opening, and throughout for TLS
    ReverseListener *m_listener = nullptr; // mode=listen, from the first open(); a child
    bool m_awaitingDevice = false;          // mode=listen: open() waits for a connection
    int m_fd = -1;                  // plain TCP once open
    DescriptorNotifier *m_readNotifier;  // children, so that moveToThread() takes them along
    DescriptorNotifier *m_writeNotifier;
    QByteArray m_unsent;            // written bytes the kernel has not taken yet (descriptor)
    QString m_where;                // where(), kept when the QTcpSocket goes
    QList<qint64> m_marks;  // m_submitted at the end of each write not yet reported
    qint64 m_submitted = 0; // bytes given to the socket since open()
    bool m_inWrite = false;
    QByteArray m_readBuffer; // the bytes of the latest read, reused
    std::unique_ptr<char[]> m_recvBuffer; // what recv() fills, kReceiveChunk bytes
};

} // namespace mbscope
