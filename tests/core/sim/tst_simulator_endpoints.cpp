// The simulator's network endpoints with plain sockets as clients: tcp, rtu-tcp, ascii-tcp,
// udp and rtu-udp on loopback ports the OS chooses; many clients at once, gateway units,
// unknown units (0B or silence), broadcast, malformed requests, limits, idle timeout, faults.

#include "traffic/trafficlog.h"
#include "protocol/adubuilder.h"
#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/simulator.h"
#include "simclient.h"
#include "simfixture.h"
#include "transport/monotonicclock.h"

#include <QtNetwork/QTcpServer>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

namespace {

QByteArray frame(const QByteArray &pdu, Framing framing, quint8 unit, quint16 tid = 1)
{
    return AduBuilder::complete(pdu, AduOptions{framing, unit, tid, 0});
}

QByteArray readHolding(int start, int count)
{
    return pduOf(RequestBuilder::readHoldingRegisters(start, count));
}

QByteArray holdingAnswer(const QList<quint16> &values)
{
    return pduOf(ResponseBuilder::readHoldingRegisters(values));
}

// A client of any endpoint kind behind one interface.
struct Client {
    std::unique_ptr<StreamClient> stream;
    std::unique_ptr<DatagramClient> datagram;
    explicit Client(const SimEndpoint *endpoint)
    {
        if (endpoint->boundUrl().isDatagram())
            datagram = std::make_unique<DatagramClient>(endpoint);
        else
            stream = std::make_unique<StreamClient>(endpoint);
    }
    bool ready() { return !stream || stream->waitConnected(); }
    void send(const QByteArray &bytes) { stream ? stream->send(bytes) : datagram->send(bytes); }
    std::optional<QByteArray> next(int waitMs = kWaitMs) { return stream ? stream->next(waitMs) : datagram->next(waitMs); }
    std::optional<QByteArray> ask(const QByteArray &bytes)
    {
        send(bytes);
        return next();
    }
};

} // namespace

class TestSimulatorEndpoints : public QObject
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
    QList<SimLogEntry> logged(SimLogEntry::Verdict verdict) const
    {
        QList<SimLogEntry> out;
        for (const SimLogEntry &e : m_log) {
            if (e.verdict == verdict)
                out.append(e);
        }
        return out;
    }

private Q_SLOTS:
    void init();
    void cleanup();
    void boundAddress();
    void listenErrors_data();
    void listenErrors();
    void gateway_data();
    void gateway();
    void unknownUnitIgnored();
    void directUnitIds();
    void manyClientsAtOnce();
    void severalEndpointsOneUnit();
    void broadcast_data();
    void broadcast();
    void badChecksumIsSilentAndCounted_data();
    void badChecksumIsSilentAndCounted();
    void malformedPduGetsException03();
    void udpMalformedDropped();
    void mbapBadHeaderCloses();
    void connectionLimit();
    void idleTimeout();
    void responseDelay();
    void faultPlans();
    void answersKeepRequestOrder();
    void logAndTrafficLog();
};

void TestSimulatorEndpoints::init()
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

void TestSimulatorEndpoints::cleanup()
{
    m_sim.reset();
}

void TestSimulatorEndpoints::boundAddress()
{
    SimEndpoint *tcp = listen(QStringLiteral("tcp://:0"));
    QVERIFY(tcp);
    QCOMPARE(tcp->boundUrl().host, QStringLiteral("127.0.0.1")); // no host: loopback only
    QVERIFY(tcp->boundUrl().port != 0);
    QCOMPARE(tcp->url().port, quint16(0));
    QCOMPARE(tcp->name(), QStringLiteral("tcp://127.0.0.1:%1").arg(tcp->boundUrl().port));
    SimEndpoint *udp = listen(QStringLiteral("rtu-udp://127.0.0.1:0"));
    QVERIFY(udp);
    QVERIFY(udp->boundUrl().port != 0);
    QCOMPARE(m_sim->endpoints().size(), 2);
}

void TestSimulatorEndpoints::listenErrors_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QString>("message");
    QTest::newRow("host name") << QStringLiteral("tcp://example.invalid:0") << QStringLiteral("give an IP address");
    QTest::newRow("not a url") << QStringLiteral("tcp:/x") << QStringLiteral("no scheme");
    QTest::newRow("tls without cert") << QStringLiteral("tls://127.0.0.1:0") << QStringLiteral("needs cert=FILE and key=FILE");
    QTest::newRow("tls missing file") << QStringLiteral("tls://127.0.0.1:0?cert=/nonexistent.pem&key=/nonexistent.key")
                                      << QStringLiteral("cannot read the certificate file");
    QTest::newRow("serial missing") << QStringLiteral("rtu:///nonexistent/ttyX") << QStringLiteral("cannot open /nonexistent/ttyX");
    QTest::newRow("delimited") << QStringLiteral("tcp://127.0.0.1:0?framing=delimited")
                               << QStringLiteral("framing=delimited needs a profile with a 'delimited' table");
}

void TestSimulatorEndpoints::listenErrors()
{
    QFETCH(QString, url);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!m_sim->listen(url, {}, &error));
    QVERIFY2(error.contains(message), qPrintable(error));
    QVERIFY(m_sim->endpoints().isEmpty());
}

void TestSimulatorEndpoints::gateway_data()
{
    QTest::addColumn<QString>("url");
    QTest::newRow("tcp") << QStringLiteral("tcp://127.0.0.1:0");
    QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:0");
    QTest::newRow("ascii-tcp") << QStringLiteral("ascii-tcp://127.0.0.1:0");
    QTest::newRow("udp") << QStringLiteral("udp://127.0.0.1:0");
    QTest::newRow("rtu-udp") << QStringLiteral("rtu-udp://127.0.0.1:0");
}

void TestSimulatorEndpoints::gateway()
{
    QFETCH(QString, url);
    SimEndpoint *endpoint = listen(url);
    QVERIFY(endpoint);
    const Framing framing = endpoint->framing();
    Client client(endpoint);
    QVERIFY(client.ready());
    // Each unit its own map; the answer carries the request's unit and transaction id.
    QCOMPARE(client.ask(frame(readHolding(1, 2), framing, 1, 0x1111)), frame(holdingAnswer({10, 20}), framing, 1, 0x1111));
    QCOMPARE(client.ask(frame(readHolding(1, 2), framing, 3, 0x2222)), frame(holdingAnswer({3001, 3002}), framing, 3, 0x2222));
    // Unit 2 is nobody: exception 0B on a network endpoint.
    QCOMPARE(client.ask(frame(readHolding(1, 2), framing, 2, 0x3333)),
             frame(pduOf(ResponseBuilder::exception(0x03, 0x0B)), framing, 2, 0x3333));
    // Writes reach the unit addressed only.
    QCOMPARE(client.ask(frame(pduOf(RequestBuilder::writeSingleRegister(1, 99)), framing, 3, 4)),
             frame(pduOf(ResponseBuilder::writeSingleRegister(1, 99)), framing, 3, 4));
    QCOMPARE(m_sim->unit(3)->value(SimTable::HoldingRegisters, 1), std::optional<quint16>(99));
    QCOMPARE(m_sim->unit(1)->value(SimTable::HoldingRegisters, 1), std::optional<quint16>(10));
    QCOMPARE(logged(SimLogEntry::Verdict::UnknownUnit).size(), 1);
}

void TestSimulatorEndpoints::unknownUnitIgnored()
{
    SimEndpointOptions options;
    options.unknownUnit = SimEndpointOptions::UnknownUnit::Ignore;
    options.units = {1}; // unit 3 exists but not behind this endpoint
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"), options);
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    client.send(frame(readHolding(0, 1), Framing::Tcp, 3, 1)); // ignored
    client.send(frame(readHolding(0, 1), Framing::Tcp, 2, 2)); // ignored
    // Answers come in request order, so the first answer is the third request's.
    QCOMPARE(client.ask(frame(readHolding(0, 1), Framing::Tcp, 1, 3)), frame(holdingAnswer({0}), Framing::Tcp, 1, 3));
    QCOMPARE(client.framesWaiting(), 0);
    QCOMPARE(logged(SimLogEntry::Verdict::UnknownUnit).size(), 2);
}

void TestSimulatorEndpoints::directUnitIds()
{
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    // Messaging on TCP/IP V1.0b 4.4.1.1: 0xFF (and 0) address the server itself: the lowest unit.
    QCOMPARE(client.ask(frame(readHolding(2, 1), Framing::Tcp, 0xFF, 7)), frame(holdingAnswer({20}), Framing::Tcp, 0xFF, 7));
    QCOMPARE(client.ask(frame(readHolding(2, 1), Framing::Tcp, 0x00, 8)), frame(holdingAnswer({20}), Framing::Tcp, 0x00, 8));
    SimEndpointOptions strict;
    strict.directUnitIds = false;
    SimEndpoint *other = listen(QStringLiteral("tcp://127.0.0.1:0"), strict);
    QVERIFY(other);
    StreamClient second(other);
    QVERIFY(second.waitConnected());
    QCOMPARE(second.ask(frame(readHolding(2, 1), Framing::Tcp, 0xFF, 9)),
             frame(pduOf(ResponseBuilder::exception(0x03, 0x0B)), Framing::Tcp, 0xFF, 9));
}

void TestSimulatorEndpoints::manyClientsAtOnce()
{
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    constexpr int kClients = 20;
    constexpr int kRequests = 25;
    std::vector<std::unique_ptr<StreamClient>> clients;
    for (int c = 0; c < kClients; ++c)
        clients.push_back(std::make_unique<StreamClient>(endpoint));
    for (auto &client : clients)
        QVERIFY(client->waitConnected());
    QTRY_COMPARE_WITH_TIMEOUT(endpoint->connectionCount(), kClients, kWaitMs);
    // Every client pipelines all its requests before reading any answer.
    for (int c = 0; c < kClients; ++c) {
        for (int i = 0; i < kRequests; ++i)
            clients[c]->send(frame(readHolding((c + i) % 32, 1), Framing::Tcp, 1, quint16(c * 100 + i)));
    }
    for (int c = 0; c < kClients; ++c) {
        for (int i = 0; i < kRequests; ++i) {
            const auto answer = clients[c]->next();
            QVERIFY2(answer, qPrintable(QStringLiteral("client %1, answer %2 missing").arg(c).arg(i)));
            QCOMPARE(*answer, frame(holdingAnswer({quint16(10 * ((c + i) % 32))}), Framing::Tcp, 1, quint16(c * 100 + i)));
        }
    }
    QCOMPARE(logged(SimLogEntry::Verdict::Answered).size(), kClients * kRequests);
}

void TestSimulatorEndpoints::severalEndpointsOneUnit()
{
    SimEndpoint *tcp = listen(QStringLiteral("tcp://127.0.0.1:0"));
    SimEndpoint *rtu = listen(QStringLiteral("rtu-tcp://127.0.0.1:0"));
    SimEndpoint *udp = listen(QStringLiteral("udp://127.0.0.1:0"));
    QVERIFY(tcp && rtu && udp);
    Client a(tcp);
    Client b(rtu);
    Client c(udp);
    QVERIFY(a.ready() && b.ready() && c.ready());
    QVERIFY(a.ask(frame(pduOf(RequestBuilder::writeSingleRegister(7, 0x7777)), Framing::Tcp, 1)));
    QCOMPARE(b.ask(frame(readHolding(7, 1), Framing::Rtu, 1)), frame(holdingAnswer({0x7777}), Framing::Rtu, 1));
    QCOMPARE(c.ask(frame(readHolding(7, 1), Framing::Udp, 1, 5)), frame(holdingAnswer({0x7777}), Framing::Udp, 1, 5));
}

void TestSimulatorEndpoints::broadcast_data()
{
    QTest::addColumn<QString>("url");
    QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:0");
    QTest::newRow("ascii-tcp") << QStringLiteral("ascii-tcp://127.0.0.1:0");
    QTest::newRow("rtu-udp") << QStringLiteral("rtu-udp://127.0.0.1:0");
}

void TestSimulatorEndpoints::broadcast()
{
    QFETCH(QString, url);
    SimEndpoint *endpoint = listen(url);
    QVERIFY(endpoint);
    const Framing framing = endpoint->framing();
    Client client(endpoint);
    QVERIFY(client.ready());
    // Serial Line V1.02, 2.1: unit 0 reaches every unit, none answers.
    client.send(frame(pduOf(RequestBuilder::writeSingleRegister(5, 0x55)), framing, 0));
    QCOMPARE(client.ask(frame(readHolding(5, 1), framing, 1)), frame(holdingAnswer({0x55}), framing, 1));
    QCOMPARE(m_sim->unit(3)->value(SimTable::HoldingRegisters, 5), std::optional<quint16>(0x55));
    QCOMPARE(logged(SimLogEntry::Verdict::NoAnswer).size(), 1);
    QCOMPARE(m_sim->unit(1)->counters().serverNoResponse, quint16(1));
}

void TestSimulatorEndpoints::badChecksumIsSilentAndCounted_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("bad");
    QByteArray rtu = frame(readHolding(0, 1), Framing::Rtu, 1);
    rtu[rtu.size() - 1] = char(rtu.back() ^ 0x5A);
    QByteArray ascii = frame(readHolding(0, 1), Framing::Ascii, 1);
    ascii[ascii.size() - 3] = ascii[ascii.size() - 3] == '0' ? '1' : '0'; // an LRC digit
    QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:0") << rtu;
    QTest::newRow("ascii-tcp") << QStringLiteral("ascii-tcp://127.0.0.1:0") << ascii;
    QTest::newRow("rtu-udp") << QStringLiteral("rtu-udp://127.0.0.1:0") << rtu;
}

void TestSimulatorEndpoints::badChecksumIsSilentAndCounted()
{
    QFETCH(QString, url);
    QFETCH(QByteArray, bad);
    SimEndpoint *endpoint = listen(url);
    QVERIFY(endpoint);
    const Framing framing = endpoint->framing();
    Client client(endpoint);
    QVERIFY(client.ready());
    client.send(bad);
    // Serial Line V1.02, 2.5.1.2: discarded without an answer; 08/000C counts it.
    const auto answer = client.ask(frame(pduOf(RequestBuilder::diagnostics(0x0C)), framing, 1));
    QCOMPARE(answer, frame(pduOf(ResponseBuilder::diagnosticsValue(0x0C, 1)), framing, 1));
    QVERIFY(!logged(SimLogEntry::Verdict::ChecksumError).isEmpty() || !logged(SimLogEntry::Verdict::Garbage).isEmpty());
}

void TestSimulatorEndpoints::malformedPduGetsException03()
{
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    // A well-framed MBAP request whose PDU is a byte short: V1.1b3 says 03.
    QCOMPARE(client.ask(frame(hex("03 00 00 00"), Framing::Tcp, 1, 3)),
             frame(pduOf(ResponseBuilder::exception(0x03, 0x03)), Framing::Tcp, 1, 3));
    QCOMPARE(client.ask(frame(hex("2B 0E"), Framing::Tcp, 1, 4)),
             frame(pduOf(ResponseBuilder::exception(0x2B, 0x03)), Framing::Tcp, 1, 4));
}

void TestSimulatorEndpoints::udpMalformedDropped()
{
    SimEndpoint *endpoint = listen(QStringLiteral("udp://127.0.0.1:0"));
    QVERIFY(endpoint);
    DatagramClient client(endpoint);
    client.send(hex("00 01 00 01 00 06 01 03 00 00 00 01")); // protocol id 1
    client.send(hex("00 02 00 00 00 09 01 03 00 00 00 01")); // length 9, 6 bytes follow
    client.send(hex("00 03 00"));                            // a piece of a header
    QCOMPARE(client.ask(frame(readHolding(0, 1), Framing::Udp, 1, 4)), frame(holdingAnswer({0}), Framing::Udp, 1, 4));
    QCOMPARE(logged(SimLogEntry::Verdict::Malformed).size(), 3);
    QVERIFY(logged(SimLogEntry::Verdict::Malformed).at(0).reason.contains(QStringLiteral("protocol id 1")));
}

void TestSimulatorEndpoints::mbapBadHeaderCloses()
{
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    client.send(hex("00 01 00 05 00 06 01 03 00 00 00 01")); // protocol id 5
    QVERIFY(client.waitDisconnected());
    QCOMPARE(client.framesWaiting(), 0);
    QVERIFY(!logged(SimLogEntry::Verdict::Garbage).isEmpty());
    QTRY_COMPARE_WITH_TIMEOUT(logged(SimLogEntry::Verdict::ConnectionClosed).size(), 1, kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(endpoint->connectionCount(), 0, kWaitMs);
}

void TestSimulatorEndpoints::connectionLimit()
{
    SimEndpointOptions options;
    options.maxConnections = 2;
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"), options);
    QVERIFY(endpoint);
    auto a = std::make_unique<StreamClient>(endpoint);
    StreamClient b(endpoint);
    QVERIFY(a->waitConnected() && b.waitConnected());
    QTRY_COMPARE_WITH_TIMEOUT(endpoint->connectionCount(), 2, kWaitMs);
    StreamClient c(endpoint);
    QVERIFY(c.waitDisconnected()); // accepted by the kernel, closed by the simulator
    QCOMPARE(logged(SimLogEntry::Verdict::ConnectionRefused).size(), 1);
    QVERIFY(b.ask(frame(readHolding(0, 1), Framing::Tcp, 1)));
    a.reset(); // one leaves: room for another
    QTRY_COMPARE_WITH_TIMEOUT(endpoint->connectionCount(), 1, kWaitMs);
    StreamClient d(endpoint);
    QVERIFY(d.waitConnected());
    QCOMPARE(d.ask(frame(readHolding(0, 1), Framing::Tcp, 1, 2)), frame(holdingAnswer({0}), Framing::Tcp, 1, 2));
}

void TestSimulatorEndpoints::idleTimeout()
{
    SimEndpointOptions options;
    options.idleTimeoutMs = 200;
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"), options);
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    QVERIFY(client.ask(frame(readHolding(0, 1), Framing::Tcp, 1)));
    QVERIFY(client.waitDisconnected());
    const auto closed = logged(SimLogEntry::Verdict::ConnectionClosed);
    QCOMPARE(closed.size(), 1);
    QVERIFY2(closed.first().reason.contains(QStringLiteral("idle for 200 ms")), qPrintable(closed.first().reason));
}

void TestSimulatorEndpoints::responseDelay()
{
    m_sim->unit(1)->setResponseDelayNs(80'000'000);
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    const qint64 sent = monotonicNowNs();
    QVERIFY(client.ask(frame(readHolding(0, 1), Framing::Tcp, 1)));
    QVERIFY(monotonicNowNs() - sent >= 80'000'000); // a lower bound, never a speed
}

void TestSimulatorEndpoints::faultPlans()
{
    m_sim->setFaultHook([](const SimExchange &x) {
        FaultPlan plan;
        const QByteArray &adu = x.responseAdu;
        switch (x.transactionId) {
        case 1: // in two pieces 30 ms apart
            plan.chunks = {{adu.left(3), 0}, {adu.mid(3), 30'000'000}};
            break;
        case 2: // not at all
            plan.drop = true;
            break;
        case 3: // junk first, then the answer and a close
            plan.chunks = {{QByteArray(3, char(0xEE)), 0}, {adu, 0}};
            plan.closeAfter = true;
            break;
        default:
            plan.closeBefore = true;
            break;
        }
        return plan;
    });
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    const QByteArray expected1 = frame(holdingAnswer({0}), Framing::Tcp, 1, 1);
    QCOMPARE(client.ask(frame(readHolding(0, 1), Framing::Tcp, 1, 1)), expected1);
    client.send(frame(readHolding(0, 1), Framing::Tcp, 1, 2)); // dropped
    QCOMPARE(client.ask(frame(readHolding(0, 1), Framing::Tcp, 1, 3)), frame(holdingAnswer({0}), Framing::Tcp, 1, 3));
    QVERIFY(client.waitDisconnected());
    QCOMPARE(client.framesWaiting(), 0);
    // Close before answering.
    StreamClient other(endpoint);
    QVERIFY(other.waitConnected());
    other.send(frame(readHolding(0, 1), Framing::Tcp, 1, 4));
    QVERIFY(other.waitDisconnected());
    QCOMPARE(other.framesWaiting(), 0);
}

void TestSimulatorEndpoints::answersKeepRequestOrder()
{
    // A slow answer holds back a fast one on a stream, as a device answering one at a time.
    m_sim->setFaultHook([](const SimExchange &x) {
        FaultPlan plan;
        plan.chunks = {{x.responseAdu, x.transactionId == 1 ? 100'000'000 : 0}};
        return plan;
    });
    SimEndpoint *endpoint = listen(QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    client.send(frame(readHolding(0, 1), Framing::Tcp, 1, 1) + frame(readHolding(1, 1), Framing::Tcp, 1, 2));
    QCOMPARE(client.next(), frame(holdingAnswer({0}), Framing::Tcp, 1, 1));
    QCOMPARE(client.next(), frame(holdingAnswer({10}), Framing::Tcp, 1, 2));
}

void TestSimulatorEndpoints::logAndTrafficLog()
{
    TrafficLog traffic;
    m_sim->setTrafficLog(&traffic);
    SimEndpoint *endpoint = listen(QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    const QByteArray request = frame(readHolding(0, 2), Framing::Rtu, 1);
    const QByteArray answer = frame(holdingAnswer({0, 10}), Framing::Rtu, 1);
    QCOMPARE(client.ask(request), answer);
    const auto answered = logged(SimLogEntry::Verdict::Answered);
    QCOMPARE(answered.size(), 1);
    QCOMPARE(answered.first().request, request);
    QCOMPARE(answered.first().response, answer);
    QCOMPARE(answered.first().unitId, 1);
    QCOMPARE(answered.first().endpoint, endpoint->name());
    QVERIFY(answered.first().peer.startsWith(QStringLiteral("127.0.0.1:")));
    QCOMPARE(logged(SimLogEntry::Verdict::ConnectionOpened).size(), 1);
    QCOMPARE(traffic.size(), quint64(2));
    QCOMPARE(traffic.at(0).direction, TrafficDirection::In);
    QCOMPARE(traffic.at(0).bytes.toByteArray(), request);
    QCOMPARE(traffic.at(1).direction, TrafficDirection::Out);
    QCOMPARE(traffic.at(1).bytes.toByteArray(), answer);
    QCOMPARE(traffic.linkName(traffic.at(0).link), endpoint->name());
}

QTEST_GUILESS_MAIN(TestSimulatorEndpoints)
#include "tst_simulator_endpoints.moc"
