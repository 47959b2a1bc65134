// DueTimer: fires once, never before its due time on the monotonic clock (it spins the last
// stretch), not at all once stopped, and only for the latest start().
#include "transport/duetimer.h"
#include "transport/monotonicclock.h"

#include <QtTest/QtTest>

using namespace mbscope;

class TestDueTimer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void firesOnceNotBeforeDue_data();
    void firesOnceNotBeforeDue();
    void stoppedTimerStaysSilent();
    void latestStartCounts();
};

void TestDueTimer::firesOnceNotBeforeDue_data()
{
    QTest::addColumn<qint64>("inNs");
    QTest::newRow("a time passed") << qint64(-1'000'000);
    QTest::newRow("now") << qint64(0);
    QTest::newRow("100 us: inside the spin") << qint64(100'000);
    QTest::newRow("t3.5 above 19200 baud: 1.75 ms") << qint64(1'750'000);
    QTest::newRow("t3.5 at 9600 baud: 4.01 ms") << qint64(4'010'417);
    QTest::newRow("20 ms") << qint64(20'000'000);
}

void TestDueTimer::firesOnceNotBeforeDue()
{
    QFETCH(qint64, inNs);
    DueTimer timer;
    QList<qint64> fired;
    connect(&timer, &DueTimer::timeout, this, [&fired] { fired.append(monotonicNowNs()); });
    const qint64 due = monotonicNowNs() + inNs;
    timer.start(due);
    QVERIFY(timer.isActive());
    QTRY_COMPARE_WITH_TIMEOUT(fired.size(), 1, 5000);
    QVERIFY2(fired.first() >= due, qPrintable(QStringLiteral("fired %1 ns before its time").arg(due - fired.first())));
    QVERIFY(!timer.isActive());
    QTest::qWait(30);
    QCOMPARE(fired.size(), 1); // one-shot
}

void TestDueTimer::stoppedTimerStaysSilent()
{
    DueTimer timer;
    int fired = 0;
    connect(&timer, &DueTimer::timeout, this, [&fired] { ++fired; });
    timer.stop(); // never started: nothing to undo
    timer.start(monotonicNowNs() + 5'000'000);
    timer.stop();
    QVERIFY(!timer.isActive());
    QTest::qWait(50);
    QCOMPARE(fired, 0);
}

void TestDueTimer::latestStartCounts()
{
    DueTimer timer;
    QList<qint64> fired;
    connect(&timer, &DueTimer::timeout, this, [&fired] { fired.append(monotonicNowNs()); });
    timer.start(monotonicNowNs() + 50'000'000);
    const qint64 due = monotonicNowNs() + 2'000'000; // moved earlier
    timer.start(due);
    QTRY_COMPARE_WITH_TIMEOUT(fired.size(), 1, 5000);
    QVERIFY(fired.first() >= due);
    QTest::qWait(100); // past the first due time: it was replaced, not added
    QCOMPARE(fired.size(), 1);
}

QTEST_GUILESS_MAIN(TestDueTimer)
#include "tst_duetimer.moc"
