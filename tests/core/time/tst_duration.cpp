// The one grammar of durations (time/duration.h) that the command line, target URLs, poll
// bounds and plan waits share: every spelling it takes and every refusal, with its words.
#include "time/duration.h"

#include <QtTest/QtTest>

using namespace mbscope;

class tst_Duration : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void accepted_data();
    void accepted();
    void refused_data();
    void refused();
    void lists();
    void formatted_data();
    void formatted();
};

void tst_Duration::accepted_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<qint64>("bareUnit");
    QTest::addColumn<qint64>("ns");
    const qint64 ms = Duration::Millisecond;
    auto row = [](const char *name, const char *text, qint64 bare, qint64 ns) {
        QTest::newRow(name) << QString::fromUtf8(text) << bare << ns;
    };
    row("zero", "0", ms, 0);
    row("bare milliseconds", "100", ms, 100'000'000);
    row("ms", "100ms", ms, 100'000'000);
    row("space before the unit", "100 ms", ms, 100'000'000);
    row("decimal seconds, padded", " 1.5s ", ms, 1'500'000'000);
    row("us", "250us", ms, 250'000);
    row("micro sign", "250\u00b5s", ms, 250'000);
    row("upper case", "250US", ms, 250'000);
    row("ns", "40ns", ms, 40);
    row("half a millisecond", "0.5ms", ms, 500'000);
    row("min", "2min", ms, 120'000'000'000);
    row("m", "2m", ms, 120'000'000'000);
    row("h", "1h", ms, 3'600'000'000'000);
    row("leading point", ".5s", ms, 500'000'000);
    row("bare microseconds", "1500", Duration::Microsecond, 1'500'000);
    row("unit required and given", "20 ms", Duration::UnitRequired, 20'000'000);
}

void tst_Duration::accepted()
{
    QFETCH(QString, text);
    QFETCH(qint64, bareUnit);
    QFETCH(qint64, ns);
    const DurationResult d = parseDuration(text, bareUnit);
    QVERIFY2(d.ok(), qPrintable(d.error));
    QCOMPARE(d.ns, ns);
    QVERIFY(d.error.isEmpty());
}

void tst_Duration::refused_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<qint64>("bareUnit");
    QTest::addColumn<int>("problem");
    QTest::addColumn<QString>("error");
    const qint64 ms = Duration::Millisecond;
    using P = DurationResult::Problem;
    auto row = [](const char *name, const char *text, qint64 bare, P problem, const char *error) {
        QTest::newRow(name) << QString::fromUtf8(text) << bare << int(problem) << QString::fromUtf8(error);
    };
    row("empty", "", ms, P::Syntax,
        "'' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, 1.5s, 2min; "
        "a bare number is milliseconds)");
    row("word", "soon", ms, P::Syntax,
        "'soon' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, 1.5s, "
        "2min; a bare number is milliseconds)");
    row("unit alone", "ms", ms, P::Syntax,
        "'ms' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, 1.5s, "
        "2min; a bare number is milliseconds)");
    row("two points", "1.2.3s", ms, P::Syntax,
        "'1.2.3s' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, "
        "1.5s, 2min; a bare number is milliseconds)");
    row("exponent", "1e3ms", ms, P::Syntax,
        "'1e3ms' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, "
        "1.5s, 2min; a bare number is milliseconds)");
    row("plus sign", "+5s", ms, P::Syntax,
        "'+5s' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, 1.5s, "
        "2min; a bare number is milliseconds)");
    row("unknown unit", "10 parsecs", ms, P::Syntax,
        "'10 parsecs' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. "
        "100ms, 1.5s, 2min; a bare number is milliseconds)");
    row("negative", "-1ms", ms, P::Negative, "'-1ms' is a negative duration: a duration is 0 or more");
    row("beyond a year", "367d", ms, P::Syntax,
        "'367d' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, "
        "1.5s, 2min; a bare number is milliseconds)");
    row("too long", "9000h", ms, P::TooLong, "'9000h' is too long: at most a year");
    row("overflowing", "999999999999999999999s", ms, P::TooLong, "'999999999999999999999s' is too long: at most a year");
    row("unit required", "20", Duration::UnitRequired, P::UnitMissing,
        "'20' has no unit: expected ns, us, ms, s, min or h after the number");
    row("bare microseconds said", "x", Duration::Microsecond, P::Syntax,
        "'x' is not a duration: expected a number with an optional unit ns, us, ms, s, min or h (e.g. 100ms, 1.5s, "
        "2min; a bare number is microseconds)");
}

void tst_Duration::refused()
{
    QFETCH(QString, text);
    QFETCH(qint64, bareUnit);
    QFETCH(int, problem);
    QFETCH(QString, error);
    const DurationResult d = parseDuration(text, bareUnit);
    QVERIFY(!d.ok());
    QCOMPARE(int(d.problem), problem);
    QCOMPARE(d.error, error);
}

void tst_Duration::lists()
{
    const DurationListResult good = parseDurationList(u"100,200ms, 1s");
    QVERIFY(good.ok);
    QCOMPARE(good.ns, (QList<qint64>{100'000'000, 200'000'000, 1'000'000'000}));
    const DurationListResult empty = parseDurationList(u"100,,300");
    QVERIFY(!empty.ok);
    QCOMPARE(empty.error, QStringLiteral("item 2 of '100,,300' is empty: expected durations separated by commas (e.g. 100,200,300ms)"));
    const DurationListResult bad = parseDurationList(u"100,-5ms");
    QVERIFY(!bad.ok);
    QVERIFY(bad.ns.isEmpty());
    QCOMPARE(bad.error, QStringLiteral("item 2: '-5ms' is a negative duration: a duration is 0 or more"));
}

void tst_Duration::formatted_data()
{
    QTest::addColumn<qint64>("ns");
    QTest::addColumn<QString>("text");
    QTest::newRow("zero") << qint64(0) << QStringLiteral("0 ms");
    QTest::newRow("ns") << qint64(999) << QStringLiteral("999 ns");
    QTest::newRow("us") << qint64(250'000) << QStringLiteral("250 µs");
    QTest::newRow("ms") << qint64(100'000'000) << QStringLiteral("100 ms");
    QTest::newRow("s") << qint64(1'500'000'000) << QStringLiteral("1.5 s");
    QTest::newRow("min") << qint64(120'000'000'000) << QStringLiteral("2 min");
    QTest::newRow("h") << qint64(5'400'000'000'000) << QStringLiteral("1.5 h");
}

void tst_Duration::formatted()
{
    QFETCH(qint64, ns);
    QFETCH(QString, text);
    QCOMPARE(formatDuration(ns), text);
    // What formatDuration writes, parseDuration reads back.
    const DurationResult back = parseDuration(text);
    QVERIFY2(back.ok(), qPrintable(back.error));
    QCOMPARE(back.ns, ns);
}

QTEST_APPLESS_MAIN(tst_Duration)
#include "tst_duration.moc"
