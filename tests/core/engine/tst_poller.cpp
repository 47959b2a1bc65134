// Polls and sweeps through the engine against a scripted peer: cycles by count and duration,
// overruns, pipelined polling, sweeps over several intervals, and stop in the middle.

#include "enginetesting.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::test;

namespace {

constexpr qint64 kMs = 1000000;

PeerScript mbapServer(int delayMs = 1)
{
    return [delayMs](const QByteArray &request, int) {
        // Unit 2 is absent from the bus: it never answers.
        if (request.at(6) == 2)
            return QList<Reply>{};
        const quint8 function = quint8(request.at(7));
        const QByteArray pdu = function == 0x0F ? hex("0F00000003") : hex("1000000002");
        const quint16 tid = quint16(quint8(request.at(0)) << 8 | quint8(request.at(1)));
        return QList<Reply>{Reply{delayMs, AduBuilder::mbap(pdu, quint8(request.at(6)), tid), false}};
    };
}

// "write bits then write words", as the M221 lab did.
QList<RequestItem> writeItems(const EngineHarness &h, int timeoutMs = 2000)
{
    return {h.item(mbap("0F000000030105", 1, 1), timeoutMs, 0, QStringLiteral("write bits")),
            h.item(mbap("100000000204000a000b", 2, 1), timeoutMs, 0, QStringLiteral("write words"))};
}

} // namespace

class tst_Poller : public QObject
{
    Q_OBJECT

private slots:
    void pollCount();
    void pollDuration();
    void countEndsBeforeDuration();
    void overruns();
    void noOverrunWhenAnswersAreFast();
    void intervalRunsFromTheFirstWrite();
    void pipelinedPoll();
    void sweepThreeIntervals();
    void stopInTheMiddle();
    void stopWithRequestInFlight();
    void stopSweep();
    void emptyPoll();
};

void tst_Poller::pollCount()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer());
    PollSettings poll;
    poll.items = writeItems(h);
    poll.count = 5;
    h.engine.startPoll(poll);
    const std::optional<PollReport> report = h.engine.waitForFinished(30000);
    QVERIFY(report.has_value());
    QVERIFY(!report->sweep);
    QVERIFY(!report->stopped);
    QCOMPARE(report->runs.size(), 1);
    const PollRun &run = report->runs.first();
    QCOMPARE(run.cycles, quint64(5));
    QCOMPARE(run.overruns, quint64(0));
    QVERIFY(!run.stopped);
    QCOMPARE(run.statistics.overall().count(), quint64(10));
    QCOMPARE(run.statistics.overall().ok(), quint64(10));
    QCOMPARE(run.statistics.item(0).count(), quint64(5));
    QCOMPARE(run.statistics.item(1).count(), quint64(5));
    QCOMPARE(run.statistics.overall().latency().count(), qint64(10));
    QVERIFY(run.statistics.overall().latency().minNs() > 0);
    QCOMPARE(run.counters.requestsSent, quint64(10));
    QCOMPARE(run.counters.cycles, quint64(5));
    // Every record reached observers before the report, in order: item 0, item 1, item 0...
    QCOMPARE(h.records.size(), 10);
    for (qsizetype i = 0; i < h.records.size(); ++i) {
        QCOMPARE(h.records.at(i).item, int(i % 2));
        QCOMPARE(h.records.at(i).status, TransactionStatus::Ok);
    }
    QCOMPARE(h.peer->writes.load(), 10);
    QVERIFY(h.waitFor([&] { return !h.progress.polling; }));
    QCOMPARE(h.progress.cycle, quint64(5));
    QCOMPARE(h.progress.ok, quint64(10));
}

void tst_Poller::pollDuration()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer());
    PollSettings poll;
    poll.items = writeItems(h);
    poll.intervalNs = 20 * kMs;
    poll.durationNs = 150 * kMs;
    h.engine.startPoll(poll);
    const std::optional<PollReport> report = h.engine.waitForFinished(30000);
    QVERIFY(report.has_value());
    const PollRun &run = report->runs.first();
    QVERIFY(!run.stopped);
    QVERIFY(run.cycles >= 1);
    QVERIFY(run.elapsedNs >= poll.durationNs);
    QCOMPARE(run.statistics.overall().count(), run.cycles * 2);
    QCOMPARE(quint64(h.peer->writes.load()), run.cycles * 2);
}

void tst_Poller::countEndsBeforeDuration()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer());
    PollSettings poll;
    poll.items = writeItems(h).mid(0, 1);
    poll.count = 3;
    poll.durationNs = 3600 * 1000 * kMs;
    h.engine.startPoll(poll);
    const std::optional<PollReport> report = h.engine.waitForFinished(30000);
    QVERIFY(report.has_value());
    QCOMPARE(report->runs.first().cycles, quint64(3));
    QCOMPARE(report->runs.first().statistics.overall().count(), quint64(3));
}

void tst_Poller::overruns()
{
    // Each answer takes 60 ms against a 20 ms interval: every cycle after the first starts late.
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer(60));
    PollSettings poll;
    poll.items = writeItems(h).mid(1, 1);
    poll.intervalNs = 20 * kMs;
    poll.count = 4;
    h.engine.startPoll(poll);
    const std::optional<PollReport> report = h.engine.waitForFinished(30000);
    QVERIFY(report.has_value());
    const PollRun &run = report->runs.first();
    QCOMPARE(run.cycles, quint64(4));
    QCOMPARE(run.overruns, quint64(3));
    QCOMPARE(run.counters.overruns, quint64(3));
    QCOMPARE(run.statistics.overall().ok(), quint64(4));
    // The cycles ran back to back: each request left after the answer before it.
    for (qsizetype i = 1; i < h.records.size(); ++i)
        QVERIFY(h.records.at(i).sentNs >= h.records.at(i - 1).doneNs);
}

void tst_Poller::noOverrunWhenAnswersAreFast()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer(1));
    PollSettings poll;
    poll.items = writeItems(h).mid(1, 1);
    poll.intervalNs = 300 * kMs;
    poll.count = 3;
    h.engine.startPoll(poll);
    const std::optional<PollReport> report = h.engine.waitForFinished(30000);
    QVERIFY(report.has_value());
    const PollRun &run = report->runs.first();
    QCOMPARE(run.cycles, quint64(3));
    QCOMPARE(run.overruns, quint64(0));
    // Start to start: the cycles' requests were handed to the link at least an interval apart.
    // (writeNs, not sentNs: a link reports its bytes written a little after the write, and on a
    // loaded machine that little varied by more than the timer's lateness.)
    QCOMPARE(h.records.size(), 3);
    for (qsizetype i = 1; i < h.records.size(); ++i)
        QVERIFY2(h.records.at(i).writeNs - h.records.at(i - 1).writeNs >= poll.intervalNs,
                 qPrintable(QStringLiteral("cycle %1 began %2 ms after the one before, the interval is %3 ms")
                                .arg(i + 1)
                                .arg(double(h.records.at(i).writeNs - h.records.at(i - 1).writeNs) / kMs)
                                .arg(poll.intervalNs / kMs)));
}

void tst_Poller::intervalRunsFromTheFirstWrite()
{
    // The link takes 150 ms to open: the first cycle's request waits for it. The second cycle is
    // due an interval after the first one's request went out, not after the poll began (the
    // interval ran from the poll's start, and the second request followed the first by 150 ms;
    // on a loaded machine, by a little less than the interval, which failed the test above).
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer(1));
    h.peer->openDelayMs = 150;
    PollSettings poll;
    poll.items = writeItems(h).mid(1, 1);
    poll.intervalNs = 300 * kMs;
    poll.count = 3;
    h.engine.startPoll(poll);
    const std::optional<PollReport> report = h.engine.waitForFinished(30000);
    QVERIFY(report.has_value());
    const PollRun &run = report->runs.first();
    QCOMPARE(run.cycles, quint64(3));
    QCOMPARE(run.overruns, quint64(0));
    QCOMPARE(h.peer->opens.load(), 1);
    QCOMPARE(h.records.size(), 3);
    for (qsizetype i = 1; i < h.records.size(); ++i)
        QVERIFY2(h.records.at(i).writeNs - h.records.at(i - 1).writeNs >= poll.intervalNs,
                 qPrintable(QStringLiteral("cycle %1 began %2 ms after the one before, the interval is %3 ms")
                                .arg(i + 1)
                                .arg(double(h.records.at(i).writeNs - h.records.at(i - 1).writeNs) / kMs)
                                .arg(poll.intervalNs / kMs)));
}

void tst_Poller::pipelinedPoll()
{
    // The peer answers only once four requests wait, so the poll completes only if four are in
    // flight at once.
    auto held = std::make_shared<QList<QByteArray>>();
    EngineOptions options;
    options.pipelineDepth = 4;
    EngineHarness h(QStringLiteral("tcp://peer:502"), [held](const QByteArray &request, int) {
        held->append(request);
        QList<Reply> replies;
        if (held->size() == 4) {
            for (const QByteArray &r : std::as_const(*held))
                replies.append(Reply{1, mbapAnswer(r, "1000000002"), false});
            held->clear();
        }
        return replies;
    }, options);
    PollSettings poll;
    poll.items = writeItems(h).mid(1, 1);
    poll.count = 20;
    h.engine.startPoll(poll);
    const std::optional<PollReport> report = h.engine.waitForFinished(30000);
    QVERIFY(report.has_value());
    const PollRun &run = report->runs.first();
    QCOMPARE(run.cycles, quint64(20));
    QCOMPARE(run.statistics.overall().ok(), quint64(20));
    QCOMPARE(h.peer->writes.load(), 20);
}

void tst_Poller::sweepThreeIntervals()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer());
    SweepSettings sweep;
    // One item answered, one sent to a unit that never answers: an error rate of one half.
    sweep.poll.items = {writeItems(h).at(1), h.item(mbap("100000000204000a000b", 3, 2), 50, 0, QStringLiteral("absent unit"))};
    sweep.poll.count = 4;
    sweep.intervalsNs = {0, 10 * kMs, 20 * kMs};
    h.engine.startSweep(sweep);
    const std::optional<PollReport> report = h.engine.waitForFinished(60000);
    QVERIFY(report.has_value());
    QVERIFY(report->sweep);
    QVERIFY(!report->stopped);
    QCOMPARE(report->runs.size(), 3);
    for (qsizetype i = 0; i < 3; ++i) {
        const PollRun &run = report->runs.at(i);
        QCOMPARE(run.intervalNs, sweep.intervalsNs.at(i));
        QCOMPARE(run.cycles, quint64(4));
        const Statistics &all = run.statistics.overall();
        QCOMPARE(all.count(), quint64(8));
        QCOMPARE(all.ok(), quint64(4));
        QCOMPARE(all.timeouts(), quint64(4));
        QCOMPARE(all.errorRate(), 0.5);
        QCOMPARE(all.latency().count(), qint64(4));
        QCOMPARE(run.statistics.item(1).timeouts(), quint64(4));
    }
    QCOMPARE(h.records.size(), 24);
}

void tst_Poller::stopInTheMiddle()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer(5));
    PollSettings poll;
    poll.items = writeItems(h);
    h.engine.startPoll(poll); // no count, no duration: until stopped
    QVERIFY(h.waitForRecords(6));
    h.engine.stop();
    QVERIFY(h.waitForReport());
    const PollReport &report = h.reports.first();
    QVERIFY(report.stopped);
    QCOMPARE(report.runs.size(), 1);
    const PollRun &run = report.runs.first();
    QVERIFY(run.stopped);
    QVERIFY(run.statistics.overall().count() >= 6);
    QCOMPARE(run.statistics.overall().count(), quint64(h.records.size()));
    QCOMPARE(run.statistics.overall().ok(), run.statistics.overall().count());
    // Nothing more is sent after the stop.
    const int writes = h.peer->writes.load();
    QTest::qWait(100);
    QCOMPARE(h.peer->writes.load(), writes);
}

void tst_Poller::stopWithRequestInFlight()
{
    // A request that would wait a minute is abandoned at once.
    EngineHarness h(QStringLiteral("tcp://peer:502"), [](const QByteArray &, int) { return QList<Reply>{}; });
    PollSettings poll;
    poll.items = {h.item(mbap("0300000001"), 60000)};
    poll.count = 10;
    h.engine.startPoll(poll);
    QVERIFY(h.waitFor([&] { return h.peer->writes.load() == 1; }));
    h.engine.stop();
    QVERIFY(h.waitForReport(10000));
    const PollRun &run = h.reports.first().runs.first();
    QVERIFY(run.stopped);
    QCOMPARE(run.statistics.overall().count(), quint64(0));
    QCOMPARE(run.counters.abandoned, quint64(1));
    QCOMPARE(run.cycles, quint64(1));
}

void tst_Poller::stopSweep()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer(2));
    SweepSettings sweep;
    sweep.poll.items = writeItems(h).mid(0, 1);
    sweep.intervalsNs = {0, 0, 0};
    h.engine.startSweep(sweep); // the first run has no end of its own
    QVERIFY(h.waitForRecords(3));
    h.engine.stop();
    QVERIFY(h.waitForReport());
    const PollReport &report = h.reports.first();
    QVERIFY(report.sweep);
    QVERIFY(report.stopped);
    QCOMPARE(report.runs.size(), 1);
    QVERIFY(report.runs.first().stopped);
    QVERIFY(report.runs.first().statistics.overall().count() >= 3);
}

void tst_Poller::emptyPoll()
{
    EngineHarness h(QStringLiteral("tcp://peer:502"), mbapServer());
    h.engine.startPoll(PollSettings{});
    const std::optional<PollReport> report = h.engine.waitForFinished(10000);
    QVERIFY(report.has_value());
    QCOMPARE(report->runs.size(), 1);
    QCOMPARE(report->runs.first().cycles, quint64(0));
    QCOMPARE(h.peer->writes.load(), 0);
}

QTEST_GUILESS_MAIN(tst_Poller)
#include "tst_poller.moc"
