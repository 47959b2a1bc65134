// Latency truth: are the engine's latencies the wire's? tshark captures the loopback while the
// engine polls a local server 200 times over tcp://, then, on a second connection to the same
// server in the same capture, while libmodbus's client reads the same registers 200 times (the
// reference: it times from before its send() to after its last recv()). Each transaction is found
// on the wire (the engine's request segment carries exactly its request bytes, its response
// segment exactly its response bytes; libmodbus's exchanges by their order on its connection) and
// each client's latency is compared with the wire's (capture time of the request segment to that
// of the response segment). The median and p99 of client minus wire are printed for both.
//
// Asserted: every transaction on the wire, in order, both latencies positive, and one statistical
// bound: the engine's median |difference| stays under 1 ms. A loopback exchange deviates by
// microseconds; a median off by a millisecond means the engine stamps something other than the
// send() of the request and the read of the answer (a batch flush, a timer, the poller).
// Never a speed: the machine may be loaded.
//
// Expect both clients to see slightly more than the wire: the engine reads its clock just before
// the send() that puts the request on the wire, and when its read handler runs, after the kernel
// has woken its thread for the answer (the capture stamps the answer before that wake-up).
#include "engineharness.h"
#include "peerprocess.h"
#include "tsharkcapture.h"

#include "engine/transactionengine.h"

#include <QtCore/QThread>
#include <QtTest/QTest>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <vector>

#ifdef MBSCOPE_HAVE_LIBMODBUS
#include <modbus.h>
#endif

using namespace mbscope;
using namespace mbscope::testpeers;

namespace {

constexpr int kTransactions = 200;

double percentileUs(std::vector<qint64> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const auto n = qsizetype(v.size());
    const qsizetype rank = std::clamp<qsizetype>(qsizetype(std::ceil(p / 100.0 * double(n))), 1, n);
    return double(v[size_t(rank - 1)]) / 1000.0;
}

// One client's exchanges on one connection: its own latencies and the wire's, in order.
struct Comparison {
    std::vector<qint64> clientNs;
    std::vector<qint64> wireNs;

    [[nodiscard]] std::vector<qint64> differenceNs(bool absolute) const
    {
        std::vector<qint64> d;
        for (size_t i = 0; i < clientNs.size(); ++i) {
            const qint64 x = clientNs[i] - wireNs[i];
            d.push_back(absolute && x < 0 ? -x : x);
        }
        return d;
    }
    void print(const char *client) const
    {
        const std::vector<qint64> d = differenceNs(false);
        const std::vector<qint64> a = differenceNs(true);
        qInfo("%-16s latency median %7.1f us p99 %7.1f us | wire median %7.1f us p99 %7.1f us | client minus wire "
              "median %6.1f us p99 %6.1f us (min %.1f, max %.1f; |difference| median %.1f)",
              client, percentileUs(clientNs, 50), percentileUs(clientNs, 99), percentileUs(wireNs, 50),
              percentileUs(wireNs, 99), percentileUs(d, 50), percentileUs(d, 99), percentileUs(d, 0), percentileUs(d, 100),
              percentileUs(a, 50));
    }
};

qint64 nowNs()
{
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return qint64(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

// libmodbus's client on its own connection: kTransactions reads of 10 holding registers, 2 ms
// apart, each timed from before modbus_read_registers() to its return. Empty when libmodbus was
// not built in; an error message when a read failed.
std::vector<qint64> pollLibmodbus(quint16 port, QString *error)
{
    std::vector<qint64> latencies;
#ifdef MBSCOPE_HAVE_LIBMODBUS
    modbus_t *ctx = modbus_new_tcp("127.0.0.1", port);
    if (!ctx || modbus_connect(ctx) != 0) {
        *error = QStringLiteral("libmodbus cannot connect to port %1").arg(port);
        if (ctx)
            modbus_free(ctx);
        return {};
    }
    modbus_set_slave(ctx, 1);
    modbus_set_response_timeout(ctx, 2, 0);
    uint16_t values[10];
    for (int i = 0; i < kTransactions; ++i) {
        QThread::usleep(2000);
        const qint64 t0 = nowNs();
        const int rc = modbus_read_registers(ctx, 0, 10, values);
        const qint64 t1 = nowNs();
        if (rc != 10) {
            *error = QStringLiteral("libmodbus read %1 failed: %2").arg(i).arg(QString::fromLocal8Bit(modbus_strerror(errno)));
            break;
        }
        latencies.push_back(t1 - t0);
    }
    modbus_close(ctx);
    modbus_free(ctx);
#else
    Q_UNUSED(port);
    Q_UNUSED(error);
#endif
    return latencies;
}

// The request and response segments of the connection from clientPort, in capture order.
void segmentsOf(const QList<WireSegment> &segments, quint16 serverPort, quint16 clientPort, QList<WireSegment> *requests,
                QList<WireSegment> *responses)
{
    for (const WireSegment &s : segments) {
        if (s.destinationPort == serverPort && s.sourcePort == clientPort)
            requests->append(s);
        else if (s.sourcePort == serverPort && s.destinationPort == clientPort)
            responses->append(s);
    }
}

} // namespace

class TestLatencyTruth : public QObject
{
    Q_OBJECT

private slots:
    void wireAgrees_data();
    void wireAgrees();
};

void TestLatencyTruth::wireAgrees_data()
{
    QTest::addColumn<QString>("peer");
    QTest::newRow("libmodbus server") << QStringLiteral("libmodbus");
    QTest::newRow("pymodbus server") << QStringLiteral("pymodbus");
}

void TestLatencyTruth::wireAgrees()
{
    QFETCH(QString, peer);
    QString why;
    PeerProcess server;
    if (peer == QLatin1String("libmodbus")) {
        if (!libmodbusPeersAvailable(&why))
            QSKIP(qPrintable(why));
        QVERIFY2(server.start(libmodbusServerPath(), {QStringLiteral("tcp")}), qPrintable(server.error()));
    } else {
        if (!pymodbusAvailable(&why))
            QSKIP(qPrintable(why));
        QVERIFY2(server.start(systemPython(), {peersDir() + QStringLiteral("/pymodbus_server.py"), QStringLiteral("tcp")}),
                 qPrintable(server.error()));
    }

    TsharkCapture capture;
    if (!capture.start(server.port()))
        QSKIP(qPrintable(capture.error()));

    const LinkUrl url = networkTarget(QStringLiteral("tcp"), server.port());
    TransactionEngine engine;
    engine.setTarget(url);
    EngineProbe probe(&engine);
    PollSettings settings;
    settings.items = {request(url, hex("03 0000 000A"), 1, 0x2A2A, 2000)};
    settings.count = kTransactions;
    settings.intervalNs = 2 * 1000000; // 2 ms apart: one exchange at a time on the wire
    engine.startPoll(settings);
    const std::optional<PollReport> report = engine.waitForFinished(120000);
    QVERIFY2(report, "the poll did not finish within 120 s");
    QVERIFY(probe.waitFor([&] { return probe.records().size() >= kTransactions; }, 5000));
    engine.closeLink();

    // The reference on a second connection, after the engine's: its segments come later.
    QString libmodbusError;
    const std::vector<qint64> libmodbusNs = pollLibmodbus(server.port(), &libmodbusError);
    QVERIFY2(libmodbusError.isEmpty(), qPrintable(libmodbusError));

    QList<WireSegment> segments;
    QVERIFY2(capture.stopAndRead(&segments), qPrintable(capture.error()));
    QList<quint16> clientPorts; // in order of their first request: the engine's, then libmodbus's
    for (const WireSegment &s : segments) {
        if (s.destinationPort == server.port() && !clientPorts.contains(s.sourcePort))
            clientPorts.append(s.sourcePort);
    }
    QVERIFY2(!clientPorts.isEmpty(), "no request on the wire");

    QList<WireSegment> requests;
    QList<WireSegment> responses;
    segmentsOf(segments, server.port(), clientPorts.first(), &requests, &responses);
    QList<Transaction> records = probe.records();
    std::sort(records.begin(), records.end(), [](const Transaction &a, const Transaction &b) { return a.id < b.id; });
    QCOMPARE(records.size(), qsizetype(kTransactions));
    QCOMPARE(requests.size(), qsizetype(kTransactions));
    QCOMPARE(responses.size(), qsizetype(kTransactions));

    Comparison engineSide;
    for (qsizetype i = 0; i < records.size(); ++i) {
        const Transaction &t = records.at(i);
        QVERIFY2(t.isOk(), qPrintable(describe(t)));
        QCOMPARE(requests.at(i).payload.toHex(' '), t.request.toHex(' '));
        QCOMPARE(responses.at(i).payload.toHex(' '), t.response.toHex(' '));
        const qint64 wire = responses.at(i).timeNs - requests.at(i).timeNs;
        QVERIFY2(wire > 0, qPrintable(QStringLiteral("transaction %1: the response was captured before the request").arg(i)));
        QVERIFY2(t.latencyNs() > 0, qPrintable(describe(t)));
        // The next request leaves after this response on the wire: the exchanges do not overlap.
        if (i + 1 < records.size())
            QVERIFY(requests.at(i + 1).timeNs >= responses.at(i).timeNs);
        engineSide.clientNs.push_back(t.latencyNs());
        engineSide.wireNs.push_back(wire);
    }

    Comparison libmodbusSide;
    if (!libmodbusNs.empty()) {
        QCOMPARE(clientPorts.size(), 2);
        QList<WireSegment> lmbRequests;
        QList<WireSegment> lmbResponses;
        segmentsOf(segments, server.port(), clientPorts.at(1), &lmbRequests, &lmbResponses);
        QCOMPARE(lmbRequests.size(), qsizetype(libmodbusNs.size()));
        QCOMPARE(lmbResponses.size(), qsizetype(libmodbusNs.size()));
        for (qsizetype i = 0; i < lmbRequests.size(); ++i) {
            const qint64 wire = lmbResponses.at(i).timeNs - lmbRequests.at(i).timeNs;
            QVERIFY(wire > 0);
            libmodbusSide.clientNs.push_back(libmodbusNs[size_t(i)]);
            libmodbusSide.wireNs.push_back(wire);
        }
    }

    qInfo("%s server, %d transactions per client:", qPrintable(peer), kTransactions);
    engineSide.print("mbscope engine");
    if (libmodbusNs.empty())
        qInfo("libmodbus client: not built in (libmodbus-dev missing)");
    else
        libmodbusSide.print("libmodbus client");

    const double medianErrorUs = percentileUs(engineSide.differenceNs(true), 50);
    QVERIFY2(medianErrorUs < 1000.0,
             qPrintable(QStringLiteral("the engine's latencies are off the wire's by a median of %1 us").arg(medianErrorUs)));
}

QTEST_GUILESS_MAIN(TestLatencyTruth)
#include "tst_latency_truth.moc"
