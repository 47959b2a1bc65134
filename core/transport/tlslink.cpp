#include "tlslink.h"

#include <QtCore/QFile>
#include <QtNetwork/QSslConfiguration>
#include <QtNetwork/QSslError>
#include <QtNetwork/QSslSocket>

namespace mbscope {

namespace {

// Reads a whole file, or says why not ("cannot read the certificate file 'x' (No such file...)").
std::optional<QByteArray> readFile(const QString &path, const char *what, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read the %1 file '%2' (%3)").arg(QLatin1String(what), path, file.errorString());
        return std::nullopt;
    }
    return file.readAll();
}

} // namespace

TlsLink::TlsLink(const LinkUrl &url, QObject *parent)
    : TcpLink(url, parent)
{
}

TlsLink::~TlsLink() = default;

TcpLink::Failure TlsLink::prepare()
{
    using Kind = LinkError::Kind;
    if (!QSslSocket::supportsSsl())
        return {Kind::Config, QStringLiteral("TLS is not available: Qt found no TLS backend (%1)")
                                  .arg(QSslSocket::sslLibraryVersionString())};
    const TlsSettings &tls = url().tls;
    QString error;
    m_localChain.clear();
    m_key = QSslKey();
    m_caCertificates.clear();
    if (!tls.certificate.isEmpty()) {
        const auto pem = readFile(tls.certificate, "certificate", &error);
        if (!pem)
            return {Kind::Config, error};
        m_localChain = QSslCertificate::fromData(*pem, QSsl::Pem);
        if (m_localChain.isEmpty())
            return {Kind::Config, QStringLiteral("the certificate file '%1' holds no PEM certificate").arg(tls.certificate)};
        const auto keyPem = readFile(tls.privateKey, "private key", &error);
        if (!keyPem)
            return {Kind::Config, error};
        for (QSsl::KeyAlgorithm algorithm : {QSsl::Rsa, QSsl::Ec, QSsl::Dsa}) {
            m_key = QSslKey(*keyPem, algorithm, QSsl::Pem, QSsl::PrivateKey);
            if (!m_key.isNull())
                break;
        }
        if (m_key.isNull())
            return {Kind::Config, QStringLiteral("the private key file '%1' holds no usable PEM key "
                                                 "(RSA, EC or DSA, not protected by a passphrase)")
                                      .arg(tls.privateKey)};
    }
    if (!tls.caCertificates.isEmpty()) {
        const auto pem = readFile(tls.caCertificates, "CA certificate", &error);
        if (!pem)
            return {Kind::Config, error};
        m_caCertificates = QSslCertificate::fromData(*pem, QSsl::Pem);
        if (m_caCertificates.isEmpty())
            return {Kind::Config, QStringLiteral("the CA file '%1' holds no PEM certificate").arg(tls.caCertificates)};
    }
    return {Kind::None, {}};
}

QTcpSocket *TlsLink::createSocket()
{
    auto *socket = new QSslSocket(this);
    QSslConfiguration config = socket->sslConfiguration();
    if (!m_localChain.isEmpty()) {
        config.setLocalCertificateChain(m_localChain);
        config.setPrivateKey(m_key);
    }
    if (!m_caCertificates.isEmpty())
        config.setCaCertificates(m_caCertificates);
    // MODBUS/TCP Security requires TLS 1.2 or later and both sides authenticated.
    config.setProtocol(QSsl::TlsV1_2OrLater);
    config.setPeerVerifyMode(QSslSocket::VerifyPeer);
    socket->setSslConfiguration(config);
    m_handshakeErrors.clear();
    connect(socket, &QSslSocket::sslErrors, this, [this](const QList<QSslError> &errors) {
        for (const QSslError &e : errors)
            m_handshakeErrors.append(osAnswer(e.errorString()));
    });
    connect(socket, &QSslSocket::encrypted, this, &TlsLink::establish);
    // The ciphertext leaving counts as the request leaving.
    connect(socket, &QSslSocket::encryptedBytesWritten, this, &TlsLink::reportWritten);
    return socket;
}

void TlsLink::startConnecting()
{
    static_cast<QSslSocket *>(socket())->connectToHostEncrypted(url().host, url().port);
}

void TlsLink::onTcpConnected()
{
    if (url().listen)
        static_cast<QSslSocket *>(socket())->startServerEncryption();
}

qint64 TlsLink::acceptedBytes() const
{
    const auto *ssl = static_cast<const QSslSocket *>(socket());
    if (!ssl)
        return 0;
    // Plain bytes still to encrypt and ciphertext still to hand to the kernel have not left. A
    // record is at least as long as the plain bytes it holds, so subtracting the ciphertext count
    // gives a lower bound: a write is reported only once all of it has surely left.
    return submittedBytes() - ssl->bytesToWrite() - ssl->encryptedBytesToWrite();
}

TcpLink::Failure TlsLink::describe(QAbstractSocket::SocketError error, bool opening) const
{
    Failure failure = describeTls(error, opening);
    // With TLS 1.3 a server that wants a client certificate finds out after our side of the
    // handshake has finished, and closes the connection: say what is likely missing.
    if (url().tls.certificate.isEmpty()
        && (error == QAbstractSocket::RemoteHostClosedError || failure.kind == LinkError::Kind::Handshake))
        failure.what += QStringLiteral(" (no client certificate was given: MODBUS/TCP Security servers require one, "
                                       "set cert= and key=)");
    return failure;
}

TcpLink::Failure TlsLink::describeTls(QAbstractSocket::SocketError error, bool opening) const
{
    switch (error) {
    case QAbstractSocket::SslHandshakeFailedError:
    case QAbstractSocket::SslInternalError:
    case QAbstractSocket::SslInvalidUserDataError: {
        const QString os = osAnswer(socket() ? socket()->errorString() : QString());
        const QString why = m_handshakeErrors.isEmpty() ? os : m_handshakeErrors.join(QStringLiteral("; "));
        return {LinkError::Kind::Handshake, QStringLiteral("TLS handshake with %1 failed: %2").arg(where(), why)};
    }
    default:
        return TcpLink::describe(error, opening);
    }
}

} // namespace mbscope

#include "moc_tlslink.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
