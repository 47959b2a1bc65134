// Poll bounds as people write them ("p95 < 20 ms", "timeouts == 0"): what is read, what is
// refused and why, and how a bound is judged against statistics.

#include "session/pollbound.h"

#include "exchange/statistics.h"

#include <QtTest/QtTest>

using namespace mbscope;

class TestPollBound : public QObject
{
    Q_OBJECT

private slots:
    void parses_data();
    void parses();
    void refuses_data();
    void refuses();
    void judges_data();
    void judges();
    void noLatencyWithoutAnswers();
};

void TestPollBound::parses_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("figure");
    QTest::addColumn<int>("op");
    QTest::addColumn<double>("value");

    QTest::newRow("p95 < 20 ms") << "p95 < 20 ms" << "p95" << int(PollBound::Op::Less) << 20e6;
    QTest::newRow("no spaces") << "p95<20ms" << "p95" << int(PollBound::Op::Less) << 20e6;
    QTest::newRow("timeouts == 0") << "timeouts == 0" << "timeouts" << int(PollBound::Op::Equal) << 0.0;
    QTest::newRow("p99.9 <= 1.5 s") << "  p99.9 <= 1.5 s " << "p99.9" << int(PollBound::Op::LessEqual) << 1.5e9;
    QTest::newRow("mean > 250 us") << "mean > 250 us" << "mean" << int(PollBound::Op::Greater) << 250e3;
    QTest::newRow("micro sign") << "max < 900 \u00b5s" << "max" << int(PollBound::Op::Less) << 900e3;
    QTest::newRow("upper case") << "P50 >= 1 MS" << "p50" << int(PollBound::Op::GreaterEqual) << 1e6;
    QTest::newRow("error_rate %") << "error_rate <= 1 %" << "error_rate" << int(PollBound::Op::LessEqual) << 1.0;
    QTest::newRow("error_rate bare") << "error_rate != 0" << "error_rate" << int(PollBound::Op::NotEqual) << 0.0;
    QTest::newRow("ok >= 100") << "ok >= 100" << "ok" << int(PollBound::Op::GreaterEqual) << 100.0;
    QTest::newRow("stddev ns") << "stddev < 100000 ns" << "stddev" << int(PollBound::Op::Less) << 1e5;
}

void TestPollBound::parses()
{
    QFETCH(QString, text);
    QFETCH(QString, figure);
    QFETCH(int, op);
    QFETCH(double, value);
    const PollBound::Parsed p = PollBound::parse(text);
    QVERIFY2(p.bound, qPrintable(p.error));
    QCOMPARE(p.bound->figure, figure);
    QCOMPARE(int(p.bound->op), op);
    QCOMPARE(p.bound->value, value);
    QCOMPARE(p.bound->text, text.trimmed());
}

void TestPollBound::refuses_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("error");

    QTest::newRow("no unit") << "p95 < 20" << "'p95 < 20': p95 is a latency: give a unit after 20 (ns, us, ms, s, min or h)";
    QTest::newRow("bad unit") << "p95 < 20 parsecs" << "'p95 < 20 parsecs': 'parsecs' is not a unit of time: expected ns, us, ms, s, min or h";
    QTest::newRow("unknown figure") << "p9x < 2 ms" << "'p9x < 2 ms': 'p9x' is not a percentile: expected p0 to p100, such as p95 or p99.9";
    QTest::newRow("typo") << "timeout == 0"
                          << "'timeout == 0': unknown figure 'timeout': expected one of count, ok, failed, exceptions, timeouts, "
                             "crc_errors, malformed, unexpected, late, link_errors, broadcasts, error_rate, min, max, mean, "
                             "median, stddev, pNN (p50, p95, p99.9)";
    QTest::newRow("single =") << "timeouts = 0" << "'timeouts = 0': expected a comparison (<, <=, >, >=, ==, !=) after 'timeouts' at column 10";
    QTest::newRow("<<") << "p95 << 20 ms" << "'p95 << 20 ms': expected a comparison (<, <=, >, >=, ==, !=) after 'p95' at column 6";
    QTest::newRow("no number") << "p95 < ms" << "'p95 < ms': expected a number at column 7";
    QTest::newRow("count with unit") << "timeouts == 0 ms" << "'timeouts == 0 ms': timeouts is a count: 'ms' after 0 is not expected";
    QTest::newRow("fractional count") << "ok > 1.5" << "'ok > 1.5': ok is a count: 1.5 is not a whole number";
    QTest::newRow("rate beyond 100") << "error_rate < 150 %" << "'error_rate < 150 %': error_rate is a percentage: 150 is beyond 100";
    QTest::newRow("percentile beyond 100") << "p101 < 1 ms" << "'p101 < 1 ms': 'p101' is not a percentile: expected p0 to p100, such as p95 or p99.9";
    QTest::newRow("empty") << "  " << "an empty bound: expected FIGURE OP VALUE [UNIT], such as \"p95 < 20 ms\"";
}

void TestPollBound::refuses()
{
    QFETCH(QString, text);
    QFETCH(QString, error);
    const PollBound::Parsed p = PollBound::parse(text);
    QVERIFY(!p.bound);
    QCOMPARE(p.error, error);
}

void TestPollBound::judges_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("holds");
    QTest::addColumn<QString>("described");

    // Statistics of four answers at 1, 2, 3 and 10 ms and one timeout.
    QTest::newRow("p50 is 2 ms") << "p50 <= 2 ms" << true << "p50 is 2.000 ms";
    QTest::newRow("p95 is 10 ms") << "p95 < 10 ms" << false << "p95 is 10.000 ms";
    QTest::newRow("max") << "max == 10 ms" << true << "max is 10.000 ms";
    QTest::newRow("mean") << "mean > 3.9 ms" << true << "mean is 4.000 ms";
    QTest::newRow("timeouts") << "timeouts == 0" << false << "timeouts is 1";
    QTest::newRow("count") << "count == 5" << true << "count is 5";
    QTest::newRow("error_rate") << "error_rate <= 20 %" << true << "error_rate is 20.00 %";
    QTest::newRow("error_rate strict") << "error_rate < 20" << false << "error_rate is 20.00 %";
}

void TestPollBound::judges()
{
    QFETCH(QString, text);
    QFETCH(bool, holds);
    QFETCH(QString, described);
    Statistics stats;
    for (qint64 ms : {1, 2, 3, 10}) {
        Transaction t;
        t.status = TransactionStatus::Ok;
        t.sentNs = 1'000'000'000;
        t.doneNs = t.sentNs + ms * 1'000'000;
        stats.add(t);
    }
    Transaction timeout;
    timeout.status = TransactionStatus::Timeout;
    stats.add(timeout);

    const PollBound::Parsed p = PollBound::parse(text);
    QVERIFY2(p.bound, qPrintable(p.error));
    const std::optional<double> measured = p.bound->measure(stats);
    QVERIFY(measured);
    QCOMPARE(p.bound->holds(*measured), holds);
    QCOMPARE(p.bound->describe(stats), described);
}

void TestPollBound::noLatencyWithoutAnswers()
{
    Statistics stats;
    Transaction timeout;
    timeout.status = TransactionStatus::Timeout;
    stats.add(timeout);
    const PollBound bound = *PollBound::parse(u"p95 < 20 ms").bound;
    QVERIFY(!bound.measure(stats));
    QCOMPARE(bound.describe(stats), QStringLiteral("p95: no request was answered, so there is no latency"));
}

QTEST_GUILESS_MAIN(TestPollBound)
#include "tst_pollbound.moc"
