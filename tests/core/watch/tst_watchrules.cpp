// WatchRuleEvaluator: each condition, forPolls consecutive polls before a rule fires, clearing on
// the first poll it does not hold, failed polls neither advancing nor breaking a run, counts,
// messages made from the rule, and the active rule of a value.
#include "watch/watchcsvlog.h"
#include "watch/watchruleevaluator.h"

#include <QtTest/QtTest>

using namespace mbscope;

namespace {

WatchDefinition watchWithRule(const WatchRule &rule)
{
    WatchDefinition w;
    w.name = QStringLiteral("gamma");
    w.address = 0x86;
    w.quantity = 2;
    WatchPoint p;
    p.address = 0x86;
    p.name = QStringLiteral("counts");
    p.unit = QStringLiteral("cps");
    w.points.append(p);
    w.rules.append(rule);
    return w;
}

QList<WatchPointValue> values(double counts, quint64 raw = 0)
{
    WatchPointValue v;
    v.address = 0x86;
    v.name = QStringLiteral("counts");
    v.unit = QStringLiteral("cps");
    v.value = counts;
    v.raw = raw ? raw : quint64(counts);
    WatchPointValue other;
    other.address = 0x87;
    return {v, other};
}

} // namespace

class TestWatchRules : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void conditions_data();
    void conditions();
    void forPollsConsecutive();
    void failedPollKeepsRun();
    void addressAsPoint();
    void addressNamedInUpperCase();
    void messages();
};

void TestWatchRules::conditions_data()
{
    QTest::addColumn<int>("condition");
    QTest::addColumn<double>("low");
    QTest::addColumn<double>("high");
    QTest::addColumn<double>("value");
    QTest::addColumn<bool>("holds");
    using C = WatchRule::Condition;
    QTest::newRow("above, over") << int(C::Above) << 0.0 << 100.0 << 100.5 << true;
    QTest::newRow("above, at") << int(C::Above) << 0.0 << 100.0 << 100.0 << false;
    QTest::newRow("below, under") << int(C::Below) << 10.0 << 0.0 << 9.0 << true;
    QTest::newRow("outside, high") << int(C::Outside) << 10.0 << 20.0 << 21.0 << true;
    QTest::newRow("outside, within") << int(C::Outside) << 10.0 << 20.0 << 20.0 << false;
    QTest::newRow("inside, edge") << int(C::Inside) << 10.0 << 20.0 << 10.0 << true;
    QTest::newRow("equal") << int(C::Equal) << 3.0 << 0.0 << 3.0 << true;
    QTest::newRow("notEqual") << int(C::NotEqual) << 3.0 << 0.0 << 3.0 << false;
    QTest::newRow("bits, set") << int(C::Bits) << 8.0 << 0.0 << 12.0 << true;
    QTest::newRow("bits, clear") << int(C::Bits) << 8.0 << 0.0 << 7.0 << false;
}

void TestWatchRules::conditions()
{
    QFETCH(int, condition);
    QFETCH(double, low);
    QFETCH(double, high);
    QFETCH(double, value);
    QFETCH(bool, holds);
    WatchRule r;
    r.condition = WatchRule::Condition(condition);
    r.low = low;
    r.high = high;
    QCOMPARE(WatchRuleEvaluator::holds(r, value, quint64(value)), holds);
}

void TestWatchRules::forPollsConsecutive()
{
    WatchRule r;
    r.point = QStringLiteral("counts");
    r.condition = WatchRule::Condition::Above;
    r.high = 300;
    r.forPolls = 3;
    r.severity = WatchSeverity::Alarm;
    r.colour = QStringLiteral("#D32F2F");
    WatchRuleEvaluator e(watchWithRule(r));
    QVERIFY(e.evaluate(values(400)).isEmpty());
    QVERIFY(e.evaluate(values(400)).isEmpty());
    QVERIFY(e.evaluate(values(200)).isEmpty()); // the run is broken
    QVERIFY(e.evaluate(values(400)).isEmpty());
    QVERIFY(e.evaluate(values(400)).isEmpty());
    QVERIFY(!e.isActive(0));
    const QList<WatchRuleEvent> fired = e.evaluate(values(401), 1234);
    QCOMPARE(fired.size(), 1);
    QCOMPARE(fired.first().fired, true);
    QCOMPARE(fired.first().value, 401.0);
    QCOMPARE(fired.first().severity, WatchSeverity::Alarm);
    QCOMPARE(fired.first().colour, QStringLiteral("#D32F2F"));
    QCOMPARE(fired.first().timeMs, 1234);
    QCOMPARE(fired.first().firedCount, 1u);
    QVERIFY(e.isActive(0));
    QVERIFY(e.evaluate(values(500)).isEmpty()); // fired once, not again while it holds
    const QList<WatchRuleEvent> cleared = e.evaluate(values(100));
    QCOMPARE(cleared.size(), 1);
    QCOMPARE(cleared.first().fired, false);
    QCOMPARE(e.firedCount(0), 1u);
    QVERIFY(!e.isActive(0));
}

void TestWatchRules::failedPollKeepsRun()
{
    WatchRule r;
    r.point = QStringLiteral("counts");
    r.condition = WatchRule::Condition::Above;
    r.high = 300;
    r.forPolls = 2;
    WatchRuleEvaluator e(watchWithRule(r));
    QVERIFY(e.evaluate(values(400)).isEmpty());
    QVERIFY(e.evaluate({}).isEmpty()); // a timeout: no values
    QCOMPARE(e.evaluate(values(400)).size(), 1);
}

void TestWatchRules::addressAsPoint()
{
    WatchRule r;
    r.point = QStringLiteral("0x0087");
    r.condition = WatchRule::Condition::Equal;
    r.low = 0;
    const WatchDefinition w = watchWithRule(r);
    QCOMPARE(WatchRuleEvaluator::ruleAddress(w, QStringLiteral("0x0087")), 0x87);
    QCOMPARE(WatchRuleEvaluator::ruleAddress(w, QStringLiteral("135")), 0x87);
    QCOMPARE(WatchRuleEvaluator::ruleAddress(w, QStringLiteral("counts")), 0x86);
    QCOMPARE(WatchRuleEvaluator::ruleAddress(w, QStringLiteral("0x0088")), -1);
    QCOMPARE(WatchRuleEvaluator::ruleAddress(w, QStringLiteral("volts")), -1);
    WatchRuleEvaluator e(w);
    const QList<WatchRuleEvent> fired = e.evaluate(values(1));
    QCOMPARE(fired.size(), 1);
    QCOMPARE(fired.first().point, QStringLiteral("0x0087"));
    QCOMPARE(fired.first().message, QStringLiteral("0x0087 equal to 0"));
}

// An unnamed address with hex letters is named as the watch's lines and CSV columns name it,
// "0x01AF" (failed before: "0x01af"), whatever case the rule was written in.
void TestWatchRules::addressNamedInUpperCase()
{
    WatchRule r;
    r.point = QStringLiteral("0x01af");
    r.condition = WatchRule::Condition::Above;
    r.high = 5;
    WatchDefinition w;
    w.name = QStringLiteral("drive");
    w.address = 0x01A0;
    w.quantity = 16;
    w.rules.append(r);
    WatchPointValue v;
    v.address = 0x01AF;
    v.value = 9;
    v.raw = 9;
    WatchRuleEvaluator e(w);
    const QList<WatchRuleEvent> fired = e.evaluate({v});
    QCOMPARE(fired.size(), 1);
    QCOMPARE(fired.first().point, QStringLiteral("0x01AF"));
    QCOMPARE(fired.first().message, QStringLiteral("0x01AF above 5"));
    QVERIFY(WatchCsvLog::columns(w).contains(fired.first().point));
}

void TestWatchRules::messages()
{
    WatchRule r;
    r.condition = WatchRule::Condition::Outside;
    r.low = 900;
    r.high = 1100;
    r.forPolls = 3;
    QCOMPARE(WatchRuleEvaluator::message(r, QStringLiteral("pressure"), QStringLiteral("hPa")),
             QStringLiteral("pressure outside 900 hPa to 1100 hPa for 3 polls"));
    r.condition = WatchRule::Condition::Bits;
    r.low = 8;
    r.forPolls = 1;
    QCOMPARE(WatchRuleEvaluator::message(r, QStringLiteral("status"), {}), QStringLiteral("status has bits 0x8 set"));
    r.message = QStringLiteral("door open");
    QCOMPARE(WatchRuleEvaluator::message(r, QStringLiteral("status"), {}), QStringLiteral("door open"));
}

QTEST_GUILESS_MAIN(TestWatchRules)
#include "tst_watchrules.moc"
