// Random requests never crash the simulator nor make it answer outside the specification:
// random PDUs to SimProcessor, random frames to Simulator::handleFrame for every framing, and
// random bytes down an rtu-tcp and an ascii-tcp stream followed by a request that must still be
// answered. Seeded: a failure repeats.

#include "protocol/adubuilder.h"
#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/simendpoint.h"
#include "sim/simprocessor.h"
#include "sim/simulator.h"
#include "simclient.h"
#include "simfixture.h"

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

namespace {

QByteArray randomBytes(QRandomGenerator &random, int size)
{
    QByteArray bytes(size, 0);
    for (char &c : bytes)
        c = char(random.bounded(256));
    return bytes;
}

// A PDU that starts like a real request more often than not, so the checks past the first
// byte are reached.
QByteArray randomPdu(QRandomGenerator &random)
{
    static const QList<quint8> codes = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x0B, 0x0C, 0x0F,
                                        0x10, 0x11, 0x14, 0x15, 0x16, 0x17, 0x18, 0x2B};
    const int size = 1 + int(random.bounded(random.bounded(2) ? 12 : 253));
    QByteArray pdu = randomBytes(random, size);
    if (random.bounded(4) != 0)
        pdu[0] = char(codes.at(random.bounded(int(codes.size()))));
    if (pdu.size() > 2 && random.bounded(2)) // small addresses and quantities reach the map
        pdu[1] = 0;
    if (pdu.size() > 3 && random.bounded(2))
        pdu[3] = 0;
    if (pdu.size() > 1 && quint8(pdu[0]) == 0x2B && random.bounded(2))
        pdu[1] = 0x0E;
    if (random.bounded(3) == 0) {
        // The shape of a read or single write: address and quantity (or value) within the map.
        pdu.resize(5);
        pdu[1] = 0;
        pdu[2] = char(random.bounded(40));
        pdu[3] = 0;
        pdu[4] = char(random.bounded(12));
    }
    return pdu;
}

} // namespace

class TestSimRobustness : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void randomPdus();
    void randomFrames_data();
    void randomFrames();
    void randomStream_data();
    void randomStream();
};

void TestSimRobustness::randomPdus()
{
    QRandomGenerator random(20240401);
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    int answers = 0;
    int normal = 0;
    for (int i = 0; i < 30000; ++i) {
        const QByteArray request = randomPdu(random);
        if (random.bounded(50) == 0)
            unit->setListenOnly(false); // 08/04 may have been drawn: come back now and then
        const SimReply reply = processor.process(request, random.bounded(20) == 0);
        if (!reply.hasAnswer())
            continue;
        ++answers;
        QVERIFY2(reply.pdu.size() <= 253, qPrintable(hexOf(request)));
        QCOMPARE(quint8(reply.pdu[0]) & 0x7F, quint8(request[0]) & 0x7F);
        if (reply.kind == SimReply::Kind::Exception) {
            QCOMPARE(reply.pdu.size(), 2);
            const quint8 code = quint8(reply.pdu[1]);
            QVERIFY2(code == 1 || code == 2 || code == 3 || code == 4 || code == 6, qPrintable(hexOf(request)));
            continue;
        }
        ++normal;
        QString why;
        QVERIFY2(dissectsCleanly(request, reply.pdu, &why),
                 qPrintable(hexOf(request) + QStringLiteral(" -> ") + hexOf(reply.pdu) + QStringLiteral(": ") + why));
    }
    QVERIFY(answers > 10000);
    QVERIFY2(normal > 1000, qPrintable(QString::number(normal))); // the random requests reach the map
}

void TestSimRobustness::randomFrames_data()
{
    QTest::addColumn<QString>("url");
    QTest::newRow("tcp") << QStringLiteral("tcp://127.0.0.1:0");
    QTest::newRow("udp") << QStringLiteral("udp://127.0.0.1:0");
    QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:0");
    QTest::newRow("ascii-tcp") << QStringLiteral("ascii-tcp://127.0.0.1:0");
}

void TestSimRobustness::randomFrames()
{
    QFETCH(QString, url);
    QRandomGenerator random(77);
    Simulator sim;
    QVERIFY(sim.adoptUnit(makeUnit(1)));
    QVERIFY(sim.adoptUnit(makeUnit(2)));
    SimEndpoint *endpoint = sim.listen(url);
    QVERIFY(endpoint);
    const Framing framing = endpoint->framing();
    for (int i = 0; i < 5000; ++i) {
        QByteArray frame;
        switch (random.bounded(3)) {
        case 0: frame = randomBytes(random, int(random.bounded(300))); break;
        case 1: // a well-framed random PDU to a random unit
            frame = AduBuilder::complete(randomPdu(random), AduOptions{framing, quint8(random.bounded(4)), quint16(i), 0});
            break;
        default: { // a well-framed one with a byte flipped
            frame = AduBuilder::complete(randomPdu(random), AduOptions{framing, 1, quint16(i), 0});
            const int at = int(random.bounded(frame.size()));
            frame[at] = char(frame[at] ^ (1 << random.bounded(8)));
            break;
        }
        }
        const auto status = FrameStatus(random.bounded(4));
        const FaultPlan plan = sim.handleFrame(endpoint, frame, status, QStringLiteral("fuzz"), 0);
        QVERIFY(plan.drop || plan.chunks.size() == 1);
        if (!plan.drop)
            QVERIFY(plan.chunks.first().bytes.size() <= 513);
        sim.unit(1)->setListenOnly(false);
        sim.unit(2)->setListenOnly(false);
    }
}

void TestSimRobustness::randomStream_data()
{
    QTest::addColumn<QString>("url");
    QTest::newRow("rtu-tcp") << QStringLiteral("rtu-tcp://127.0.0.1:0");
    QTest::newRow("ascii-tcp") << QStringLiteral("ascii-tcp://127.0.0.1:0");
}

void TestSimRobustness::randomStream()
{
    QFETCH(QString, url);
    QRandomGenerator random(5);
    Simulator sim;
    QVERIFY(sim.adoptUnit(makeUnit(1)));
    SimEndpointOptions options;
    options.streamSilenceMs = 100;
    SimEndpoint *endpoint = sim.listen(url, options);
    QVERIFY(endpoint);
    StreamClient client(endpoint);
    QVERIFY(client.waitConnected());
    for (int i = 0; i < 64; ++i) {
        QByteArray chunk = randomBytes(random, 1 + int(random.bounded(1024)));
        if (endpoint->framing() == Framing::Ascii)
            chunk.replace(':', '#'); // no frame starts inside the noise
        client.send(chunk);
        QTest::qWait(0);
    }
    // Once the noise has ended in a silence, a request is answered (answers to requests that
    // the noise happened to hold are read past).
    QTest::qWait(300);
    const QByteArray request = AduBuilder::complete(pduOf(RequestBuilder::readHoldingRegisters(3, 1)),
                                                    AduOptions{endpoint->framing(), 1, 0, 0});
    const QByteArray expected = AduBuilder::complete(pduOf(ResponseBuilder::readHoldingRegisters({30})),
                                                     AduOptions{endpoint->framing(), 1, 0, 0});
    client.send(request);
    bool found = false;
    while (const auto answer = client.next()) {
        if (*answer == expected) {
            found = true;
            break;
        }
    }
    QVERIFY(found);
    QCOMPARE(client.socket().state(), QAbstractSocket::ConnectedState);
}

QTEST_GUILESS_MAIN(TestSimRobustness)
#include "tst_simrobustness.moc"
