// The transaction engine against a scripted peer in the same process: a peer that closes
// mid-frame or refuses, pipelining, broadcasts, write reports that come late, many requests at
// once and the traffic log.

#include "enginetesting.h"

#include "traffic/trafficlog.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::test;

Q_DECLARE_METATYPE(mbscope::TransactionStatus)

namespace {

PeerScript answerWith(const QByteArray &reply, int delayMs = 1)
{
    return [reply, delayMs](const QByteArray &, int) { return QList<Reply>{Reply{delayMs, reply, false}}; };
}

// Answers every MBAP request with the PDU, echoing its transaction id and unit.
PeerScript mbapServer(const char *pduHex, int delayMs = 1)
{
    const QByteArray pdu = hex(pduHex);
    return [pdu, delayMs](const QByteArray &request, int) {
        const quint16 tid = quint16(quint8(request.at(0)) << 8 | quint8(request.at(1)));
        return QList<Reply>{Reply{delayMs, AduBuilder::mbap(pdu, quint8(request.at(6)), tid), false}};
    };
}

void checkTimes(const Transaction &t)
{
    QVERIFY2(t.sentNs > 0, "sentNs set");
    QVERIFY2(t.sentNs <= t.firstByteNs, "the answer began after the request was written");
    QVERIFY2(t.firstByteNs <= t.doneNs, "the answer's first byte came before its last");
    QVERIFY(t.latencyNs() > 0);
}

} // namespace

class tst_EngineFlow : public QObject
{
    Q_OBJECT

private slots:
    void closesMidFrame();
    void linkRefusedThenReconnects();
    void pipeliningOutOfOrder();
    void noPipeliningSendsBytesAsGiven();
    void broadcast();
    void broadcastAnswered();
    void broadcastWaitsTheLinkTurnaround();
    void answerBeforeWriteReport();
    void manySends();
    void sendAndWaitDoesNotWaitForTheBatch();
    void trafficLog();
};

void tst_EngineFlow::closesMidFrame()
{
    const QByteArray answer = mbap("0304000a000b", 1, 1);
    EngineHarness h(QStringLiteral("tcp://peer:502"), [answer](const QByteArray &, int index) {
        if (index == 0)
            return QList<Reply>{Reply{1, answer.left(9), true}};
        return QList<Reply>{Reply{1, answer, false}};
    });
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(mbap("0300000002", 1, 1)));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::LinkError);
    QVERIFY2(t->problem.contains(QLatin1String("closed")), qPrintable(t->problem));
    QVERIFY2(t->problem.contains(QLatin1String("9 bytes of an unfinished answer")), qPrintable(t->problem));
    QVERIFY(t->response.isEmpty());
    // The next request reconnects and succeeds.
    const std::optional<Transaction> next = h.engine.sendAndWait(h.item(mbap("0300000002", 1, 1)));
    QVERIFY(next.has_value());
    QCOMPARE(next->status, TransactionStatus::Ok);
    QCOMPARE(h.peer->opens.load(), 2);
    QVERIFY(h.waitFor([&] { return h.progress.counters.connects == 2; }));
    QCOMPARE(h.progress.counters.skippedBytes, quint64(9));
    QCOMPARE(h.progress.counters.linkErrors, quint64(1));
}

// A plan's send steps come one after the other: each must return with its answer, not when the
// observers' batch is next due (with batches a minute apart, the old wait gave up empty-handed).
void tst_EngineFlow::sendAndWaitDoesNotWaitForTheBatch()
{
    EngineOptions options;
    options.batchIntervalMs = 60000;
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer("0304000a000b"), options);
    for (quint16 tid = 1; tid <= 3; ++tid) {
        const std::optional<Transaction> t = h.engine.sendAndWait(h.item(mbap("0300000002", tid, 1)), 5000);
        QVERIFY2(t.has_value(), "sendAndWait returned without the transaction");
        QCOMPARE(t->status, TransactionStatus::Ok);
    }
}

void tst_EngineFlow::linkRefusedThenReconnects()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer("0304000a000b"));
    h.peer->refuse = true;
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(mbap("0300000002")));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::LinkError);
    QVERIFY2(t->problem.contains(QLatin1String("tcp://peer:502")), qPrintable(t->problem));
    QVERIFY2(t->problem.contains(QLatin1String("refused")), qPrintable(t->problem));
    QCOMPARE(t->sentNs, qint64(0));
    h.peer->refuse = false;
    const std::optional<Transaction> next = h.engine.sendAndWait(h.item(mbap("0300000002")));
    QVERIFY(next.has_value());
    QCOMPARE(next->status, TransactionStatus::Ok);
    QCOMPARE(h.peer->opens.load(), 2);
}

void tst_EngineFlow::pipeliningOutOfOrder()
{
    // The peer answers nothing until four requests are in flight, then answers them last first.
    auto held = std::make_shared<QList<QByteArray>>();
    EngineOptions options;
    options.pipelineDepth = 4;
    EngineHarness h(QStringLiteral("tcp://peer:502"), [held](const QByteArray &request, int) {
        held->append(request);
        QList<Reply> replies;
        if (held->size() == 4) {
            for (int i = 3; i >= 0; --i)
                replies.append(Reply{(3 - i) * 10, mbapAnswer(held->at(i), "0304000a000b"), false});
            held->clear();
        }
        return replies;
    }, options);
    // The same bytes four times: the engine must give each its own transaction id.
    const QByteArray request = mbap("0300000002", 1, 1);
    QList<quint64> ids;
    for (int i = 0; i < 4; ++i)
        ids.append(h.engine.send(h.item(request)));
    QVERIFY(h.waitForRecords(4));
    QSet<QByteArray> tids;
    int rewritten = 0;
    for (qsizetype i = 0; i < 4; ++i) {
        const Transaction &t = h.records.at(i);
        QCOMPARE(t.status, TransactionStatus::Ok);
        QCOMPARE(t.response.left(2), t.request.left(2));
        QCOMPARE(t.request.mid(2), request.mid(2));
        tids.insert(t.request.left(2));
        rewritten += t.transactionIdRewritten ? 1 : 0;
        QCOMPARE(t.transactionIdRewritten, t.request.left(2) != request.left(2));
        checkTimes(t);
    }
    QCOMPARE(tids.size(), 4);
    QVERIFY(rewritten >= 3);
    // Answered last first: records come in the order of the answers.
    QCOMPARE(h.records.at(0).id, ids.at(3));
    QCOMPARE(h.records.at(3).id, ids.at(0));
}

void tst_EngineFlow::noPipeliningSendsBytesAsGiven()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer("0304000a000b"));
    const QByteArray request = mbap("0300000002", 0xBEEF, 1);
    for (int i = 0; i < 3; ++i)
        h.engine.send(h.item(request));
    QVERIFY(h.waitForRecords(3));
    for (const Transaction &t : std::as_const(h.records)) {
        QCOMPARE(t.status, TransactionStatus::Ok);
        QCOMPARE(t.request, request);
        QVERIFY(!t.transactionIdRewritten);
    }
}

void tst_EngineFlow::broadcast()
{
    EngineOptions options;
    options.broadcastTurnaroundMs = 50;
    EngineHarness h(QStringLiteral("rtu-tcp://peer:4001"), [](const QByteArray &request, int) {
        if (request.at(0) == 0)
            return QList<Reply>{};
        return QList<Reply>{Reply{1, rtu("0304000a000b", 1), false}};
    }, options);
    const QByteArray broadcastWrite = rtu("0600010003", 0);
    h.engine.send(h.item(broadcastWrite));
    h.engine.send(h.item(rtu("0300000002", 1)));
    QVERIFY(h.waitForRecords(2));
    const Transaction &b = h.records.at(0);
    QCOMPARE(b.status, TransactionStatus::Broadcast);
    QVERIFY(b.response.isEmpty());
    QVERIFY(b.problem.isEmpty());
    QCOMPARE(h.records.at(1).status, TransactionStatus::Ok);
    // The next request waited for the turnaround after the broadcast left.
    QVERIFY(h.records.at(1).sentNs >= b.sentNs + 50 * 1000000LL);
}

void tst_EngineFlow::broadcastAnswered()
{
    EngineHarness h(QStringLiteral("rtu-tcp://peer:4001"), answerWith(rtu("0600010003", 3)));
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(rtu("0600010003", 0)));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::Unexpected);
    QVERIFY(t->problem.contains(QLatin1String("broadcast")));
    QCOMPARE(t->response, rtu("0600010003", 3));
}

void tst_EngineFlow::broadcastWaitsTheLinkTurnaround()
{
    // The URL's RS485 turnaround delay is the wait after a broadcast (Serial Line V1.02, 2.4.1).
    EngineOptions options;
    options.broadcastTurnaroundMs = 1;
    EngineHarness h(QStringLiteral("rtu:///dev/ttyTEST?baud=19200&turnaround=80ms"), [](const QByteArray &request, int) {
        return request.at(0) == 0 ? QList<Reply>{} : QList<Reply>{Reply{1, rtu("0304000a000b", 1), false}};
    }, options);
    h.engine.send(h.item(rtu("0600010003", 0)));
    h.engine.send(h.item(rtu("0300000002", 1)));
    QVERIFY(h.waitForRecords(2));
    QCOMPARE(h.records.at(0).status, TransactionStatus::Broadcast);
    QCOMPARE(h.records.at(1).status, TransactionStatus::Ok);
    QVERIFY(h.records.at(1).sentNs >= h.records.at(0).sentNs + 80 * 1000000LL);
}

void tst_EngineFlow::answerBeforeWriteReport()
{
    // The link reports each write 40 ms late, with the write's time. The first answer comes
    // before that report, the second long after: the first report must not be taken for the
    // second request's, which is in flight when it comes.
    EngineHarness h(QStringLiteral("rtu-tcp://peer:4001"), [](const QByteArray &, int index) {
        return QList<Reply>{Reply{index % 2 == 0 ? 5 : 100, rtu("0304000a000b", 1), false}};
    });
    h.peer->writtenDelayMs = 40;
    for (int i = 0; i < 3; ++i)
        h.engine.send(h.item(rtu("0300000002", 1)));
    QVERIFY(h.waitForRecords(3));
    for (qsizetype i = 0; i < 3; ++i) {
        QCOMPARE(h.records.at(i).status, TransactionStatus::Ok);
        checkTimes(h.records.at(i));
        if (i > 0)
            QVERIFY(h.records.at(i).sentNs >= h.records.at(i - 1).doneNs);
    }
}

void tst_EngineFlow::manySends()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer("0304000a000b", 0));
    QList<quint64> ids;
    for (int i = 0; i < 300; ++i)
        ids.append(h.engine.send(h.item(mbap("0300000002", quint16(i), 1))));
    QVERIFY(h.waitForRecords(300, 30000));
    for (qsizetype i = 0; i < 300; ++i) {
        QCOMPARE(h.records.at(i).id, ids.at(i));
        QCOMPARE(h.records.at(i).status, TransactionStatus::Ok);
    }
    QVERIFY(h.batches <= 300);
}

void tst_EngineFlow::trafficLog()
{
    TrafficLog log;
    const QByteArray garbage = hex("ffff");
    const QByteArray answer = mbap("0304000a000b", 1, 1);
    {
        EngineHarness h(QStringLiteral("tcp://peer:502"), [=](const QByteArray &, int index) {
            return index == 0 ? QList<Reply>{Reply{1, garbage + answer, false}} : QList<Reply>{};
        });
        h.engine.setTrafficLog(&log);
        const std::optional<Transaction> ok = h.engine.sendAndWait(h.item(mbap("0300000002", 1, 1)));
        const std::optional<Transaction> lost = h.engine.sendAndWait(h.item(mbap("0300000002", 2, 1), 50));
        QVERIFY(ok && lost);
        QCOMPARE(ok->status, TransactionStatus::Ok);
        QCOMPARE(lost->status, TransactionStatus::Timeout);
        h.engine.setTrafficLog(nullptr);

        QCOMPARE(log.size(), quint64(5));
        const TrafficEntry sent = log.at(0);
        QCOMPARE(sent.direction, TrafficDirection::Out);
        QCOMPARE(sent.verdict, TrafficVerdict::Sent);
        QCOMPARE(sent.transactionId, ok->id);
        QCOMPARE(sent.bytes.toByteArray(), ok->request);
        const TrafficEntry junk = log.at(1);
        QCOMPARE(junk.direction, TrafficDirection::In);
        QCOMPARE(junk.verdict, TrafficVerdict::Garbage);
        QCOMPARE(junk.bytes.toByteArray(), garbage);
        const TrafficEntry in = log.at(2);
        QCOMPARE(in.verdict, TrafficVerdict::Ok);
        QCOMPARE(in.transactionId, ok->id);
        QCOMPARE(in.bytes.toByteArray(), answer);
        QCOMPARE(in.tNs, ok->firstByteNs);
        QCOMPARE(log.at(3).transactionId, lost->id);
        QCOMPARE(log.at(3).verdict, TrafficVerdict::Sent);
        const TrafficEntry timeout = log.at(4);
        QCOMPARE(timeout.verdict, TrafficVerdict::Timeout);
        QCOMPARE(timeout.transactionId, lost->id);
        QVERIFY(timeout.bytes.isEmpty());
    }
}

QTEST_GUILESS_MAIN(tst_EngineFlow)
#include "tst_engineflow.moc"
