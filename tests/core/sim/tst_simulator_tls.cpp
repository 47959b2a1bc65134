// The simulator's tls:// endpoint (MODBUS/TCP Security: MBAP over mutual TLS) with throwaway
// openssl certificates: a client with a certificate from the CA is served; one without a
// certificate, or with one from another CA, is refused and the refusal logged.

#include "protocol/adubuilder.h"
#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "simclient.h"
#include "simfixture.h"
#include "testcertificates.h"

#include <QtCore/QTemporaryDir>
#include <QtNetwork/QSslCertificate>
#include <QtNetwork/QSslConfiguration>
#include <QtNetwork/QSslKey>
#include <QtNetwork/QSslSocket>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

class TestSimulatorTls : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    QString path(const QString &name) const { return m_dir.filePath(name); }

    // A client socket with the given certificate (empty: none), trusting the test CA.
    std::unique_ptr<QSslSocket> client(const QString &name)
    {
        auto socket = std::make_unique<QSslSocket>();
        QSslConfiguration config = socket->sslConfiguration();
        config.setCaCertificates(QSslCertificate::fromPath(path(QStringLiteral("ca.pem"))));
        if (!name.isEmpty()) {
            config.setLocalCertificateChain(QSslCertificate::fromPath(path(name + QStringLiteral(".pem"))));
            QFile key(path(name + QStringLiteral(".key")));
            if (key.open(QIODevice::ReadOnly))
                config.setPrivateKey(QSslKey(key.readAll(), QSsl::Ec));
        }
        config.setPeerVerifyMode(QSslSocket::VerifyPeer);
        socket->setSslConfiguration(config);
        return socket;
    }

    QString serverUrl() const
    {
        return QStringLiteral("tls://127.0.0.1:0?cert=%1&key=%2&ca=%3")
            .arg(path(QStringLiteral("server.pem")), path(QStringLiteral("server.key")), path(QStringLiteral("ca.pem")));
    }

private Q_SLOTS:
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
        QVERIFY2(certificates.issue(QStringLiteral("server"), "subjectAltName=IP:127.0.0.1\nextendedKeyUsage=serverAuth\n",
                                    QStringLiteral("ca")),
                 qPrintable(certificates.error()));
        QVERIFY2(certificates.issue(QStringLiteral("client"), "extendedKeyUsage=clientAuth\n", QStringLiteral("ca")),
                 qPrintable(certificates.error()));
        QVERIFY2(certificates.issue(QStringLiteral("stranger"), "extendedKeyUsage=clientAuth\n", QStringLiteral("otherca")),
                 qPrintable(certificates.error()));
    }

    void mutualTls()
    {
        Simulator sim;
        QVERIFY(sim.adoptUnit(makeUnit(1)));
        QString error;
        SimEndpoint *endpoint = sim.listen(serverUrl(), {}, &error);
        QVERIFY2(endpoint, qPrintable(error));
        auto socket = client(QStringLiteral("client"));
        socket->connectToHostEncrypted(QStringLiteral("127.0.0.1"), endpoint->boundUrl().port);
        QVERIFY2(QTest::qWaitFor([&] { return socket->isEncrypted(); }, kWaitMs), qPrintable(socket->errorString()));
        const QByteArray request = AduBuilder::mbap(pduOf(RequestBuilder::readHoldingRegisters(1, 2)), 1, 0x0A0B);
        socket->write(request);
        const QByteArray expected = AduBuilder::mbap(pduOf(ResponseBuilder::readHoldingRegisters({10, 20})), 1, 0x0A0B);
        QByteArray got;
        QVERIFY(QTest::qWaitFor([&] { got += socket->readAll(); return got.size() >= expected.size(); }, kWaitMs));
        QCOMPARE(got, expected);
    }

    void refusedClients_data()
    {
        QTest::addColumn<QString>("certificate");
        QTest::newRow("no certificate") << QString();
        QTest::newRow("another CA") << QStringLiteral("stranger");
    }

    void refusedClients()
    {
        QFETCH(QString, certificate);
        Simulator sim;
        QVERIFY(sim.adoptUnit(makeUnit(1)));
        QList<SimLogEntry> log;
        connect(&sim, &Simulator::logged, this, [&log](const SimLogEntry &e) { log.append(e); });
        QString error;
        SimEndpoint *endpoint = sim.listen(serverUrl(), {}, &error);
        QVERIFY2(endpoint, qPrintable(error));
        auto socket = client(certificate);
        socket->connectToHostEncrypted(QStringLiteral("127.0.0.1"), endpoint->boundUrl().port);
        socket->write(AduBuilder::mbap(pduOf(RequestBuilder::readHoldingRegisters(1, 2)), 1, 1));
        QVERIFY(QTest::qWaitFor([&] { return socket->state() == QAbstractSocket::UnconnectedState; }, kWaitMs));
        QVERIFY(QTest::qWaitFor([&] {
            for (const SimLogEntry &e : log) {
                if (e.verdict == SimLogEntry::Verdict::ConnectionRefused)
                    return true;
            }
            return false;
        }, kWaitMs));
        QCOMPARE(endpoint->connectionCount(), 0);
    }
};

QTEST_GUILESS_MAIN(TestSimulatorTls)
#include "tst_simulator_tls.moc"
