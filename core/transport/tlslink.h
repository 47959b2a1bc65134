#pragma once

#include "tcplink.h"

#include <QtCore/QStringList>
#include <QtNetwork/QSslCertificate>
#include <QtNetwork/QSslKey>

namespace mbscope {

// MODBUS/TCP Security (tls://host:802): MBAP over TLS, mutual authentication. Our certificate and
// key (cert=, key=) identify us to the server; the server's certificate must chain to the CA file
// (ca=; the system's CAs when absent) and name the host of the URL. The files are read at each
// open(), so a renewed certificate is used on the next connection. The link is open once the
// handshake has finished; the connect timeout covers lookup, TCP connect and handshake.
// With mode=listen (a device that connects to us, see TcpLink) mbscope is the TLS server of the
// device's connection: cert= and key= are the server's, and the device must present a
// certificate that chains to ca= (the system's CAs when absent); the connect timeout covers the
// wait for the device and the handshake.
class TlsLink final : public TcpLink
{
    Q_OBJECT
public:
    explicit TlsLink(const LinkUrl &url, QObject *parent = nullptr);
    ~TlsLink() override;

protected:
    [[nodiscard]] Failure prepare() override;
    [[nodiscard]] QTcpSocket *createSocket() override;
    void startConnecting() override;
    // Connecting: nothing (the handshake follows by itself). A device's connection (mode=listen):
    // the server side of the handshake starts.
    void onTcpConnected() override;
    [[nodiscard]] qint64 acceptedBytes() const override;
    [[nodiscard]] Failure describe(QAbstractSocket::SocketError error, bool opening) const override;

private:
    [[nodiscard]] Failure describeTls(QAbstractSocket::SocketError error, bool opening) const;

    QList<QSslCertificate> m_localChain;
    QSslKey m_key;
    QList<QSslCertificate> m_caCertificates;
    QStringList m_handshakeErrors; // what the certificate checks said, for the failure message
};

} // namespace mbscope
