// The simulator on serial lines (rtu:// and ascii://) over a socat pty pair: the simulator owns
// one end, a plain QSerialPort client the other. Requests to units, silence for unknown units,
// broadcast, bad CRC/LRC counted, a request written byte by byte, listen-only mode end to end.

#include "protocol/adubuilder.h"
#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "simclient.h"
#include "simfixture.h"

#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtSerialPort/QSerialPort>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

namespace {

QByteArray readHolding(int start, int count)
{
    return pduOf(RequestBuilder::readHoldingRegisters(start, count));
}

QByteArray holdingAnswer(const QList<quint16> &values)
{
    return pduOf(ResponseBuilder::readHoldingRegisters(values));
}

class SerialClient
{
public:
    SerialClient(const QString &device, Framing framing)
        : m_port(device)
        , m_framing(framing)
        , m_framer(responseFramer(framing))
    {
        QObject::connect(&m_port, &QSerialPort::readyRead, [this] {
            m_framer->feed(m_port.readAll());
            for (const StreamFrame &f : m_framer->takeFrames())
                m_frames.append(f.bytes);
        });
    }
    bool open()
    {
        m_port.setBaudRate(19200);
        return m_port.open(QIODevice::ReadWrite);
    }
    QByteArray frame(const QByteArray &pdu, quint8 unit) const
    {
        return AduBuilder::complete(pdu, AduOptions{m_framing, unit, 0, 0});
    }
    void send(const QByteArray &bytes) { m_port.write(bytes); }
    std::optional<QByteArray> next(int waitMs = kWaitMs)
    {
        if (!QTest::qWaitFor([this] { return !m_frames.isEmpty(); }, waitMs))
            return std::nullopt;
        return m_frames.takeFirst();
    }
    std::optional<QByteArray> ask(const QByteArray &pdu, quint8 unit)
    {
        send(frame(pdu, unit));
        return next();
    }
    [[nodiscard]] int framesWaiting() const { return int(m_frames.size()); }

private:
    QSerialPort m_port;
    Framing m_framing;
    std::unique_ptr<StreamFramer> m_framer;
    QList<QByteArray> m_frames;
};

} // namespace

class TestSimulatorSerial : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QProcess m_socat;
    QString m_a;
    QString m_b;
    std::unique_ptr<Simulator> m_sim;

    SimEndpoint *listen(const QString &scheme, const QString &options = {})
    {
        QString error;
        SimEndpoint *endpoint = m_sim->listen(scheme + QStringLiteral("://") + m_a + options, {}, &error);
        if (!endpoint)
            qWarning().noquote() << error;
        return endpoint;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void init();
    void cleanup();
    void rtu();
    void rtuByteByByte();
    void rtuBroadcast();
    void rtuBadCrc();
    void ascii();
    void asciiBadLrc();
    void listenOnlyEndToEnd();
};

void TestSimulatorSerial::init()
{
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        QSKIP("socat is not installed: no pty pair to serve on");
    static int pair = 0;
    ++pair;
    m_a = m_dir.filePath(QStringLiteral("sim%1").arg(pair));
    m_b = m_dir.filePath(QStringLiteral("client%1").arg(pair));
    m_socat.start(socat, {QStringLiteral("pty,raw,echo=0,link=") + m_a, QStringLiteral("pty,raw,echo=0,link=") + m_b});
    QVERIFY2(m_socat.waitForStarted(kWaitMs), qPrintable(m_socat.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(m_a) && QFileInfo::exists(m_b), kWaitMs);
    m_sim = std::make_unique<Simulator>();
    QVERIFY(m_sim->adoptUnit(makeUnit(1)));
    SimUnit *three = m_sim->addUnit(3);
    SimRange r;
    r.count = 10;
    QVERIFY(three->addRange(r));
}

void TestSimulatorSerial::cleanup()
{
    m_sim.reset();
    if (m_socat.state() != QProcess::NotRunning) {
        m_socat.terminate();
        if (!m_socat.waitForFinished(kWaitMs)) {
            m_socat.kill();
            m_socat.waitForFinished(kWaitMs);
        }
    }
}

void TestSimulatorSerial::rtu()
{
    QVERIFY(listen(QStringLiteral("rtu"), QStringLiteral("?baud=19200")));
    SerialClient client(m_b, Framing::Rtu);
    QVERIFY(client.open());
    QCOMPARE(client.ask(readHolding(0, 3), 1), client.frame(holdingAnswer({0, 10, 20}), 1));
    QCOMPARE(client.ask(readHolding(0, 2), 3), client.frame(holdingAnswer({0, 0}), 3));
    // Unit 2 is not on this bus: silence (another device may own the id), then the next answer.
    client.send(client.frame(readHolding(0, 1), 2));
    QCOMPARE(client.ask(readHolding(1, 1), 1), client.frame(holdingAnswer({10}), 1));
    QCOMPARE(client.framesWaiting(), 0);
    QCOMPARE(client.ask(hex("03 00 00 00 7E"), 1), client.frame(pduOf(ResponseBuilder::exception(3, 3)), 1));
}

void TestSimulatorSerial::rtuByteByByte()
{
    // At 300 baud t3.5 is 128 ms (Serial Line V1.02, 2.5.1.1): the pauses between the bytes
    // written one by one stay far below it even on a loaded machine, so they never end the frame.
    QVERIFY(listen(QStringLiteral("rtu"), QStringLiteral("?baud=300")));
    SerialClient client(m_b, Framing::Rtu);
    QVERIFY(client.open());
    const QByteArray request = client.frame(pduOf(RequestBuilder::writeMultipleRegisters(2, {1, 2, 3})), 1);
    for (char c : request) {
        client.send(QByteArray(1, c));
        QTest::qWait(1);
    }
    QCOMPARE(client.next(), client.frame(pduOf(ResponseBuilder::writeMultipleRegisters(2, 3)), 1));
    QCOMPARE(m_sim->unit(1)->values(SimTable::HoldingRegisters, 2, 3), (QList<quint16>{1, 2, 3}));
}

void TestSimulatorSerial::rtuBroadcast()
{
    QVERIFY(listen(QStringLiteral("rtu"), QStringLiteral("?baud=19200")));
    SerialClient client(m_b, Framing::Rtu);
    QVERIFY(client.open());
    client.send(client.frame(pduOf(RequestBuilder::writeSingleRegister(4, 0x4444)), 0));
    QCOMPARE(client.ask(readHolding(4, 1), 3), client.frame(holdingAnswer({0x4444}), 3));
    QCOMPARE(m_sim->unit(1)->value(SimTable::HoldingRegisters, 4), std::optional<quint16>(0x4444));
    QCOMPARE(client.framesWaiting(), 0);
}

void TestSimulatorSerial::rtuBadCrc()
{
    QVERIFY(listen(QStringLiteral("rtu"), QStringLiteral("?baud=19200")));
    SerialClient client(m_b, Framing::Rtu);
    QVERIFY(client.open());
    QByteArray bad = client.frame(readHolding(0, 1), 1);
    bad[6] = char(bad[6] ^ 0xFF);
    client.send(bad);
    QTest::qWait(20); // more than t3.5: the bad frame ends before the next request
    QCOMPARE(client.ask(pduOf(RequestBuilder::diagnostics(0x0C)), 1),
             client.frame(pduOf(ResponseBuilder::diagnosticsValue(0x0C, 1)), 1));
    QCOMPARE(m_sim->unit(3)->counters().busCommErrors, quint16(1)); // every unit on the bus saw it
}

void TestSimulatorSerial::ascii()
{
    QVERIFY(listen(QStringLiteral("ascii"), QStringLiteral("?baud=9600&data=7")));
    SerialClient client(m_b, Framing::Ascii);
    QVERIFY(client.open());
    QCOMPARE(client.ask(readHolding(0, 2), 1), client.frame(holdingAnswer({0, 10}), 1));
    client.send(client.frame(pduOf(RequestBuilder::writeSingleRegister(1, 7)), 0)); // broadcast
    QCOMPARE(client.ask(readHolding(1, 1), 3), client.frame(holdingAnswer({7}), 3));
}

void TestSimulatorSerial::asciiBadLrc()
{
    QVERIFY(listen(QStringLiteral("ascii"), QStringLiteral("?baud=9600&data=7")));
    SerialClient client(m_b, Framing::Ascii);
    QVERIFY(client.open());
    QByteArray bad = client.frame(readHolding(0, 1), 1);
    bad[bad.size() - 3] = bad[bad.size() - 3] == '0' ? '1' : '0';
    client.send(bad + "junk");
    QCOMPARE(client.ask(pduOf(RequestBuilder::diagnostics(0x0C)), 1),
             client.frame(pduOf(ResponseBuilder::diagnosticsValue(0x0C, 1)), 1));
}

void TestSimulatorSerial::listenOnlyEndToEnd()
{
    QVERIFY(listen(QStringLiteral("rtu"), QStringLiteral("?baud=19200")));
    SerialClient client(m_b, Framing::Rtu);
    QVERIFY(client.open());
    client.send(client.frame(hex("08 00 04 00 00"), 1)); // V1.1b3 6.8.1: no answer, listen-only
    client.send(client.frame(readHolding(0, 1), 1));      // not processed
    client.send(client.frame(hex("08 00 01 00 00"), 1)); // restart: no answer from listen-only
    QCOMPARE(client.ask(readHolding(0, 1), 1), client.frame(holdingAnswer({0}), 1));
    QCOMPARE(client.framesWaiting(), 0);
    QVERIFY(!m_sim->unit(1)->isListenOnly());
    QCOMPARE(m_sim->unit(3)->counters().busMessages, quint16(4)); // unit 3 saw every frame
}

QTEST_GUILESS_MAIN(TestSimulatorSerial)
#include "tst_simulator_serial.moc"
