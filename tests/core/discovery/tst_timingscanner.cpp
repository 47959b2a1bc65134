// TimingScanner's progress and bounds (issue 18: every scan is bounded in count and time, shows
// progress and an estimate of the time left, and can be stopped) against the simulator on
// loopback: steps counted of a plan known at the start, done only growing and reaching the total,
// the first estimate made of the plan's gaps and timeouts, nothing left at the end; the time
// limit and stop() end the scan with what was measured. No assertion on how long anything took.

#include "discovery/timingscanner.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "sim/simunit.h"

#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// A TCP device that answers busy (06) when asked sooner than 20 ms after its last answer and
// serves two clients at once; unit 1 has 30 holding registers, other ids are silent.
struct Device {
    Simulator sim;
    LinkUrl url;

    bool start(double warmUpMs = 0, bool closesAfterAnswer = false)
    {
        SimUnit *unit = sim.addUnit(1);
        SimRange range;
        range.table = SimTable::HoldingRegisters;
        range.count = 30;
        if (!unit->addRange(range))
            return false;
        DeviceLimits limits;
        limits.minGapMs = 20;
        limits.tooSoon = DeviceLimits::TooSoon::Busy;
        limits.warmUpMs = warmUpMs;
        limits.closesAfterAnswer = closesAfterAnswer;
        sim.setLimits(limits);
        SimEndpointOptions options;
        options.maxConnections = 2;
        options.unknownUnit = SimEndpointOptions::UnknownUnit::Ignore;
        QString error;
        SimEndpoint *endpoint = sim.listen(QStringLiteral("tcp://127.0.0.1:0"), options, &error);
        if (!endpoint)
            qWarning().noquote() << error;
        url = endpoint ? endpoint->boundUrl() : LinkUrl();
        return endpoint != nullptr;
    }
};

TimingScanSettings smallScan(const LinkUrl &url)
{
    TimingScanSettings s;
    s.url = url;
    s.unit = 1;
    s.timeoutMs = 300;
    s.gapsMs = {50, 20, 10, 0};
    s.requestsPerGap = 3;
    s.pipelineDepth = 2;
    s.maxClients = 3;
    return s;
}

} // namespace

class TestTimingScanner : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { qRegisterMetaType<JobProgress>(); }
    void progressFollowsThePlan();
    void timeLimitEndsIt();
    void timeLimitBeforeAnyAnswer();
    void stopKeepsWhatWasMeasured();
    void limitMustBePositive();
    void warmUpNarrowed_data();
    void warmUpNarrowed();
};

void TestTimingScanner::progressFollowsThePlan()
{
    Device device;
    QVERIFY(device.start());
    TimingScanner scanner;
    QList<JobProgress> seen;
    connect(&scanner, &TimingScanner::progressChanged, this, [&](const JobProgress &p) { seen.append(p); });
    const std::optional<TimingReport> report = scanner.run(smallScan(device.url));
    QVERIFY(report);
    QCOMPARE(scanner.end(), JobEnd::Completed);
    // The device is busy under 20 ms: errors start at 10 ms, so 0 ms is never asked.
    QCOMPARE(report->shortestCleanGapMs, 20);
    QCOMPARE(report->gaps.size(), 3);
    QCOMPARE(report->clientsServed, 2);

    // The plan: the first answer, 4 gaps x 3 requests, the largest read of 03 (125, then at most
    // 7 more by bisection), the pipelined burst (tcp), 3 clients.
    const int total = 1 + 4 * 3 + 1 + 7 + 1 + 3;
    QVERIFY(seen.size() > 10);
    // Before any answer, the estimate is the plan itself: every step its wait and its timeout,
    // the later parts at the gap 0 ms would give (none tried yet), 20 ms between warm-up asks.
    QCOMPARE(seen.first().done, 0);
    const int warmup = 20 + 300;
    const int gaps = 3 * (50 + 300) + 3 * (20 + 300) + 3 * (10 + 300) + 3 * (0 + 300);
    const int largest = 8 * 300;
    const int pipeline = 300;
    const int clients = 300 + 2 * (300 + 20 + 300);
    QCOMPARE(seen.first().remainingMs, qint64(warmup + gaps + largest + pipeline + clients));
    int done = 0;
    for (const JobProgress &p : std::as_const(seen)) {
        QCOMPARE(p.total, total);
        QVERIFY2(p.done >= done, qPrintable(QStringLiteral("done went from %1 to %2").arg(done).arg(p.done)));
        QVERIFY(p.remainingMs >= 0);
        done = p.done;
    }
    // Steps not needed (the 0 ms gap, the bisection's shorter end) count as done: the whole plan.
    QCOMPARE(seen.last().done, total);
    QCOMPARE(seen.last().remainingMs, qint64(0));
    QCOMPARE(seen.last().percent(), 100);
}

// A device that answers, a limit too short for the gaps: the scan ends at the limit, keeping the
// gap it was measuring (not counted clean: it was not finished).
void TestTimingScanner::timeLimitEndsIt()
{
    Device device;
    QVERIFY(device.start());
    TimingScanSettings s = smallScan(device.url);
    s.gapsMs = {200};
    s.requestsPerGap = 50; // 10 s of gaps
    s.maxDurationMs = 1500;
    TimingScanner scanner;
    QList<JobProgress> seen;
    connect(&scanner, &TimingScanner::progressChanged, this, [&](const JobProgress &p) { seen.append(p); });
    const std::optional<TimingReport> report = scanner.run(s);
    QVERIFY(report);
    QCOMPARE(scanner.end(), JobEnd::TimeLimit);
    QVERIFY(scanner.end() != JobEnd::Stopped);
    QVERIFY(report->firstAnswerMs >= 0);
    QCOMPARE(report->gaps.size(), 1);
    QVERIFY(report->gaps.first().ok >= 1 && report->gaps.first().ok < 50);
    QCOMPARE(report->shortestCleanGapMs, -1);
    QCOMPARE(report->clientsTried, 0);
    QVERIFY(seen.last().done < seen.last().total);
    QCOMPARE(seen.last().remainingMs, qint64(0));
    // The estimate never promises more than the limit leaves.
    for (const JobProgress &p : std::as_const(seen))
        QVERIFY(p.remainingMs <= s.maxDurationMs);
}

// A silent unit: the warm-up would wait 10 s for a first answer; the limit ends it first.
void TestTimingScanner::timeLimitBeforeAnyAnswer()
{
    Device device;
    QVERIFY(device.start());
    TimingScanSettings s = smallScan(device.url);
    s.unit = 9;
    s.timeoutMs = 100;
    s.maxDurationMs = 400;
    TimingScanner scanner;
    const std::optional<TimingReport> report = scanner.run(s);
    QVERIFY(report);
    QCOMPARE(scanner.end(), JobEnd::TimeLimit);
    QVERIFY(report->firstAnswerMs < 0);
    QVERIFY(report->warmupFailures >= 1);
    QVERIFY(report->gaps.isEmpty());
}

// stop() from a progress slot (as Ctrl-C or the Stop button comes) in the middle of the gaps.
void TestTimingScanner::stopKeepsWhatWasMeasured()
{
    Device device;
    QVERIFY(device.start());
    TimingScanner scanner;
    QList<JobProgress> seen;
    connect(&scanner, &TimingScanner::progressChanged, this, [&](const JobProgress &p) {
        seen.append(p);
        if (p.done == 5)
            scanner.stop();
    });
    const std::optional<TimingReport> report = scanner.run(smallScan(device.url));
    QVERIFY(report);
    QCOMPARE(scanner.end(), JobEnd::Stopped);
    QCOMPARE(scanner.end(), JobEnd::Stopped);
    QVERIFY(report->firstAnswerMs >= 0);
    QCOMPARE(report->gaps.size(), 2); // 50 ms done (3), 20 ms begun (1)
    QCOMPARE(report->gaps.constFirst().ok, 3);
    QCOMPARE(report->shortestCleanGapMs, 50);
    QCOMPARE(report->largestQuantity, 0);
    QCOMPARE(report->clientsTried, 0);
    QCOMPARE(seen.last().done, 5);
    QCOMPARE(seen.last().remainingMs, qint64(0));
}

void TestTimingScanner::limitMustBePositive()
{
    TimingScanSettings s;
    s.url = *LinkUrl::parse(QStringLiteral("tcp://127.0.0.1:502")).url;
    s.maxDurationMs = 0;
    QCOMPARE(s.problem(), QStringLiteral("the time limit must be positive"));
    TimingScanner scanner;
    QVERIFY(!scanner.run(s));
}

void TestTimingScanner::warmUpNarrowed_data()
{
    QTest::addColumn<bool>("hangsUp");
    QTest::newRow("keeps the connection") << false;
    QTest::newRow("hangs up after each answer") << true;
}

void TestTimingScanner::warmUpNarrowed()
{
    // A device that ignores what comes in its first 150 ms on a connection: the first answer comes
    // one timeout (300 ms) after the first request, and the warm-up is then found to 10 ms on new
    // connections. Against one that also hangs up, every gap request waits it out (none is
    // ignored) and the gaps shorter than the first cannot be asked: not measured, no minGapMs.
    QFETCH(bool, hangsUp);
    Device device;
    QVERIFY(device.start(150, hangsUp));
    TimingScanSettings s = smallScan(device.url);
    s.gapsMs = {30, 0};
    s.maxClients = 2;
    TimingScanner scanner;
    const std::optional<TimingReport> report = scanner.run(s);
    QVERIFY(report);
    QCOMPARE(report->warmupFailures, 1);
    QVERIFY2(report->firstAnswerMs >= 300, qPrintable(QString::number(report->firstAnswerMs)));
    QVERIFY2(report->warmUpMs >= 150 && report->warmUpMs - report->warmUpRefusedMs <= 10,
             qPrintable(QStringLiteral("%1 %2").arg(report->warmUpMs).arg(report->warmUpRefusedMs)));
    QCOMPARE(report->pauseAfterConnectMs(), report->warmUpMs);
    QCOMPARE(report->gaps.first().failed, 0);
    const QJsonObject limits = report->profileLimits(3);
    QCOMPARE(limits.value(QStringLiteral("warmUpMs")).toDouble(), double(report->warmUpMs));
    QCOMPARE(report->gapsHeldByWarmUp, hangsUp);
    if (hangsUp) {
        QCOMPARE(report->gaps.size(), 1);
        QVERIFY(!limits.contains(QStringLiteral("minGapMs")));
        QCOMPARE(report->recommendedGapMs(), 0);
    } else {
        QCOMPARE(limits.value(QStringLiteral("minGapMs")).toInt(), 30); // 0 ms was refused busy
    }
}

QTEST_GUILESS_MAIN(TestTimingScanner)
#include "tst_timingscanner.moc"
