// Latency truth: are the engine's latencies the wire's? tshark captures the loopback while the
// engine polls a local server 200 times over tcp://; each transaction is then found on the wire
// (its request segment carries exactly its request bytes, its response segment exactly its
// response bytes) and its engine latency (doneNs - sentNs: last request byte written to last
// answer byte read) is compared with the wire's (capture time of the request segment to that of
// the response segment). The median and p99 of the difference are printed; only sanity is
// asserted (every transaction on the wire, in order, both latencies positive), never a speed.
//
// Expect the engine to see slightly more than the wire: its sentNs is taken when the kernel has
// the bytes (after the capture point's timestamp for the request, at most the send syscall's
// return) and its doneNs when the event loop has read them (after the capture of the response).
#include "engineharness.h"
#include "peerprocess.h"
#include "tsharkcapture.h"

#include "engine/transactionengine.h"

#include <QtTest/QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace mbscope;
using namespace mbscope::testpeers;

namespace {

constexpr int kTransactions = 200;

double percentileUs(std::vector<qint64> v, double p)
{
    std::sort(v.begin(), v.end());
    const auto n = qsizetype(v.size());
    const qsizetype rank = std::clamp<qsizetype>(qsizetype(std::ceil(p / 100.0 * double(n))), 1, n);
    return double(v[size_t(rank - 1)]) / 1000.0;
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

    QList<WireSegment> segments;
    QVERIFY2(capture.stopAndRead(&segments), qPrintable(capture.error()));

    QList<WireSegment> requests;
    QList<WireSegment> responses;
    for (const WireSegment &s : segments) {
        if (s.destinationPort == server.port())
            requests.append(s);
        else if (s.sourcePort == server.port())
            responses.append(s);
    }
    QList<Transaction> records = probe.records();
    std::sort(records.begin(), records.end(), [](const Transaction &a, const Transaction &b) { return a.id < b.id; });
    QCOMPARE(records.size(), qsizetype(kTransactions));
    QCOMPARE(requests.size(), qsizetype(kTransactions));
    QCOMPARE(responses.size(), qsizetype(kTransactions));

    std::vector<qint64> engineNs, wireNs, differenceNs;
    for (qsizetype i = 0; i < records.size(); ++i) {
        const Transaction &t = records.at(i);
        QVERIFY2(t.isOk(), qPrintable(describe(t)));
        QCOMPARE(requests.at(i).payload.toHex(' '), t.request.toHex(' '));
        QCOMPARE(responses.at(i).payload.toHex(' '), t.response.toHex(' '));
        const qint64 wire = responses.at(i).timeNs - requests.at(i).timeNs;
        const qint64 measured = t.latencyNs();
        QVERIFY2(wire > 0, qPrintable(QStringLiteral("transaction %1: the response was captured before the request").arg(i)));
        QVERIFY2(measured > 0, qPrintable(describe(t)));
        // The next request leaves after this response on the wire: the exchanges do not overlap.
        if (i + 1 < records.size())
            QVERIFY(requests.at(i + 1).timeNs >= responses.at(i).timeNs);
        engineNs.push_back(measured);
        wireNs.push_back(wire);
        differenceNs.push_back(measured - wire);
    }
    std::vector<qint64> absolute(differenceNs);
    for (qint64 &d : absolute)
        d = d < 0 ? -d : d;
    qInfo("%s, %d transactions: engine latency median %.1f us p99 %.1f us; wire median %.1f us p99 %.1f us",
          qPrintable(peer), kTransactions, percentileUs(engineNs, 50), percentileUs(engineNs, 99), percentileUs(wireNs, 50),
          percentileUs(wireNs, 99));
    qInfo("engine minus wire: median %.1f us, p99 %.1f us, min %.1f us, max %.1f us; |difference| median %.1f us p99 %.1f us",
          percentileUs(differenceNs, 50), percentileUs(differenceNs, 99), percentileUs(differenceNs, 0),
          percentileUs(differenceNs, 100), percentileUs(absolute, 50), percentileUs(absolute, 99));
}

QTEST_GUILESS_MAIN(TestLatencyTruth)
#include "tst_latency_truth.moc"
