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
// Written bytes are flushed to the kernel inside write(); bytesWritten(t) comes when the kernel has
// accepted the last byte of that write (TCP gives no later moment to an application).
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
    void onReadyRead();
    void onSocketError(QAbstractSocket::SocketError error);
    void onDisconnected();
    void onConnectTimeout();

    QTcpSocket *m_socket = nullptr;
    QTimer m_connectTimer;
    QList<qint64> m_marks;  // m_submitted at the end of each write not yet reported
    qint64 m_submitted = 0; // bytes given to the socket since open()
    bool m_inWrite = false;
};

} // namespace mbscope
