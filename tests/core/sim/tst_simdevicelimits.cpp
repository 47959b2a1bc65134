// Device limits and unknown units (DeviceLimits, docs/profiles.md "Device limits"): the request
// path (Simulator::handleFrame) is driven with arrival times made up by the test, so gaps and
// warm-ups are exact and no test depends on how fast the machine is; the client limit with real
// sockets on loopback.

#include "profile/profileloader.h"
#include "protocol/adubuilder.h"
#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/profileapplier.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "simclient.h"
#include "simfixture.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

Q_DECLARE_METATYPE(mbscope::SimEndpointOptions::UnknownUnit)
Q_DECLARE_METATYPE(mbscope::DeviceLimits::TooSoon)

namespace {

constexpr qint64 kMs = 1'000'000;
constexpr qint64 kT0 = 1'000'000 * kMs; // a made-up arrival time, far from 0 (0 means "none")

QByteArray tcp(const QByteArray &pdu, quint8 unit, quint16 tid = 1)
{
    return AduBuilder::complete(pdu, AduOptions{Framing::Tcp, unit, tid, 0});
}

QByteArray readHolding(int start, int count)
{
    return pduOf(RequestBuilder::readHoldingRegisters(start, count));
}

// The answer's PDU, or "silent".
QString answerOf(const FaultPlan &plan)
{
    if (plan.drop || plan.chunks.isEmpty())
        return QStringLiteral("silent");
    return hexOf(plan.chunks.first().bytes.mid(7));
}

} // namespace

class TestSimDeviceLimits : public QObject
{
    Q_OBJECT
private:
    std::unique_ptr<Simulator> m_sim;
    QList<SimLogEntry> m_log;

    SimEndpoint *listen(const QString &url, const SimEndpointOptions &options = {})
    {
        QString error;
        SimEndpoint *endpoint = m_sim->listen(url, options, &error);
        if (!endpoint)
            qWarning().noquote() << error;
        return endpoint;
    }
    FaultPlan ask(SimEndpoint *endpoint, const QByteArray &adu, qint64 atNs, qint64 connectedNs = 0)
    {
        return m_sim->handleFrame(endpoint, adu, FrameStatus::Valid, QStringLiteral("test"), atNs, connectedNs);
    }

private Q_SLOTS:
    void init()
    {
        m_sim = std::make_unique<Simulator>();
        m_log.clear();
        connect(m_sim.get(), &Simulator::logged, this, [this](const SimLogEntry &e) { m_log.append(e); });
        QVERIFY(m_sim->adoptUnit(makeUnit(1)));
        SimUnit *three = m_sim->addUnit(3);
        SimRange r;
        r.table = SimTable::HoldingRegisters;
        r.count = 10;
        for (int i = 0; i < 10; ++i)
            r.values.append(quint16(3000 + i));
        QVERIFY(three->addRange(r));
    }
    void cleanup() { m_sim.reset(); }

    void unknownUnit_data();
    void unknownUnit();
    void minGap_data();
    void minGap();
    void maxQuantity();
    void warmUp();
    void dropOldestClient();
    void closesAfterAnswer();
    void profileKeys();
};

void TestSimDeviceLimits::unknownUnit_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<SimEndpointOptions::UnknownUnit>("policy");
    QTest::addColumn<int>("unit");
    QTest::addColumn<QString>("answer"); // the PDU, or "silent"
    using U = SimEndpointOptions::UnknownUnit;
    const QString tcpUrl = QStringLiteral("tcp://127.0.0.1:0");
    const QString udpUrl = QStringLiteral("udp://127.0.0.1:0");
    // Unit 1 holds 10 x address: register 2 is 20 (0x0014).
    QTest::newRow("tcp first: unit 7 answered by unit 1") << tcpUrl << U::FirstUnit << 7 << QStringLiteral("03 02 00 14");
    QTest::newRow("udp first: unit 7 answered by unit 1") << udpUrl << U::FirstUnit << 7 << QStringLiteral("03 02 00 14");
    QTest::newRow("tcp first: unit 3 is its own") << tcpUrl << U::FirstUnit << 3 << QStringLiteral("03 02 0B BA");
    QTest::newRow("tcp exception: 0B") << tcpUrl << U::Exception << 7 << QStringLiteral("83 0B");
    QTest::newRow("tcp silent") << tcpUrl << U::Ignore << 7 << QStringLiteral("silent");
    QTest::newRow("tcp auto: 0B") << tcpUrl << U::Auto << 7 << QStringLiteral("83 0B");
}

void TestSimDeviceLimits::unknownUnit()
{
    QFETCH(QString, url);
    QFETCH(SimEndpointOptions::UnknownUnit, policy);
    QFETCH(int, unit);
    QFETCH(QString, answer);
    SimEndpointOptions options;
    options.unknownUnit = policy;
    SimEndpoint *endpoint = listen(url, options);
    QVERIFY(endpoint);
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), quint8(unit)), kT0)), answer);
}

void TestSimDeviceLimits::minGap_data()
{
    QTest::addColumn<DeviceLimits::TooSoon>("tooSoon");
    QTest::addColumn<QString>("refused");
    QTest::newRow("busy") << DeviceLimits::TooSoon::Busy << QStringLiteral("83 06");
    QTest::newRow("silent") << DeviceLimits::TooSoon::Silent << QStringLiteral("silent");
}

void TestSimDeviceLimits::minGap()
{
    QFETCH(DeviceLimits::TooSoon, tooSoon);
    QFETCH(QString, refused);
    DeviceLimits limits;
    limits.minGapMs = 10;
    limits.tooSoon = tooSoon;
    m_sim->setLimits(limits);
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    const QString ok = QStringLiteral("03 02 00 14");
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), kT0)), ok);
    // 5 ms later: too soon. The gap runs from the last request taken (kT0), so 12 ms after it
    // is taken although only 7 ms after the refused one; then 9.9 ms after that is too soon.
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), kT0 + 5 * kMs)), refused);
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), kT0 + 12 * kMs)), ok);
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), kT0 + 12 * kMs + 9'900'000)), refused);
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), kT0 + 22 * kMs)), ok);
    QVERIFY2(m_log.at(1).reason.contains(QStringLiteral("refused by minGapMs: 5.0 ms after the last request taken, minGapMs is 10")),
             qPrintable(m_log.at(1).reason));
}

void TestSimDeviceLimits::maxQuantity()
{
    DeviceLimits limits;
    limits.maxQuantity.insert(0x03, 16);
    limits.maxQuantity.insert(0x0F, 8);
    m_sim->setLimits(limits);
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(0, 16), 1), kT0)).left(5), QStringLiteral("03 20"));
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(0, 17), 1), kT0)), QStringLiteral("83 03"));
    QVERIFY2(m_log.last().reason.contains(QStringLiteral("refused by maxQuantity: quantity 17 of function 03, maxQuantity is 16")),
             qPrintable(m_log.last().reason));
    // Other functions keep the specification's limits: 01 of 32 coils.
    QCOMPARE(answerOf(ask(endpoint, tcp(pduOf(RequestBuilder::readCoils(0, 32)), 1), kT0)).left(5), QStringLiteral("01 04"));
    QCOMPARE(answerOf(ask(endpoint, tcp(hex("0F 00 00 00 09 02 FF 01"), 1), kT0)), QStringLiteral("8F 03"));
    QCOMPARE(answerOf(ask(endpoint, tcp(hex("0F 00 00 00 08 01 FF"), 1), kT0)), QStringLiteral("0F 00 00 00 08"));
}

void TestSimDeviceLimits::warmUp()
{
    DeviceLimits limits;
    limits.warmUpMs = 500;
    m_sim->setLimits(limits);
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    const qint64 connected = kT0;
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), connected + 100 * kMs, connected)), QStringLiteral("silent"));
    QVERIFY2(m_log.last().reason.contains(QStringLiteral("refused by warmUpMs: 100.0 ms after connecting, warmUpMs is 500")),
             qPrintable(m_log.last().reason));
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), connected + 499 * kMs, connected)), QStringLiteral("silent"));
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), connected + 500 * kMs, connected)), QStringLiteral("03 02 00 14"));
    // A later connection warms up again.
    QCOMPARE(answerOf(ask(endpoint, tcp(readHolding(2, 1), 1), connected + 600 * kMs, connected + 550 * kMs)),
             QStringLiteral("silent"));
}

// maxClients 2 with dropOldest: the third client knocks the first off and is served.
void TestSimDeviceLimits::dropOldestClient()
{
    SimEndpointOptions options;
    options.maxConnections = 2;
    options.dropOldestConnection = true;
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"), options);
    QVERIFY(endpoint);
    StreamClient a(endpoint);
    QVERIFY(a.waitConnected());
    QTRY_COMPARE_WITH_TIMEOUT(endpoint->connectionCount(), 1, kWaitMs);
    StreamClient b(endpoint);
    QVERIFY(b.waitConnected());
    QTRY_COMPARE_WITH_TIMEOUT(endpoint->connectionCount(), 2, kWaitMs);
    StreamClient c(endpoint);
    QVERIFY(c.waitConnected());
    QVERIFY(a.waitDisconnected());
    QCOMPARE(endpoint->connectionCount(), 2);
    QCOMPARE(c.ask(tcp(readHolding(2, 1), 1, 9)), tcp(pduOf(ResponseBuilder::readHoldingRegisters({20})), 1, 9));
    QCOMPARE(b.ask(tcp(readHolding(2, 1), 1, 8)), tcp(pduOf(ResponseBuilder::readHoldingRegisters({20})), 1, 8));
    bool knocked = false;
    for (const SimLogEntry &e : std::as_const(m_log))
        knocked = knocked || e.reason == QStringLiteral("knocked off by a new client: maxClients is 2, extraClients is dropOldest");
    QVERIFY(knocked);
}

// closesAfterAnswer: a connection is closed once each answer has left, with the reason in the
// log; a datagram endpoint has no connection to close.
void TestSimDeviceLimits::closesAfterAnswer()
{
    DeviceLimits limits;
    limits.closesAfterAnswer = true;
    m_sim->setLimits(limits);
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    const FaultPlan plan = ask(endpoint, tcp(readHolding(2, 1), 1), kT0);
    QCOMPARE(answerOf(plan), QStringLiteral("03 02 00 14"));
    QVERIFY(plan.closeAfter);
    QCOMPARE(plan.closeReason, QStringLiteral("closesAfterAnswer: the device hangs up after each answer"));
    SimEndpoint *udp = listen(QStringLiteral("udp://127.0.0.1:0"));
    QVERIFY(udp);
    QVERIFY(!ask(udp, tcp(readHolding(2, 1), 1), kT0 + 10 * kMs).closeAfter);

    // On a real connection: the answer arrives whole, then the connection ends.
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    QCOMPARE(client.ask(tcp(readHolding(2, 1), 1, 7)), tcp(pduOf(ResponseBuilder::readHoldingRegisters({20})), 1, 7));
    QVERIFY(client.waitDisconnected());
    bool said = false;
    for (const SimLogEntry &e : std::as_const(m_log))
        said = said || e.reason == QStringLiteral("closesAfterAnswer: the device hangs up after each answer");
    QVERIFY(said);
}

// The profile keys reach the simulator's objects.
void TestSimDeviceLimits::profileKeys()
{
    const ProfileLoadResult r = ProfileLoader::parse(R"({"name": "t", "unknownUnit": "first",
        "limits": {"minGapMs": 20, "tooSoon": "silent", "maxClients": 1, "extraClients": "dropOldest",
                   "maxQuantity": {"0x03": 16, "16": 8}, "warmUpMs": 250, "closesAfterAnswer": true},
        "units": [{"id": 1}]})",
                                                     QStringLiteral("test"));
    QVERIFY2(r.ok, qPrintable(r.errorText()));
    const DeviceLimits &l = r.profile.limits;
    QCOMPARE(l.unknownUnit, DeviceLimits::UnknownUnit::FirstUnit);
    QCOMPARE(l.minGapMs, 20.0);
    QCOMPARE(l.tooSoon, DeviceLimits::TooSoon::Silent);
    QCOMPARE(l.maxQuantity.value(0x03), 16);
    QCOMPARE(l.maxQuantity.value(0x10), 8);
    QCOMPARE(l.warmUpMs, 250.0);
    QVERIFY(l.closesAfterAnswer);
    const SimEndpointOptions options = ProfileApplier::endpointOptions(r.profile);
    QCOMPARE(options.unknownUnit, SimEndpointOptions::UnknownUnit::FirstUnit);
    QCOMPARE(options.maxConnections, 1);
    QVERIFY(options.dropOldestConnection);
    // Without limits: the endpoint's defaults.
    const ProfileLoadResult plain = ProfileLoader::parse(R"({"name": "t", "units": [{"id": 1}]})", QStringLiteral("test"));
    QVERIFY(plain.ok);
    QCOMPARE(ProfileApplier::endpointOptions(plain.profile).maxConnections, SimEndpointOptions().maxConnections);
    QVERIFY(!plain.profile.limits.limitsRequests());
    QVERIFY(!plain.profile.limits.closesAfterAnswer);
}

QTEST_GUILESS_MAIN(TestSimDeviceLimits)
#include "tst_simdevicelimits.moc"
