#include "sim/simstreamendpoint.h"

#include "sim/simconnection.h"
#include "sim/simlisten.h"
#include "sim/simulator.h"

#include <QtCore/QFile>
#include <QtNetwork/QSslCertificate>
#include <QtNetwork/QSslConfiguration>
#include <QtNetwork/QSslKey>
#include <QtNetwork/QSslServer>
#include <QtNetwork/QSslSocket>
#include <QtNetwork/QTcpServer>

namespace mbscope {

namespace {

std::optional<QByteArray> readPem(const QString &path, const char *what, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read the %1 file '%2': %3").arg(QLatin1String(what), path, file.errorString());
        return std::nullopt;
    }
    return file.readAll();
}

} // namespace

SimStreamEndpoint::SimStreamEndpoint(Simulator *simulator, const LinkUrl &url, const SimEndpointOptions &options)
    : SimEndpoint(simulator, url, options)
{
}

SimStreamEndpoint::~SimStreamEndpoint()
{
    stop();
}

bool SimStreamEndpoint::configureTls(QString *error)
{
    const TlsSettings &tls = url().tls;
    if (!QSslSocket::supportsSsl()) {
        *error = QStringLiteral("TLS is not available (no TLS backend in this Qt)");
        return false;
    }
    if (tls.certificate.isEmpty() || tls.privateKey.isEmpty()) {
        *error = QStringLiteral("a tls:// endpoint needs cert=FILE and key=FILE (the server's certificate and key, PEM)");
        return false;
    }
    const auto certPem = readPem(tls.certificate, "certificate", error);
    if (!certPem)
        return false;
    const QList<QSslCertificate> chain = QSslCertificate::fromData(*certPem, QSsl::Pem);
    if (chain.isEmpty()) {
        *error = QStringLiteral("'%1' holds no PEM certificate").arg(tls.certificate);
        return false;
    }
    const auto keyPem = readPem(tls.privateKey, "key", error);
    if (!keyPem)
        return false;
    QSslKey key;
    for (QSsl::KeyAlgorithm algorithm : {QSsl::Rsa, QSsl::Ec, QSsl::Dsa}) {
        key = QSslKey(*keyPem, algorithm, QSsl::Pem, QSsl::PrivateKey);
        if (!key.isNull())
            break;
    }
    if (key.isNull()) {
        *error = QStringLiteral("'%1' holds no PEM private key without a passphrase (RSA, EC or DSA)").arg(tls.privateKey);
        return false;
    }
    QSslConfiguration config = QSslConfiguration::defaultConfiguration();
    config.setLocalCertificateChain(chain);
    config.setPrivateKey(key);
    config.setProtocol(QSsl::TlsV1_2OrLater);
    if (!tls.caCertificates.isEmpty()) {
        const auto caPem = readPem(tls.caCertificates, "CA", error);
        if (!caPem)
            return false;
        const QList<QSslCertificate> ca = QSslCertificate::fromData(*caPem, QSsl::Pem);
        if (ca.isEmpty()) {
            *error = QStringLiteral("'%1' holds no PEM CA certificate").arg(tls.caCertificates);
            return false;
        }
        config.setCaCertificates(ca);
        config.setPeerVerifyMode(QSslSocket::VerifyPeer); // MODBUS/TCP Security: mutual authentication
    } else {
        config.setPeerVerifyMode(QSslSocket::VerifyNone);
    }
    auto *server = new QSslServer(this);
    server->setSslConfiguration(config);
    connect(server, &QSslServer::errorOccurred, this, [this](QSslSocket *socket, QAbstractSocket::SocketError) {
        simulator()->noteConnection(this, socket->peerAddress().toString() + QLatin1Char(':') + QString::number(socket->peerPort()),
                                    SimLogEntry::Verdict::ConnectionRefused,
                                    QStringLiteral("TLS handshake failed: %1").arg(socket->errorString()));
    });
    connect(server, &QSslServer::peerVerifyError, this, [this](QSslSocket *socket, const QSslError &e) {
        simulator()->noteConnection(this, socket->peerAddress().toString() + QLatin1Char(':') + QString::number(socket->peerPort()),
                                    SimLogEntry::Verdict::ConnectionRefused,
                                    QStringLiteral("client certificate refused: %1").arg(e.errorString()));
    });
    m_server = server;
    return true;
}

bool SimStreamEndpoint::start(QString *error)
{
    QString why;
    const auto address = listenAddress(url().host, &why);
    auto fail = [&](const QString &message) {
        *error = url().toString() + QStringLiteral(": ") + message;
        delete m_server;
        m_server = nullptr;
        return false;
    };
    if (!address)
        return fail(why);
    if (url().kind == LinkKind::Tls) {
        if (!configureTls(&why))
            return fail(why);
    } else {
        m_server = new QTcpServer(this);
    }
    if (!m_server->listen(*address, url().port))
        return fail(m_server->errorString());
    // pendingConnectionAvailable (Qt 6.4): QSslServer queues a client only once its handshake is
    // done, after newConnection was already emitted; for QTcpServer both come together.
    connect(m_server, &QTcpServer::pendingConnectionAvailable, this, &SimStreamEndpoint::onNewConnection);
    LinkUrl bound = url();
    bound.port = m_server->serverPort();
    setBound(bound, true);
    return true;
}

void SimStreamEndpoint::stop()
{
    if (m_server)
        m_server->close();
    const QList<SimConnection *> all = m_connections;
    for (SimConnection *c : all)
        c->close(QStringLiteral("endpoint stopped"));
    setBound(boundUrl(), false);
}

void SimStreamEndpoint::onNewConnection()
{
    while (m_server->hasPendingConnections()) {
        QTcpSocket *socket = m_server->nextPendingConnection();
        const int limit = options().maxConnections;
        if (limit > 0 && m_connections.size() >= limit && options().dropOldestConnection) {
            // Some gateways make room for a new client by dropping the one connected longest.
            // It leaves the count at once; its finished() still deletes it once it is closed.
            SimConnection *oldest = m_connections.takeFirst();
            oldest->close(QStringLiteral("knocked off by a new client: maxClients is %1, extraClients is dropOldest").arg(limit));
        } else if (limit > 0 && m_connections.size() >= limit) {
            simulator()->noteConnection(this, socket->peerAddress().toString() + QLatin1Char(':') + QString::number(socket->peerPort()),
                                        SimLogEntry::Verdict::ConnectionRefused,
                                        QStringLiteral("refused by maxClients: %1 client(s) connected already, maxClients is %1").arg(limit));
            socket->abort();
            socket->deleteLater();
            continue;
        }
        auto *connection = new SimConnection(simulator(), this, socket, this);
        m_connections.append(connection);
        connect(connection, &SimConnection::finished, this, [this](SimConnection *c) {
            m_connections.removeOne(c);
            c->deleteLater();
        });
        simulator()->noteConnection(this, connection->peer(), SimLogEntry::Verdict::ConnectionOpened,
                                    QStringLiteral("client %1 of %2").arg(m_connections.size()).arg(limit > 0 ? QString::number(limit) : QStringLiteral("any")));
    }
}

} // namespace mbscope

#include "moc_simstreamendpoint.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
