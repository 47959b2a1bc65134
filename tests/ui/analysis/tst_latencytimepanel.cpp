// LatencyTimePanel: one point per transaction at its send time, timeouts (and every other request
// without a usable answer) marked, against a poll of the built-in simulator that drops answers.
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "analysis/latencytimepanel.h"
#include "link/linkcontroller.h"
#include "common/plotcursor.h"

#include "exchange/statistics.h"

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>
#include <qcustomplot.h>

using namespace mbscope;

class TestLatencyTimePanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void pointsByStatus_data();
    void pointsByStatus();
    void pollWithDropsMarksTimeouts();
    void batchesAppendAndFollow();
    void longPollKeepsPointBudget();
};

namespace {

Transaction transaction(TransactionStatus status, qint64 sentMs, qint64 latencyMs)
{
    Transaction t;
    t.status = status;
    t.sentNs = 1'000'000'000 + sentMs * 1'000'000;
    const bool answered = status != TransactionStatus::Timeout && status != TransactionStatus::LinkError
        && status != TransactionStatus::Broadcast;
    t.doneNs = answered ? t.sentNs + latencyMs * 1'000'000 : 0;
    return t;
}

} // namespace

void TestLatencyTimePanel::pointsByStatus_data()
{
    QTest::addColumn<QList<int>>("statuses"); // TransactionStatus values, sent 10 ms apart
    QTest::addColumn<int>("answered");
    QTest::addColumn<int>("exceptions");
    QTest::addColumn<int>("failed");
    const auto s = [](TransactionStatus status) { return int(status); };
    QTest::newRow("all ok") << QList<int>{s(TransactionStatus::Ok), s(TransactionStatus::Ok)} << 2 << 0 << 0;
    QTest::newRow("timeouts are marks") << QList<int>{s(TransactionStatus::Ok), s(TransactionStatus::Timeout),
                                                      s(TransactionStatus::Timeout)} << 1 << 0 << 2;
    QTest::newRow("exceptions have a latency") << QList<int>{s(TransactionStatus::Exception), s(TransactionStatus::Ok)}
                                               << 1 << 1 << 0;
    QTest::newRow("every unusable answer is a mark")
        << QList<int>{s(TransactionStatus::CrcError), s(TransactionStatus::Malformed), s(TransactionStatus::Unexpected),
                      s(TransactionStatus::LinkError)}
        << 0 << 0 << 4;
    QTest::newRow("late and broadcast are no points")
        << QList<int>{s(TransactionStatus::Timeout), s(TransactionStatus::Late), s(TransactionStatus::Broadcast)} << 0 << 0 << 1;
}

void TestLatencyTimePanel::pointsByStatus()
{
    QFETCH(QList<int>, statuses);
    QFETCH(int, answered);
    QFETCH(int, exceptions);
    QFETCH(int, failed);
    LatencyTimePanel panel;
    QList<Transaction> batch;
    for (int i = 0; i < statuses.size(); ++i)
        batch.append(transaction(TransactionStatus(statuses.at(i)), 10 * i, 3 + i));
    panel.addTransactions(batch);
    panel.redrawNow();
    QCOMPARE(panel.graphs().answered->dataCount(), answered);
    QCOMPARE(panel.graphs().exceptions->dataCount(), exceptions);
    QCOMPARE(panel.graphs().failed->dataCount(), failed);
    QVERIFY2(panel.summary().startsWith(QStringLiteral("%1 transactions").arg(answered + exceptions + failed)),
             qPrintable(panel.summary()));
    QCOMPARE(panel.graphs().failed->name(), QStringLiteral("no usable answer (%1), drawn at 0").arg(failed));
}

void TestLatencyTimePanel::pollWithDropsMarksTimeouts()
{
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    FaultRule drop;
    drop.kind = FaultRule::Kind::Drop;
    drop.probability = 0.3;
    sim.host()->setFaultRules(FaultRuleSet{7, {drop}});

    LinkUrl url = started.url;
    url.responseTimeoutMs = 100; // a dropped answer is a timeout 100 ms later
    LinkController controller;
    LatencyTimePanel panel;
    QList<Transaction> seen;
    connect(&controller, &LinkController::transactionsFinished, &panel, &LatencyTimePanel::addTransactions);
    connect(&controller, &LinkController::transactionsFinished, this,
            [&seen](const QList<Transaction> &batch) { seen += batch; });
    QSignalSpy finished(&controller, &LinkController::pollFinished);
    controller.connectTo(url);
    const int count = 40;
    QVERIFY(controller.startPoll(QByteArray::fromHex("01030079001615DD"), 0, count));
    QVERIFY(finished.wait(30000));
    const PollReport report = finished.first().first().value<PollReport>();
    const Statistics &statistics = report.runs.constFirst().statistics.overall();
    panel.redrawNow();

    QCOMPARE(statistics.count(), quint64(count));
    QVERIFY2(statistics.timeouts() > 0, "the drop rule made no timeouts: the test would not see the marks");
    QVERIFY(statistics.ok() > 0);
    int timeouts = 0;
    int answered = 0;
    for (const Transaction &t : std::as_const(seen)) {
        timeouts += t.status == TransactionStatus::Timeout ? 1 : 0;
        answered += t.status == TransactionStatus::Ok ? 1 : 0;
    }
    // One point per transaction: the engine's statistics and the points agree.
    QCOMPARE(quint64(panel.graphs().answered->dataCount()), statistics.ok());
    QCOMPARE(quint64(panel.graphs().failed->dataCount()), statistics.timeouts());
    QCOMPARE(panel.graphs().failed->dataCount(), timeouts);
    QCOMPARE(panel.graphs().answered->dataCount(), answered);
    QCOMPARE(quint64(panel.graphs().answered->dataCount() + panel.graphs().exceptions->dataCount()
                     + panel.graphs().failed->dataCount()),
             statistics.count());
    // The marks are at the timed-out requests' send times, on the time axis.
    const qint64 startNs = seen.constFirst().sentNs;
    auto mark = panel.graphs().failed->data()->constBegin();
    for (const Transaction &t : std::as_const(seen)) {
        if (t.status != TransactionStatus::Timeout)
            continue;
        QCOMPARE(mark->key, double(t.sentNs - startNs) / 1e9);
        QCOMPARE(mark->value, 0.0);
        ++mark;
    }
    // The answered points hold their latencies in ms: the slowest is the statistics' maximum.
    double slowest = 0;
    for (auto it = panel.graphs().answered->data()->constBegin(); it != panel.graphs().answered->data()->constEnd(); ++it)
        slowest = std::max(slowest, it->value);
    QCOMPARE(slowest, double(statistics.latency().maxNs()) / 1e6);

    // The cursor on the first timeout reads it.
    const double firstMark = panel.graphs().failed->data()->constBegin()->key;
    panel.resize(900, 420);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.redrawNow();
    panel.cursor()->setX(firstMark);
    panel.plot()->replot();
    QVERIFY2(panel.cursor()->readout().contains(QLatin1String("no usable answer")), qPrintable(panel.cursor()->readout()));
    // On an answered point it reads the latency.
    const auto answeredPoint = panel.graphs().answered->data()->constBegin();
    panel.cursor()->setX(answeredPoint->key);
    panel.plot()->replot();
    const QString expected = QStringLiteral("answered: %1 ms").arg(answeredPoint->value, 0, 'f', 3);
    QVERIFY2(panel.cursor()->readout().contains(expected), qPrintable(panel.cursor()->readout()));
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("latency-over-time.png")));
}

void TestLatencyTimePanel::batchesAppendAndFollow()
{
    LatencyTimePanel panel;
    panel.resize(800, 400);
    QVERIFY(panel.isFollowing());
    for (int batch = 0; batch < 10; ++batch) {
        QList<Transaction> transactions;
        for (int i = 0; i < 100; ++i)
            transactions.append(transaction(TransactionStatus::Ok, (batch * 100 + i) * 10, 2 + i % 5));
        panel.addTransactions(transactions);
    }
    panel.redrawNow();
    QCOMPARE(panel.graphs().answered->dataCount(), 1000);
    // Following: the newest point (9.99 s) and the slowest (6 ms) are in view.
    QVERIFY(panel.plot()->xAxis->range().contains(9.99));
    QVERIFY(panel.plot()->yAxis->range().contains(6.0));
    // Zooming by hand stops following; new points no longer move the axes.
    panel.plot()->xAxis->setRange(1, 2);
    QVERIFY(!panel.isFollowing());
    panel.addTransactions({transaction(TransactionStatus::Ok, 20000, 3)});
    panel.redrawNow();
    QCOMPARE(panel.plot()->xAxis->range(), QCPRange(1, 2));
    panel.setFollowing(true);
    QVERIFY(panel.plot()->xAxis->range().contains(20.0));
    panel.clear();
    QCOMPARE(panel.graphs().answered->dataCount(), 0);
}

// Issue 31: 100,000 transactions keep at most the budget's points (the window's memory stays flat
// all day), the legend and summary still count every one, and a spike is still drawn.
void TestLatencyTimePanel::longPollKeepsPointBudget()
{
    LatencyTimePanel panel;
    for (int batch = 0; batch < 100; ++batch) {
        QList<Transaction> transactions;
        for (int i = 0; i < 1000; ++i) {
            const int n = batch * 1000 + i;
            transactions.append(transaction(TransactionStatus::Ok, n * 10, n == 54321 ? 900 : 2 + n % 5));
        }
        panel.addTransactions(transactions);
        QVERIFY(panel.graphs().answered->dataCount() <= DecimatedSeries::kDefaultBudget);
    }
    panel.redrawNow();
    QCOMPARE(panel.answeredSeries().added(), 100000);
    QVERIFY(panel.summary().startsWith(QStringLiteral("100000 transactions: 100000 answered")));
    QCOMPARE(panel.graphs().answered->name(), QStringLiteral("answered (100000)"));
    double highest = 0;
    for (auto it = panel.graphs().answered->data()->constBegin(); it != panel.graphs().answered->data()->constEnd(); ++it)
        highest = std::max(highest, it->value);
    QCOMPARE(highest, 900.0);
}

QTEST_MAIN(TestLatencyTimePanel)
#include "tst_latencytimepanel.moc"
