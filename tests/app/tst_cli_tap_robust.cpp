// `mbscope tap` under abuse (issue 27, "How fast, how solid"): a master that leaves while its
// request is at the device, a target that drops the connection, garbage from a master (handled as
// the simulator handles it, and counted), a request arriving a byte at a time, 64 masters at once,
// and a short soak that loses nothing and whose memory stays flat. The masters are raw sockets
// (bytes exactly as written) and libmodbus_many_clients (N libmodbus masters as threads, every
// answer checked); the devices are `mbscope simulate --profile conformance` (unit 1, holding
// register a = 1000 + 3a), with fault rules where a device must misbehave.
#include "clitest.h"
#include "pacedline.h"
#include "procstat.h"

#include "protocol/adubuilder.h"
#include "protocol/rtuframer.h"
#include "transport/linkurl.h"
#include "transport/seriallink.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QtTest>

#include <sys/socket.h>

using namespace mbscope;
using namespace mbscope::testcli;

namespace {

QStringList simulateArgs(const QString &listen, const QStringList &more = {})
{
    return QStringList{QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                       listen, QStringLiteral("--quiet")}
           + more;
}

QStringList tapArgs(const QString &listen, const QString &target, const QStringList &more = {})
{
    return QStringList{QStringLiteral("tap"), QStringLiteral("--listen"), listen, QStringLiteral("--target"), target} + more;
}

quint16 portOf(const QString &url)
{
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    return parsed.url ? parsed.url->port : 0;
}

// Of a URL with its port (port 0 is not a target's).
Framing framingOf(const QString &url)
{
    const LinkUrl::Result parsed = LinkUrl::parse(url);
    return parsed.url ? parsed.url->framing() : Framing::Tcp;
}

// Read Holding Registers of unit 1, framed for url's framing (MBAP transaction id tid).
QByteArray readRequest(const QString &url, int address, int quantity, quint16 tid = 1)
{
    QByteArray pdu("\x03", 1);
    pdu.append(char(address >> 8)).append(char(address & 0xFF)).append(char(quantity >> 8)).append(char(quantity & 0xFF));
    switch (framingOf(url)) {
    case Framing::Rtu: return AduBuilder::rtu(pdu, 1);
    case Framing::Ascii: return AduBuilder::ascii(pdu, 1);
    default: return AduBuilder::mbap(pdu, 1, tid);
    }
}

// The PDU a device with the peers' data map answers to readRequest (03, byte count, values).
QByteArray readAnswerPdu(int address, int quantity)
{
    QByteArray pdu;
    pdu.append('\x03').append(char(2 * quantity));
    for (int i = 0; i < quantity; ++i) {
        const quint16 value = holdingRegister(address + i);
        pdu.append(char(value >> 8)).append(char(value & 0xFF));
    }
    return pdu;
}

// A master on a plain socket: bytes exactly as the test writes them.
struct RawMaster {
    QTcpSocket socket;

    bool connect(const QString &url)
    {
        socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
        socket.connectToHost(QStringLiteral("127.0.0.1"), portOf(url));
        return socket.waitForConnected(5000);
    }
    void write(const QByteArray &bytes)
    {
        socket.write(bytes);
        socket.waitForBytesWritten(5000);
    }
    // What arrives within timeoutMs, or up to `expected` bytes.
    QByteArray read(qsizetype expected, int timeoutMs)
    {
        QByteArray got;
        QElapsedTimer timer;
        timer.start();
        while (got.size() < expected && timer.elapsed() < timeoutMs) {
            if (socket.bytesAvailable() == 0 && !socket.waitForReadyRead(int(std::max<qint64>(1, timeoutMs - timer.elapsed()))))
                break;
            got += socket.readAll();
        }
        return got;
    }
    // Whether the other side closed within timeoutMs.
    bool closedBy(int timeoutMs)
    {
        if (socket.state() == QAbstractSocket::UnconnectedState)
            return true;
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < timeoutMs) {
            socket.readAll();
            if (socket.state() == QAbstractSocket::UnconnectedState || socket.waitForDisconnected(50))
                return true;
        }
        return socket.state() == QAbstractSocket::UnconnectedState;
    }
    // An abortive close: the peer gets a reset (SO_LINGER 0), not a FIN.
    void reset()
    {
        const linger hard{1, 0};
        ::setsockopt(int(socket.socketDescriptor()), SOL_SOCKET, SO_LINGER, &hard, sizeof hard);
        socket.abort();
    }
};

// The answer PDU of one request through url, from a fresh master.
QByteArray answerPdu(const QString &url, int address, int quantity, int timeoutMs = 5000)
{
    RawMaster master;
    if (!master.connect(url))
        return {};
    master.write(readRequest(url, address, quantity));
    const Framing framing = framingOf(url);
    const qsizetype expected = framing == Framing::Ascii ? 1 + 2 * (2 + 2 + 2 * quantity + 1) + 2
                               : framing == Framing::Rtu ? 1 + 2 + 2 * quantity + 2
                                                         : 7 + 2 + 2 * quantity;
    return AduBuilder::parse(master.read(expected, timeoutMs), framing).pdu;
}

// The figures of the tap's end line ("tap: 3 requests, 3 forwarded: 2 answered, ...") and of the
// simulator's line before it ("... 1 malformed; ...").
struct TapCounts {
    bool found = false;
    qint64 requests = -1, forwarded = -1, answered = -1, exceptions = -1, noAnswer = -1, linkErrors = -1, malformed = -1;
    qint64 resent = 0; // said only when some were
};

TapCounts tapCounts(const QString &out)
{
    TapCounts c;
    static const QRegularExpression line(QStringLiteral("tap: (\\d+) requests?, (\\d+) forwarded: (\\d+) answered, (\\d+) exceptions? from "
                                                        "devices, (\\d+) without answer, (\\d+) link errors?"));
    static const QRegularExpression malformed(QStringLiteral("(\\d+) malformed;"));
    static const QRegularExpression resent(QStringLiteral("(\\d+) reads? sent again after a link closed"));
    const QRegularExpressionMatch m = line.match(out);
    if (!m.hasMatch())
        return c;
    c.found = true;
    c.requests = m.captured(1).toLongLong();
    c.forwarded = m.captured(2).toLongLong();
    c.answered = m.captured(3).toLongLong();
    c.exceptions = m.captured(4).toLongLong();
    c.noAnswer = m.captured(5).toLongLong();
    c.linkErrors = m.captured(6).toLongLong();
    const QRegularExpressionMatch bad = malformed.match(out);
    c.malformed = bad.hasMatch() ? bad.captured(1).toLongLong() : -1;
    if (const QRegularExpressionMatch again = resent.match(out); again.hasMatch())
        c.resent = again.captured(1).toLongLong();
    return c;
}

// Stops a tap with Ctrl-C; whether it was still running (no crash) and its output.
bool stopsCleanly(Background &tap, QString *out)
{
    const bool running = tap.isRunning();
    QByteArray err;
    *out = QString::fromUtf8(tap.stop(&err)) + QString::fromUtf8(err);
    return running && out->contains(QLatin1String("interrupted: "));
}

// A pty pair at baud (each character paced at its line time, or bare) with the simulated slave
// on its device end; false with *error.
bool startSerialDevice(testpeers::PacedLine &pair, Background &device, int baud, bool paced, QString *error)
{
    const LinkUrl::Result line = LinkUrl::parse(QStringLiteral("rtu:///dev/null?baud=%1").arg(baud));
    if (!line.url) {
        *error = line.error;
        return false;
    }
    return pair.start(paced ? SerialLink::lineCharacterNs(line.url->serial) : 0, error)
           && device.start(simulateArgs(QStringLiteral("rtu://") + pair.deviceEnd() + QStringLiteral("?baud=%1").arg(baud)), error);
}

// Every silence the relay measured before a request (expected of them) lasted t3.5 at least.
bool keptTheLineGap(const testpeers::PacedLine::Timing &timing, int baud, size_t expected)
{
    if (timing.masterGapsNs.size() != expected) {
        qWarning("%zu silences before a request measured, %zu expected", timing.masterGapsNs.size(), expected);
        return false;
    }
    const qint64 t35 = RtuFramer::t35Ns(baud);
    const qint64 shortest = *std::min_element(timing.masterGapsNs.begin(), timing.masterGapsNs.end());
    if (shortest < t35) {
        qWarning("%.1f us of silence before a request; t3.5 at %d baud is %.1f us", double(shortest) / 1000, baud, double(t35) / 1000);
        return false;
    }
    return true;
}

} // namespace

class TestCliTapRobust : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void masterLeavesMidRequest_data();
    void masterLeavesMidRequest();
    void targetDropsConnection_data();
    void targetDropsConnection();
    void garbageFromMaster_data();
    void garbageFromMaster();
    void requestByteByByte_data();
    void requestByteByByte();
    void manyMastersAtOnce_data();
    void manyMastersAtOnce();
    void soak_data();
    void soak();
    void serialLineGap_data();
    void serialLineGap();
    void pollKeepsTheLineGap_data();
    void pollKeepsTheLineGap();

private:
    bool writeFaults(const QString &name, const QByteArray &json, QString *path);
    QTemporaryDir m_dir;
};

void TestCliTapRobust::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

bool TestCliTapRobust::writeFaults(const QString &name, const QByteArray &json, QString *path)
{
    *path = m_dir.filePath(name);
    QFile file(*path);
    return file.open(QIODevice::WriteOnly) && file.write(json) == json.size();
}

void TestCliTapRobust::masterLeavesMidRequest_data()
{
    QTest::addColumn<int>("requests"); // written back to back before leaving
    QTest::addColumn<bool>("half");    // only the first half of the request's bytes
    QTest::addColumn<bool>("reset");   // RST instead of FIN
    QTest::newRow("FIN while the device works") << 1 << false << false;
    QTest::newRow("RST while the device works") << 1 << false << true;
    QTest::newRow("FIN after three pipelined requests") << 3 << false << false;
    QTest::newRow("RST after three pipelined requests") << 3 << false << true;
    QTest::newRow("FIN halfway through a request") << 1 << true << false;
    QTest::newRow("RST halfway through a request") << 1 << true << true;
}

void TestCliTapRobust::masterLeavesMidRequest()
{
    QFETCH(int, requests);
    QFETCH(bool, half);
    QFETCH(bool, reset);
    // The device takes 400 ms over reads starting at 50: the leaving master's answer comes back
    // after it left; the other master reads elsewhere.
    QString faults;
    QVERIFY(writeFaults(QStringLiteral("slow50.json"), R"({"rules": [{"kind": "delay", "start": 50, "delay": 400}]})", &faults));
    Background device;
    QString error;
    QVERIFY2(device.start(simulateArgs(QStringLiteral("tcp://127.0.0.1:0"), {QStringLiteral("--faults"), faults}), &error), qPrintable(error));
    Background tap;
    QVERIFY2(tap.start(tapArgs(QStringLiteral("tcp://127.0.0.1:0"), device.url(), {QStringLiteral("--quiet")}), &error), qPrintable(error));

    RawMaster staying;
    QVERIFY(staying.connect(tap.url()));
    {
        RawMaster leaving;
        QVERIFY(leaving.connect(tap.url()));
        QByteArray bytes;
        for (int i = 0; i < requests; ++i)
            bytes += readRequest(tap.url(), 50, 4, quint16(100 + i));
        leaving.write(half ? bytes.left(bytes.size() / 2) : bytes);
        QTest::qWait(100); // the tap has read it (and forwarded what was whole)
        if (reset)
            leaving.reset();
        else
            leaving.socket.disconnectFromHost();
    }
    // The other master, meanwhile and after the device answered the one that left.
    const int stayingRequests = 6;
    for (int i = 0; i < stayingRequests; ++i) {
        staying.write(readRequest(tap.url(), 10 + i, 3, quint16(i + 1)));
        const QByteArray answer = staying.read(7 + 2 + 6, 5000);
        QCOMPARE(AduBuilder::parse(answer, Framing::Tcp).pdu, readAnswerPdu(10 + i, 3));
        QCOMPARE(quint16(quint8(answer.at(0)) << 8 | quint8(answer.at(1))), quint16(i + 1));
        if (i == 2)
            QTest::qWait(500); // the late answer has come back by now
    }
    QString out;
    QVERIFY2(stopsCleanly(tap, &out), qPrintable(out));
    const TapCounts c = tapCounts(out);
    const int forwarded = half ? 0 : requests;
    QVERIFY2(c.found, qPrintable(out));
    QCOMPARE(c.requests, qint64(stayingRequests + forwarded));
    QCOMPARE(c.forwarded, qint64(stayingRequests + forwarded));
    // The device answered the leaving master's requests too; the tap had nobody to give them to.
    QCOMPARE(c.answered, qint64(stayingRequests + forwarded));
    QCOMPARE(c.linkErrors, 0);
}

void TestCliTapRobust::targetDropsConnection_data()
{
    QTest::addColumn<QString>("rule");   // the device's fault rule for reads starting at 60 ("" : none)
    QTest::addColumn<bool>("restart");   // the device stops and starts again on its port instead
    QTest::addColumn<QString>("first");  // the PDU the master gets for its read at 60
    QTest::addColumn<int>("linkErrors");
    QTest::addColumn<bool>("once");   // the rule fires only after a pause (the read sent again finds the device answering)
    QTest::addColumn<int>("resent");  // reads the tap sent again on a new connection
    // Closed every time: the read sent again meets the same close, and the master gets 0B.
    QTest::newRow("closed before the answer") << QStringLiteral("before") << false << QStringLiteral("83 0B") << 1 << false << 1;
    QTest::newRow("closed halfway through the answer") << QStringLiteral("midway") << false << QStringLiteral("83 0B") << 1 << false << 1;
    QTest::newRow("closed after the answer") << QStringLiteral("after") << false << QString() << 0 << false << 0;
    // Closed as the request arrived, once (a device that closes idle connections): the read goes
    // again on a new connection and the master gets its answer.
    QTest::newRow("closed once before the answer") << QStringLiteral("before") << false << QString() << 0 << true << 1;
    QTest::newRow("closed once halfway through the answer") << QStringLiteral("midway") << false << QString() << 0 << true << 1;
    QTest::newRow("device gone, then back on its port") << QString() << true << QStringLiteral("83 0B") << 1 << false << -1;
}

void TestCliTapRobust::targetDropsConnection()
{
    QFETCH(QString, rule);
    QFETCH(bool, restart);
    QFETCH(QString, first);
    QFETCH(int, linkErrors);
    QFETCH(bool, once);
    QFETCH(int, resent);
    QStringList more;
    if (!rule.isEmpty()) {
        QString faults;
        // once: fires only on a request that comes more than 100 ms after the one before it.
        const QString probability = once ? QStringLiteral(R"(, "probability": {"byIntervalMs": [[100, 0], [101, 1]]})") : QString();
        QVERIFY(writeFaults(QStringLiteral("close-%1-%2.json").arg(rule).arg(once),
                            QStringLiteral(R"({"rules": [{"kind": "close", "when": "%1", "start": 60%2}]})").arg(rule, probability).toUtf8(),
                            &faults));
        more = QStringList{QStringLiteral("--faults"), faults};
    }
    const QString listen = QStringLiteral("tcp://127.0.0.1:%1").arg(closedPort());
    auto device = std::make_unique<Background>();
    QString error;
    QVERIFY2(device->start(simulateArgs(listen, more), &error), qPrintable(error));
    Background tap;
    QVERIFY2(tap.start(tapArgs(QStringLiteral("tcp://127.0.0.1:0"), device->url(), {QStringLiteral("--quiet"), QStringLiteral("--timeout"),
                                                                                    QStringLiteral("2s")}),
                       &error),
             qPrintable(error));
    RawMaster master;
    QVERIFY(master.connect(tap.url()));
    // The connection to the device is up and answering.
    master.write(readRequest(tap.url(), 0, 2, 1));
    QCOMPARE(AduBuilder::parse(master.read(13, 5000), Framing::Tcp).pdu, readAnswerPdu(0, 2));
    if (restart)
        device->stop();
    QTest::qWait(300);
    master.write(readRequest(tap.url(), 60, 2, 2));
    const QByteArray got = AduBuilder::parse(master.read(first.isEmpty() ? 13 : 9, 5000), Framing::Tcp).pdu;
    QCOMPARE(QString::fromLatin1(got.toHex(' ')).toUpper(), first.isEmpty() ? QString::fromLatin1(readAnswerPdu(60, 2).toHex(' ')).toUpper() : first);
    if (restart) {
        device = std::make_unique<Background>();
        QVERIFY2(device->start(simulateArgs(listen, more), &error), qPrintable(error));
    }
    // The next request once the tap has seen the connection end (a request written in the same
    // instant as the device's FIN meets the closed connection: 0B), on the same master connection.
    QTest::qWait(300);
    master.write(readRequest(tap.url(), 70, 2, 3));
    QCOMPARE(AduBuilder::parse(master.read(13, 5000), Framing::Tcp).pdu, readAnswerPdu(70, 2));
    QCOMPARE(master.socket.state(), QAbstractSocket::ConnectedState);
    QString out;
    QVERIFY2(stopsCleanly(tap, &out), qPrintable(out));
    const TapCounts c = tapCounts(out);
    QVERIFY2(c.found, qPrintable(out));
    QCOMPARE(c.requests, 3);
    QCOMPARE(c.linkErrors, qint64(linkErrors));
    QCOMPARE(c.answered, qint64(3 - linkErrors));
    if (resent >= 0)
        QCOMPARE(c.resent, qint64(resent));
    if (linkErrors > 0) // said as it happened
        QVERIFY2(out.contains(QStringLiteral("target %1: ").arg(device->url())), qPrintable(out));
}

void TestCliTapRobust::garbageFromMaster_data()
{
    QTest::addColumn<QString>("listen");
    QTest::addColumn<QByteArray>("garbage");
    QTest::addColumn<bool>("closes");   // the connection is closed for it (MBAP: the stream cannot be trusted)
    QTest::newRow("tcp: protocol id 1") << QStringLiteral("tcp://127.0.0.1:0") << QByteArray::fromHex("000100010006010300000001") << true;
    QTest::newRow("tcp: length 300") << QStringLiteral("tcp://127.0.0.1:0") << QByteArray::fromHex("0001000001" "2C01030000000100") << true;
    QTest::newRow("tcp: text") << QStringLiteral("tcp://127.0.0.1:0") << QByteArray("GET / HTTP/1.0\r\n\r\n") << true;
    QTest::newRow("rtu-tcp: noise") << QStringLiteral("rtu-tcp://127.0.0.1:0") << QByteArray::fromHex("DEADBEEF00FF") << false;
    QTest::newRow("rtu-tcp: bad CRC") << QStringLiteral("rtu-tcp://127.0.0.1:0") << QByteArray::fromHex("010300000001FFFF") << false;
    QTest::newRow("ascii-tcp: not hex") << QStringLiteral("ascii-tcp://127.0.0.1:0") << QByteArray(":01ZZ0000\r\n") << false;
    QTest::newRow("ascii-tcp: bad LRC") << QStringLiteral("ascii-tcp://127.0.0.1:0") << QByteArray(":010300000001FF\r\n") << false;
}

void TestCliTapRobust::garbageFromMaster()
{
    QFETCH(QString, listen);
    QFETCH(QByteArray, garbage);
    QFETCH(bool, closes);
    Background device; // behind the tap
    Background alone;  // the same framing as the tap's listening side: how the simulator takes it
    QString error;
    QVERIFY2(device.start(simulateArgs(QStringLiteral("tcp://127.0.0.1:0")), &error), qPrintable(error));
    QVERIFY2(alone.start(simulateArgs(listen), &error), qPrintable(error));
    Background tap;
    QVERIFY2(tap.start(tapArgs(listen, device.url(), {QStringLiteral("--quiet")}), &error), qPrintable(error));
    for (Background *server : {&alone, &tap}) {
        RawMaster master;
        QVERIFY(master.connect(server->url()));
        master.write(garbage);
        QCOMPARE(master.closedBy(closes ? 5000 : 300), closes);
        if (closes)
            continue;
        // The garbage is skipped (the framer's silence ends it); a good request after it is answered.
        QTest::qWait(1200);
        master.write(readRequest(server->url(), 5, 2));
        const Framing framing = framingOf(server->url());
        const QByteArray answer = master.read(framing == Framing::Ascii ? 1 + 2 * 8 + 2 : framing == Framing::Rtu ? 9 : 13, 5000);
        QCOMPARE(AduBuilder::parse(answer, framing).pdu, readAnswerPdu(5, 2));
    }
    // A master after it, on a connection of its own, is served.
    QCOMPARE(answerPdu(tap.url(), 7, 1), readAnswerPdu(7, 1));
    QString out;
    QVERIFY2(stopsCleanly(tap, &out), qPrintable(out));
    const QString direct = QString::fromUtf8(alone.stop());
    const TapCounts c = tapCounts(out);
    QVERIFY2(c.found, qPrintable(out));
    // Counted as the simulator counts it, and never forwarded.
    QVERIFY2(c.malformed >= 1, qPrintable(out));
    QVERIFY2(direct.contains(QStringLiteral("%1 malformed;").arg(c.malformed)), qPrintable(direct + out));
    const qint64 good = closes ? 1 : 2;
    QCOMPARE(c.forwarded, good);
    QCOMPARE(c.answered, good);
}

void TestCliTapRobust::requestByteByByte_data()
{
    QTest::addColumn<QString>("listen");
    QTest::addColumn<QString>("target");
    QTest::newRow("tcp master, tcp device") << QStringLiteral("tcp://127.0.0.1:0") << QStringLiteral("tcp");
    QTest::newRow("rtu-tcp master, tcp device") << QStringLiteral("rtu-tcp://127.0.0.1:0") << QStringLiteral("tcp");
    QTest::newRow("ascii-tcp master, tcp device") << QStringLiteral("ascii-tcp://127.0.0.1:0") << QStringLiteral("tcp");
    QTest::newRow("tcp master, rtu-tcp device") << QStringLiteral("tcp://127.0.0.1:0") << QStringLiteral("rtu-tcp");
}

void TestCliTapRobust::requestByteByByte()
{
    QFETCH(QString, listen);
    QFETCH(QString, target);
    Background device;
    QString error;
    QVERIFY2(device.start(simulateArgs(target + QStringLiteral("://127.0.0.1:0")), &error), qPrintable(error));
    Background tap;
    QVERIFY2(tap.start(tapArgs(listen, device.url(), {QStringLiteral("--quiet")}), &error), qPrintable(error));
    RawMaster master;
    QVERIFY(master.connect(tap.url()));
    const QByteArray request = readRequest(tap.url(), 20, 5, 0x1234);
    for (const char byte : request) {
        master.write(QByteArray(1, byte));
        QTest::qWait(10); // each byte its own segment
    }
    const Framing framing = framingOf(tap.url());
    const QByteArray answer = master.read(framing == Framing::Ascii ? 1 + 2 * 14 + 2 : framing == Framing::Rtu ? 15 : 19, 5000);
    const AduParts parts = AduBuilder::parse(answer, framing);
    QCOMPARE(parts.pdu, readAnswerPdu(20, 5));
    if (framing == Framing::Tcp)
        QCOMPARE(parts.transactionId, quint16(0x1234));
    QString out;
    QVERIFY2(stopsCleanly(tap, &out), qPrintable(out));
    const TapCounts c = tapCounts(out);
    // One request, forwarded whole: nothing malformed on either side.
    QVERIFY2(c.requests == 1 && c.forwarded == 1 && c.answered == 1 && c.malformed == 0, qPrintable(out));
    const QString deviceOut = QString::fromUtf8(device.stop());
    QVERIFY2(deviceOut.contains(QLatin1String("1 requests in")) && deviceOut.contains(QLatin1String("0 malformed")), qPrintable(deviceOut));
}

void TestCliTapRobust::manyMastersAtOnce_data()
{
    QTest::addColumn<QString>("target");
    QTest::addColumn<QStringList>("options");
    QTest::newRow("64 masters, tcp device") << QStringLiteral("tcp") << QStringList{};
    QTest::newRow("64 masters, tcp device, --pipeline 8") << QStringLiteral("tcp") << QStringList{QStringLiteral("--pipeline"), QStringLiteral("8")};
    QTest::newRow("64 masters, rtu-tcp device") << QStringLiteral("rtu-tcp") << QStringList{};
}

void TestCliTapRobust::manyMastersAtOnce()
{
    QFETCH(QString, target);
    QFETCH(QStringList, options);
    QString why;
    if (!testpeers::libmodbusPeersAvailable(&why))
        QSKIP(qPrintable(why));
    Background device;
    QString error;
    QVERIFY2(device.start(simulateArgs(target + QStringLiteral("://127.0.0.1:0")), &error), qPrintable(error));
    Background tap;
    QVERIFY2(tap.start(tapArgs(QStringLiteral("tcp://127.0.0.1:0"), device.url(), QStringList{QStringLiteral("--quiet")} + options), &error),
             qPrintable(error));
    const int masters = 64;
    const int requests = 25;
    QProcess clients;
    clients.start(testpeers::libmodbusManyClientsPath(),
                  {QStringLiteral("127.0.0.1"), QString::number(portOf(tap.url())), QStringLiteral("--clients"), QString::number(masters),
                   QStringLiteral("--requests"), QString::number(requests), QStringLiteral("--check")});
    QVERIFY(clients.waitForFinished(120000));
    const QString said = QString::fromUtf8(clients.readAllStandardOutput() + clients.readAllStandardError());
    // Every master connected, every answer was there and right.
    QVERIFY2(clients.exitCode() == 0 && said.contains(QStringLiteral("transactions %1 errors 0").arg(masters * requests)), qPrintable(said));
    QString out;
    QVERIFY2(stopsCleanly(tap, &out), qPrintable(out));
    const TapCounts c = tapCounts(out);
    QVERIFY2(c.requests == masters * requests && c.forwarded == c.requests && c.answered == c.requests, qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("%1 connections").arg(masters)), qPrintable(out));
}

void TestCliTapRobust::soak_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::newRow("16 masters, 20 s") << QStringList{};
    QTest::newRow("16 masters, 20 s, --pipeline 16") << QStringList{QStringLiteral("--pipeline"), QStringLiteral("16")};
}

void TestCliTapRobust::soak()
{
    QFETCH(QStringList, options);
    QString why;
    if (!testpeers::libmodbusPeersAvailable(&why))
        QSKIP(qPrintable(why));
    Background device;
    QString error;
    QVERIFY2(device.start(simulateArgs(QStringLiteral("tcp://127.0.0.1:0")), &error), qPrintable(error));
    Background tap;
    QVERIFY2(tap.start(tapArgs(QStringLiteral("tcp://127.0.0.1:0"), device.url(), QStringList{QStringLiteral("--quiet")} + options), &error),
             qPrintable(error));
    const int seconds = 20;
    const int warmupSeconds = 5;
    QProcess clients;
    clients.start(testpeers::libmodbusManyClientsPath(),
                  {QStringLiteral("127.0.0.1"), QString::number(portOf(tap.url())), QStringLiteral("--clients"), QStringLiteral("16"),
                   QStringLiteral("--seconds"), QString::number(seconds), QStringLiteral("--check")});
    QVERIFY(clients.waitForStarted(10000));
    // The tap's resident memory twice a second: its largest after the warm-up, against what it
    // was when the warm-up ended.
    QElapsedTimer clock;
    clock.start();
    qint64 atWarmup = -1;
    qint64 peakAfter = 0;
    qint64 first = -1;
    while (!clients.waitForFinished(500)) {
        const qint64 rss = processRssKiB(tap.pid());
        QVERIFY2(rss > 0, "the tap is gone");
        if (first < 0)
            first = rss;
        if (clock.elapsed() >= warmupSeconds * 1000) {
            if (atWarmup < 0)
                atWarmup = rss;
            peakAfter = std::max(peakAfter, rss);
        }
        QVERIFY(clock.elapsed() < (seconds + 60) * 1000);
    }
    const QString said = QString::fromUtf8(clients.readAllStandardOutput() + clients.readAllStandardError());
    static const QRegularExpression figures(QStringLiteral("transactions (\\d+) errors (\\d+)"));
    const QRegularExpressionMatch m = figures.match(said);
    QVERIFY2(clients.exitCode() == 0 && m.hasMatch() && m.captured(2) == QLatin1String("0"), qPrintable(said));
    const qint64 transactions = m.captured(1).toLongLong();
    const double tapCpu = processCpuSeconds(tap.pid());
    QString out;
    QVERIFY2(stopsCleanly(tap, &out), qPrintable(out));
    const TapCounts c = tapCounts(out);
    // Nothing lost: every request the masters sent was forwarded and answered.
    QVERIFY2(c.requests == transactions && c.forwarded == transactions && c.answered == transactions, qPrintable(said + out));
    QVERIFY2(c.noAnswer == 0 && c.linkErrors == 0 && c.malformed == 0, qPrintable(out));
    qInfo("soak: %lld transactions in %d s (%.0f/s), tap CPU %.1f s (%.1f us a transaction); tap RSS %lld KiB at the start, %lld KiB "
          "after %d s of warm-up, at most %lld KiB after (+%lld KiB)",
          transactions, seconds, double(transactions) / seconds, tapCpu, transactions > 0 ? tapCpu * 1e6 / double(transactions) : 0.0,
          first, atWarmup, warmupSeconds, peakAfter, peakAfter - atWarmup);
    // Flat: no memory kept per request (a leak of even 16 bytes a request is hundreds of KiB here).
    QVERIFY2(atWarmup > 0 && peakAfter - atWarmup <= 1024,
             qPrintable(QStringLiteral("RSS %1 KiB after the warm-up, %2 KiB at most after it").arg(atWarmup).arg(peakAfter)));
}

void TestCliTapRobust::serialLineGap_data()
{
    QTest::addColumn<int>("baud");
    QTest::addColumn<bool>("paced"); // each character takes its time on the line (PacedLine), or none (a bare pty pair)
    QTest::newRow("9600 baud, paced line") << 9600 << true;
    QTest::newRow("19200 baud, paced line") << 19200 << true;
    QTest::newRow("115200 baud, paced line") << 115200 << true;
    QTest::newRow("115200 baud, bare pty pair") << 115200 << false;
}

void TestCliTapRobust::serialLineGap()
{
    // Several masters at once keep the tap's queue for the line full: the next request is always
    // waiting when an answer ends. Each must still wait t3.5 of silence (Serial Line V1.02,
    // 2.5.1.1), or a device that frames by silence takes the two for one frame.
    QFETCH(int, baud);
    QFETCH(bool, paced);
    QString why;
    if (!testpeers::libmodbusPeersAvailable(&why))
        QSKIP(qPrintable(why));
    testpeers::PacedLine pair;
    Background device;
    QString error;
    QVERIFY2(startSerialDevice(pair, device, baud, paced, &error), qPrintable(error));
    const QString options = QStringLiteral("?baud=%1").arg(baud);
    Background tap;
    QVERIFY2(tap.start(tapArgs(QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("rtu://") + pair.masterEnd() + options,
                               {QStringLiteral("--quiet")}),
                       &error),
             qPrintable(error));
    QProcess clients;
    clients.start(testpeers::libmodbusManyClientsPath(), {QStringLiteral("127.0.0.1"), QString::number(portOf(tap.url())),
                                                          QStringLiteral("--clients"), QStringLiteral("3"), QStringLiteral("--requests"),
                                                          QStringLiteral("12"), QStringLiteral("--check")});
    QVERIFY(clients.waitForFinished(120000));
    const QString said = QString::fromUtf8(clients.readAllStandardOutput() + clients.readAllStandardError());
    QVERIFY2(clients.exitCode() == 0 && said.contains(QLatin1String("transactions 36 errors 0")), qPrintable(said));
    const testpeers::PacedLine::Timing timing = pair.take();
    QString out;
    QVERIFY2(stopsCleanly(tap, &out), qPrintable(out));
    // Every request but the first followed an answer; the relay measures each silence as no
    // shorter than the tap kept it.
    QVERIFY(keptTheLineGap(timing, baud, 35));
}

void TestCliTapRobust::pollKeepsTheLineGap_data()
{
    serialLineGap_data();
}

void TestCliTapRobust::pollKeepsTheLineGap()
{
    // The gap is the engine's (EngineCore::lineQuiet), not the tap's: `mbscope poll` back to back
    // on an RTU serial line keeps t3.5 of silence after each answer too. (Before, the next request
    // left as soon as the answer was read: 76-131 us of silence.)
    QFETCH(int, baud);
    QFETCH(bool, paced);
    testpeers::PacedLine pair;
    Background device;
    QString error;
    QVERIFY2(startSerialDevice(pair, device, baud, paced, &error), qPrintable(error));
    const QString options = QStringLiteral("?baud=%1").arg(baud);
    const CliResult poll = runMbscope({QStringLiteral("poll"), QStringLiteral("--target"), QStringLiteral("rtu://") + pair.masterEnd() + options,
                                       QStringLiteral("--unit"), QStringLiteral("1"), QStringLiteral("--address"), QStringLiteral("0"),
                                       QStringLiteral("--quantity"), QStringLiteral("4"), QStringLiteral("--count"), QStringLiteral("20"),
                                       QStringLiteral("--interval"), QStringLiteral("0")});
    QVERIFY2(poll.exitCode == 0, qPrintable(poll.outText() + poll.errText()));
    const testpeers::PacedLine::Timing timing = pair.take();
    QVERIFY(keptTheLineGap(timing, baud, 19));
}

QTEST_GUILESS_MAIN(TestCliTapRobust)
#include "tst_cli_tap_robust.moc"
