#pragma once

#include "link.h"

#include <QtCore/QList>
#include <QtCore/QTimer>
#include <QtNetwork/QAbstractSocket>

QT_BEGIN_NAMESPACE
class QTcpSocket;
QT_END_NAMESPACE

namespace mbscope {

// A TCP stream: tcp://, rtu-tcp://, ascii-tcp:// (and the base of tls://). Nagle's algorithm is
// off (TCP_NODELAY), so that a request leaves at once instead of waiting for more bytes.
// A request is handed to the kernel inside write() by one send() on the socket's descriptor, and
// bytesWritten(t) carries the clock read just before that call (the segment leaves within it);
// should the kernel take only part, Qt's buffer sends the rest and bytesWritten(t) comes when the
// kernel has accepted the last byte (TCP gives no later moment to an application).
// A new socket is made at each open(), so that nothing of a lost connection leaks into the next.
class TcpLink : public Link
{
    Q_OBJECT
public:
    explicit TcpLink(const LinkUrl &url, QObject *parent = nullptr);
    ~TcpLink() override;

    void open() override;
    void close() override;
    bool write(const QByteArray &bytes) override;

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
    // Plain TCP writes a request with one send() on the descriptor, timed just before it; TLS
    // (whose bytes must go through the TLS layer) says false.
    [[nodiscard]] virtual bool writesToDescriptor() const { return true; }
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
    void startOpen();
    void teardown();
    void fail(const Failure &failure);
    // One non-blocking send() of as much as the kernel takes now; 0 when it takes nothing or fails
    // (Qt's write path then reports the failure).
    [[nodiscard]] qint64 sendNow(QByteArrayView bytes);
    void onReadyRead();
    void onSocketError(QAbstractSocket::SocketError error);
    void onDisconnected();
    void onConnectTimeout();

    QTcpSocket *m_socket = nullptr;
    QTimer m_connectTimer;
    QList<qint64> m_marks;  // m_submitted at the end of each write not yet reported
    qint64 m_submitted = 0; // bytes given to the socket since open()
    bool m_inWrite = false;
    QByteArray m_readBuffer; // the bytes of the latest read, reused
};

} // namespace mbscope
