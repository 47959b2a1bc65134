#include "transport/monotonicclock.h"
#include "transport/tlslink.h"

#include "linktesting.h"
#include "testcertificates.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QSslConfiguration>
#include <QtNetwork/QSslKey>
#include <QtNetwork/QSslSocket>
#include <QtNetwork/QTcpServer>
#include <QtTest/QtTest>

#include <memory>

using namespace mbscope;
using linktesting::Recorder;

namespace {

constexpr int kWaitMs = 15000;

// A TLS echo server on loopback that requires a client certificate signed by its CA
// (MODBUS/TCP Security: mutual authentication). A QTcpServer whose connections are wrapped in
// QSslSocket, so that it does not depend on QSslServer.
class TlsPeer : public QTcpServer
{
public:
    TlsPeer(const QString &certificate, const QString &key, const QString &ca)
    {
        QFile certFile(certificate);
        QFile keyFile(key);
        QVERIFY(certFile.open(QIODevice::ReadOnly) && keyFile.open(QIODevice::ReadOnly));
        m_config = QSslConfiguration::defaultConfiguration();
        m_config.setLocalCertificateChain(QSslCertificate::fromData(certFile.readAll(), QSsl::Pem));
        m_config.setPrivateKey(QSslKey(keyFile.readAll(), QSsl::Ec, QSsl::Pem, QSsl::PrivateKey));
        m_config.setCaCertificates(QSslCertificate::fromPath(ca, QSsl::Pem));
        m_config.setPeerVerifyMode(QSslSocket::VerifyPeer);
        QVERIFY(listen(QHostAddress::LocalHost, 0));
    }

    int encrypted = 0;
    int failed = 0;
    QStringList clientNames;
    QByteArray got;

protected:
    void incomingConnection(qintptr descriptor) override
    {
        auto *socket = new QSslSocket(this);
        socket->setSslConfiguration(m_config);
        if (!socket->setSocketDescriptor(descriptor)) {
            delete socket;
            return;
        }
        connect(socket, &QSslSocket::encrypted, this, [this, socket] {
            ++encrypted;
            clientNames += socket->peerCertificate().subjectInfo(QSslCertificate::CommonName);
        });
        connect(socket, &QSslSocket::sslErrors, this, [this](const QList<QSslError> &) { ++failed; });
        connect(socket, &QIODevice::readyRead, this, [this, socket] {
            const QByteArray bytes = socket->readAll();
            got += bytes;
            socket->write(bytes);
        });
        connect(socket, &QAbstractSocket::disconnected, socket, &QObject::deleteLater);
        socket->startServerEncryption();
    }

private:
    QSslConfiguration m_config;
};

std::unique_ptr<Link> makeLink(const QString &text)
{
    const auto parsed = LinkUrl::parse(text);
    if (!parsed.url)
        qFatal("bad URL in test: %s", qPrintable(parsed.error));
    return std::unique_ptr<Link>(Link::create(*parsed.url));
}

} // namespace

class TestTlsLink : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }

    QString clientUrl(quint16 port, const QString &ca = QStringLiteral("ca.pem")) const
    {
        return QStringLiteral("tls://127.0.0.1:%1?cert=%2&key=%3&ca=%4")
            .arg(port)
            .arg(path("client.pem"), path("client.key"), m_dir.filePath(ca));
    }

private slots:
    // A throwaway CA, a server certificate for 127.0.0.1/localhost, a client certificate, a
    // second CA that signed neither, and a server certificate for another name.
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        if (!QSslSocket::supportsSsl())
            QSKIP("Qt has no TLS backend here");
        testing::TestCertificates certificates(m_dir.path());
        if (!certificates.isAvailable())
            QSKIP(qPrintable(certificates.error()));
        QVERIFY2(certificates.makeCa(QStringLiteral("ca")), qPrintable(certificates.error()));
        QVERIFY2(certificates.makeCa(QStringLiteral("otherca")), qPrintable(certificates.error()));
        QVERIFY2(certificates.issue(QStringLiteral("server"), "subjectAltName=IP:127.0.0.1,DNS:localhost\nextendedKeyUsage=serverAuth\n",
                                    QStringLiteral("ca"), QStringLiteral("/CN=localhost")),
                 qPrintable(certificates.error()));
        QVERIFY2(certificates.issue(QStringLiteral("client"), "extendedKeyUsage=clientAuth\n", QStringLiteral("ca"),
                                    QStringLiteral("/CN=mbscope-client")),
                 qPrintable(certificates.error()));
        QVERIFY2(certificates.issue(QStringLiteral("elsewhere"), "subjectAltName=DNS:plc.example\nextendedKeyUsage=serverAuth\n",
                                    QStringLiteral("ca"), QStringLiteral("/CN=plc.example")),
                 qPrintable(certificates.error()));
    }

    void mutualEcho()
    {
        TlsPeer peer(path("server.pem"), path("server.key"), path("ca.pem"));
        auto link = makeLink(clientUrl(peer.serverPort()));
        QVERIFY(qobject_cast<TlsLink *>(link.get()));
        Recorder rec(link.get());
        link->open();
        QTRY_VERIFY_WITH_TIMEOUT(rec.opened + rec.errors.size() > 0, kWaitMs);
        QVERIFY2(rec.errors.isEmpty(), qPrintable(rec.lastMessage()));
        QCOMPARE(link->state(), Link::State::Open);
        QTRY_COMPARE_WITH_TIMEOUT(peer.encrypted, 1, kWaitMs);
        QCOMPARE(peer.clientNames, QStringList{QStringLiteral("mbscope-client")}); // we were authenticated
        auto *socket = link->findChild<QSslSocket *>();
        QVERIFY(socket);
        QCOMPARE(socket->socketOption(QAbstractSocket::LowDelayOption).toInt(), 1);

        const QByteArray request = QByteArray::fromHex("000100000006010300790016");
        const qint64 before = monotonicNowNs();
        QVERIFY(link->write(request));
        QTRY_COMPARE_WITH_TIMEOUT(rec.writtenNs.size(), 1, kWaitMs);
        QVERIFY(rec.writtenNs.first() >= before);
        QTRY_COMPARE_WITH_TIMEOUT(rec.received, request, kWaitMs);
        QCOMPARE(peer.got, request);
        QVERIFY(rec.firstNs.first() >= rec.writtenNs.first());

        link->close();
        QCOMPARE(rec.closed, 1);
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 2, kWaitMs);
        QVERIFY(link->write("again"));
        QTRY_COMPARE_WITH_TIMEOUT(rec.received, request + "again", kWaitMs);
    }

    // Reverse connection (mode=listen, issue 27): the device dials in and is the TLS client;
    // mbscope is the server, with cert= and key=, and wants the device's certificate (ca=).
    void reverseConnection_data()
    {
        QTest::addColumn<bool>("deviceHasCertificate");
        QTest::newRow("device with a certificate") << true;
        QTest::newRow("device without one") << false;
    }
    void reverseConnection()
    {
        QFETCH(bool, deviceHasCertificate);
        QTcpServer probe;
        QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
        const quint16 port = probe.serverPort();
        probe.close();
        auto link = makeLink(QStringLiteral("tls://127.0.0.1:%1?mode=listen&cert=%2&key=%3&ca=%4&connect_timeout=10s")
                                 .arg(port)
                                 .arg(path("server.pem"), path("server.key"), path("ca.pem")));
        Recorder rec(link.get());
        link->open();

        QSslSocket device;
        QSslConfiguration config = QSslConfiguration::defaultConfiguration();
        config.setCaCertificates(QSslCertificate::fromPath(path("ca.pem"), QSsl::Pem));
        if (deviceHasCertificate) {
            QFile certFile(path("client.pem"));
            QFile keyFile(path("client.key"));
            QVERIFY(certFile.open(QIODevice::ReadOnly) && keyFile.open(QIODevice::ReadOnly));
            config.setLocalCertificateChain(QSslCertificate::fromData(certFile.readAll(), QSsl::Pem));
            config.setPrivateKey(QSslKey(keyFile.readAll(), QSsl::Ec, QSsl::Pem, QSsl::PrivateKey));
        }
        device.setSslConfiguration(config);
        connect(&device, &QIODevice::readyRead, &device, [&device] { device.write(device.readAll()); });
        // The link listens from open() on, once its queued start has run.
        QTRY_VERIFY_WITH_TIMEOUT(link->findChild<QTcpServer *>() && link->findChild<QTcpServer *>()->isListening(), kWaitMs);
        device.connectToHostEncrypted(QStringLiteral("127.0.0.1"), port);
        if (!deviceHasCertificate) {
            QTRY_VERIFY_WITH_TIMEOUT(!rec.errors.isEmpty(), kWaitMs);
            QCOMPARE(rec.errors.first().kind, LinkError::Kind::Handshake);
            QVERIFY2(rec.lastMessage().startsWith(link->url().toString() + QStringLiteral(": TLS handshake with the device at 127.0.0.1:")),
                     qPrintable(rec.lastMessage()));
            qInfo().noquote() << rec.lastMessage();
            QCOMPARE(rec.opened, 0);
            QCOMPARE(link->state(), Link::State::Closed);
            return;
        }
        QTRY_COMPARE_WITH_TIMEOUT(rec.opened, 1, kWaitMs);
        QVERIFY2(rec.errors.isEmpty(), qPrintable(rec.lastMessage()));
        QCOMPARE(device.peerCertificate().subjectInfo(QSslCertificate::CommonName), QStringList{QStringLiteral("localhost")});
        const QByteArray request = QByteArray::fromHex("000100000006010300790016");
        QVERIFY(link->write(request));
        QTRY_COMPARE_WITH_TIMEOUT(rec.received, request, kWaitMs);
        QTRY_COMPARE_WITH_TIMEOUT(rec.writtenNs.size(), 1, kWaitMs);
    }

    // The server's certificate does not chain to the CA we were given.
    void wrongCa()
    {
        TlsPeer peer(path("server.pem"), path("server.key"), path("ca.pem"));
        const QString url = clientUrl(peer.serverPort(), QStringLiteral("otherca.pem"));
        auto link = makeLink(url);
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Handshake);
        const QString prefix = link->url().toString()
            + QStringLiteral(": TLS handshake with 127.0.0.1:%1 failed: ").arg(peer.serverPort());
        QVERIFY2(rec.lastMessage().startsWith(prefix), qPrintable(rec.lastMessage()));
        QVERIFY2(rec.lastMessage().size() > prefix.size(), "the reason is said");
        qInfo().noquote() << rec.lastMessage();
        QCOMPARE(rec.opened, 0);
        QCOMPARE(link->state(), Link::State::Closed);
    }

    // The server's certificate names another host.
    void wrongName()
    {
        TlsPeer peer(path("elsewhere.pem"), path("elsewhere.key"), path("ca.pem"));
        auto link = makeLink(clientUrl(peer.serverPort()));
        Recorder rec(link.get());
        link->open();
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(rec.errors.first().kind, LinkError::Kind::Handshake);
        QVERIFY2(rec.lastMessage().contains(QStringLiteral("host name")), qPrintable(rec.lastMessage()));
        qInfo().noquote() << rec.lastMessage();
        QCOMPARE(rec.opened, 0);
    }

    // Without a client certificate the server refuses us: the link does not stay open.
    void noClientCertificate()
    {
        TlsPeer peer(path("server.pem"), path("server.key"), path("ca.pem"));
        const QString url = QStringLiteral("tls://127.0.0.1:%1?ca=%2").arg(peer.serverPort()).arg(path("ca.pem"));
        auto link = makeLink(url);
        Recorder rec(link.get());
        link->open();
        QTRY_VERIFY_WITH_TIMEOUT(!rec.errors.isEmpty(), kWaitMs);
        QTRY_COMPARE_WITH_TIMEOUT(link->state(), Link::State::Closed, kWaitMs);
        QCOMPARE(peer.encrypted, 0);
        QVERIFY2(rec.lastMessage().startsWith(url + QStringLiteral(": ")), qPrintable(rec.lastMessage()));
        QVERIFY2(rec.lastMessage().endsWith(QStringLiteral("(no client certificate was given: MODBUS/TCP Security servers "
                                                           "require one, set cert= and key=)")),
                 qPrintable(rec.lastMessage()));
        qInfo().noquote() << rec.events << rec.lastMessage();
    }

    void unusableFiles_data()
    {
        QTest::addColumn<QString>("options");
        QTest::addColumn<QString>("problem");
        QTest::addColumn<int>("kind");
        const QString missing = m_dir.filePath(QStringLiteral("missing.pem"));
        QTest::newRow("missing certificate")
            << QStringLiteral("cert=%1&key=%2").arg(missing, path("client.key"))
            << QStringLiteral("cannot read the certificate file '%1' (No such file or directory)").arg(missing)
            << int(LinkError::Kind::Config);
        QTest::newRow("missing key") << QStringLiteral("cert=%1&key=%2").arg(path("client.pem"), missing)
                                     << QStringLiteral("cannot read the private key file '%1' (No such file or directory)")
                                            .arg(missing)
                                     << int(LinkError::Kind::Config);
        QTest::newRow("missing CA") << QStringLiteral("ca=%1").arg(missing)
                                    << QStringLiteral("cannot read the CA certificate file '%1' (No such file or directory)")
                                           .arg(missing)
                                    << int(LinkError::Kind::Config);
        QTest::newRow("key given as certificate")
            << QStringLiteral("cert=%1&key=%1").arg(path("client.key"))
            << QStringLiteral("the certificate file '%1' holds no PEM certificate").arg(path("client.key"))
            << int(LinkError::Kind::Config);
        QTest::newRow("certificate given as key")
            << QStringLiteral("cert=%1&key=%1").arg(path("client.pem"))
            << QStringLiteral("the private key file '%1' holds no usable PEM key (RSA, EC or DSA, not protected by a passphrase)")
                   .arg(path("client.pem"))
            << int(LinkError::Kind::Config);
        QTest::newRow("CA file without certificates")
            << QStringLiteral("ca=%1").arg(path("client.ext"))
            << QStringLiteral("the CA file '%1' holds no PEM certificate").arg(path("client.ext")) << int(LinkError::Kind::Config);
        QTest::newRow("a directory as CA")
            << QStringLiteral("ca=%1").arg(m_dir.path())
            << QStringLiteral("cannot read the CA certificate file '%1' (").arg(m_dir.path()) << int(LinkError::Kind::Config);
    }
    void unusableFiles()
    {
        QFETCH(QString, options);
        QFETCH(QString, problem);
        QFETCH(int, kind);
        TlsPeer peer(path("server.pem"), path("server.key"), path("ca.pem"));
        auto link = makeLink(QStringLiteral("tls://127.0.0.1:%1?").arg(peer.serverPort()) + options);
        Recorder rec(link.get());
        link->open();
        QCOMPARE(rec.errors.size(), 0); // reported after open() returns
        QTRY_COMPARE_WITH_TIMEOUT(rec.errors.size(), 1, kWaitMs);
        QCOMPARE(int(rec.errors.first().kind), kind);
        const QString expected = link->url().toString() + QStringLiteral(": ") + problem;
        QVERIFY2(rec.lastMessage().startsWith(expected), qPrintable(rec.lastMessage()));
        QCOMPARE(link->state(), Link::State::Closed);
        QTest::qWait(20);
        QCOMPARE(peer.encrypted, 0);
    }
};

QTEST_GUILESS_MAIN(TestTlsLink)
#include "tst_tlslink.moc"
