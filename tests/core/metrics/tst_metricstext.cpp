// The metrics registry and its text exposition: exact text in both formats (the text format 0.0.4
// and OpenMetrics 1.0.0, as their specifications write them), escaping, histogram buckets, the
// naming rules, and Debian's `promtool check metrics` (Prometheus's own linter) over what the
// registry writes, with a bad exposition beside it to show the linter does reject.
#include "metrics/metricname.h"
#include "metrics/metricsregistry.h"
#include "metrics/metricstext.h"
#include "metrics/processmetrics.h"

#include <QtCore/QProcess>
#include <QtCore/QStandardPaths>
#include <QtTest/QtTest>

#include <limits>

using namespace mbscope;

namespace {

struct Promtool {
    bool ran = false;
    int exitCode = -1;
    QByteArray output;
};

Promtool promtoolCheck(const QByteArray &text)
{
    Promtool result;
    const QString promtool = QStandardPaths::findExecutable(QStringLiteral("promtool"));
    if (promtool.isEmpty())
        return result;
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(promtool, {QStringLiteral("check"), QStringLiteral("metrics")});
    if (!p.waitForStarted(10000))
        return result;
    p.write(text);
    p.closeWriteChannel();
    if (!p.waitForFinished(30000))
        return result;
    result.ran = true;
    result.exitCode = p.exitCode();
    result.output = p.readAll();
    return result;
}

// A registry shaped like the watch service's: values with awkward names, counters, a histogram.
void fillLikeTheService(MetricsRegistry &r)
{
    MetricFamily &value = r.gauge(QStringLiteral("mbscope_watch_value"), QStringLiteral("A watched point's value (scaled, in its engineering unit)."),
                                  {QStringLiteral("watch"), QStringLiteral("name"), QStringLiteral("engineering_unit")});
    value.set({QStringLiteral("gamma \"main\""), QStringLiteral("counts\\s"), QStringLiteral("cps")}, 1234.5);
    value.set({QStringLiteral("gamma \"main\""), QStringLiteral("line\nbreak"), QStringLiteral("°C")}, -0.25);
    MetricFamily &polls = r.counter(QStringLiteral("mbscope_watch_polls_total"), QStringLiteral("Polls sent."), {QStringLiteral("watch")});
    polls.add({QStringLiteral("a")}, 3);
    polls.touch({QStringLiteral("b")});
    MetricFamily &latency = r.histogram(QStringLiteral("mbscope_watch_latency_seconds"), QStringLiteral("Request to answer."),
                                        {QStringLiteral("watch")}, {0.001, 0.01, 0.1, 1});
    latency.observe({QStringLiteral("a")}, 0.0005);
    latency.observe({QStringLiteral("a")}, 0.05);
    latency.observe({QStringLiteral("a")}, 7);
    r.gauge(QStringLiteral("mbscope_link_up"), QStringLiteral("1 while the link is connected."), {QStringLiteral("target")})
        .set({QStringLiteral("tcp://127.0.0.1:5020")}, 1);
}

} // namespace

class TestMetricsText : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void prometheusText();
    void openMetricsText();
    void histogramBuckets();
    void numbers_data();
    void numbers();
    void labelEscaping();
    void names_data();
    void names();
    void registryRecordsProblems();
    void seriesComeAndGo();
    void negotiation();
    void processMetrics();
    void promtoolAccepts();
    void promtoolRejectsABadExposition();
};

void TestMetricsText::prometheusText()
{
    MetricsRegistry r;
    r.counter(QStringLiteral("mbscope_watch_polls_total"), QStringLiteral("Polls \"sent\"\\now."), {QStringLiteral("watch")})
        .add({QStringLiteral("w1")}, 2);
    r.gauge(QStringLiteral("mbscope_build_info"), QStringLiteral("Version."), {QStringLiteral("version")}).set({QStringLiteral("0.1.0")}, 1);
    QCOMPARE(MetricsText::write(r, MetricsText::Format::Prometheus),
             QByteArray("# HELP mbscope_watch_polls_total Polls \"sent\"\\\\now.\n"
                        "# TYPE mbscope_watch_polls_total counter\n"
                        "mbscope_watch_polls_total{watch=\"w1\"} 2\n"
                        "# HELP mbscope_build_info Version.\n"
                        "# TYPE mbscope_build_info gauge\n"
                        "mbscope_build_info{version=\"0.1.0\"} 1\n"));
}

void TestMetricsText::openMetricsText()
{
    MetricsRegistry r;
    r.counter(QStringLiteral("mbscope_watch_polls_total"), QStringLiteral("Polls \"sent\"."), {QStringLiteral("watch")})
        .add({QStringLiteral("w1")}, 2);
    r.gauge(QStringLiteral("mbscope_up"), QStringLiteral("Up."));
    r.gauge(QStringLiteral("mbscope_up"), QStringLiteral("Up.")).set({}, 0);
    // OpenMetrics 1.0.0: the counter's family has no _total, '"' in help is escaped, # EOF ends it.
    QCOMPARE(MetricsText::write(r, MetricsText::Format::OpenMetrics),
             QByteArray("# HELP mbscope_watch_polls Polls \\\"sent\\\".\n"
                        "# TYPE mbscope_watch_polls counter\n"
                        "mbscope_watch_polls_total{watch=\"w1\"} 2\n"
                        "# HELP mbscope_up Up.\n"
                        "# TYPE mbscope_up gauge\n"
                        "mbscope_up 0\n"
                        "# EOF\n"));
}

void TestMetricsText::histogramBuckets()
{
    MetricsRegistry r;
    MetricFamily &h = r.histogram(QStringLiteral("t_seconds"), QStringLiteral("h"), {QStringLiteral("w")}, {0.5, 1, 2.5});
    // le is "less than or equal": 1 belongs to the bucket le="1.0".
    for (const double v : {0.1, 0.5, 1.0, 1.0001, 3.0})
        h.observe({QStringLiteral("x")}, v);
    QCOMPARE(MetricsText::write(r, MetricsText::Format::Prometheus),
             QByteArray("# HELP t_seconds h\n# TYPE t_seconds histogram\n"
                        "t_seconds_bucket{w=\"x\",le=\"0.5\"} 2\n"
                        "t_seconds_bucket{w=\"x\",le=\"1.0\"} 3\n"
                        "t_seconds_bucket{w=\"x\",le=\"2.5\"} 4\n"
                        "t_seconds_bucket{w=\"x\",le=\"+Inf\"} 5\n"
                        "t_seconds_sum{w=\"x\"} 5.6001\n"
                        "t_seconds_count{w=\"x\"} 5\n"));
    const MetricSeries *s = h.find({QStringLiteral("x")});
    QVERIFY(s);
    QCOMPARE(s->count, quint64(5));
}

void TestMetricsText::numbers_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QByteArray>("text");
    QTest::newRow("zero") << 0.0 << QByteArray("0");
    QTest::newRow("whole") << 1234.0 << QByteArray("1234");
    QTest::newRow("fraction") << 0.1 << QByteArray("0.1");
    QTest::newRow("negative") << -2.5 << QByteArray("-2.5");
    QTest::newRow("tiny") << 1e-9 << QByteArray("1e-09");
    QTest::newRow("small") << 0.0005 << QByteArray("0.0005");
    QTest::newRow("timestamp") << 1795673852.345 << QByteArray("1.795673852345e+09"); // as Go's client writes it
    QTest::newRow("huge") << 1.5e300 << QByteArray("1.5e+300");
    QTest::newRow("+Inf") << std::numeric_limits<double>::infinity() << QByteArray("+Inf");
    QTest::newRow("-Inf") << -std::numeric_limits<double>::infinity() << QByteArray("-Inf");
    QTest::newRow("NaN") << std::numeric_limits<double>::quiet_NaN() << QByteArray("NaN");
}

void TestMetricsText::numbers()
{
    QFETCH(double, value);
    QFETCH(QByteArray, text);
    QCOMPARE(MetricsText::number(value), text);
}

void TestMetricsText::labelEscaping()
{
    QCOMPARE(MetricsText::escapeLabelValue(QStringLiteral("a\"b\\c\nd")), QByteArray("a\\\"b\\\\c\\nd"));
    QCOMPARE(MetricsText::escapeLabelValue(QStringLiteral("°C")), QStringLiteral("°C").toUtf8());
}

void TestMetricsText::names_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("counter");
    QTest::addColumn<bool>("good");
    QTest::newRow("gauge") << QStringLiteral("mbscope_link_up") << false << true;
    QTest::newRow("colon") << QStringLiteral("job:mbscope_up:sum") << false << true;
    QTest::newRow("counter") << QStringLiteral("mbscope_watch_polls_total") << true << true;
    QTest::newRow("counter without _total") << QStringLiteral("mbscope_watch_polls") << true << false;
    QTest::newRow("gauge with _total") << QStringLiteral("mbscope_polls_total") << false << false;
    QTest::newRow("digit first") << QStringLiteral("1up") << false << false;
    QTest::newRow("dash") << QStringLiteral("mbscope-up") << false << false;
    QTest::newRow("empty") << QString() << false << false;
}

void TestMetricsText::names()
{
    QFETCH(QString, name);
    QFETCH(bool, counter);
    QFETCH(bool, good);
    const QString problem = MetricName::problem(name, counter);
    QCOMPARE(problem.isEmpty(), good);
    QVERIFY(MetricName::labelProblem(QStringLiteral("target")).isEmpty());
    QVERIFY(!MetricName::labelProblem(QStringLiteral("__name__")).isEmpty());
    QVERIFY(!MetricName::labelProblem(QStringLiteral("le")).isEmpty());
    QVERIFY(!MetricName::labelProblem(QStringLiteral("a:b")).isEmpty());
}

void TestMetricsText::registryRecordsProblems()
{
    MetricsRegistry r;
    r.counter(QStringLiteral("mbscope_polls"), QStringLiteral("x"));
    r.gauge(QStringLiteral("mbscope_ok"), QString(), {QStringLiteral("bad-label")});
    r.histogram(QStringLiteral("mbscope_h_seconds"), QStringLiteral("h"), {}, {1, 0.5});
    r.counter(QStringLiteral("mbscope_ok_total"), QStringLiteral("x"));
    r.gauge(QStringLiteral("mbscope_ok_total"), QStringLiteral("x"));
    QCOMPARE(r.problems().size(), 5); // no _total, no help, a bad label, bounds, a type changed
    QVERIFY2(r.problems().at(0).contains(QLatin1String("_total")), qPrintable(r.problems().join(QLatin1Char('\n'))));
}

void TestMetricsText::seriesComeAndGo()
{
    MetricsRegistry r;
    MetricFamily &g = r.gauge(QStringLiteral("g"), QStringLiteral("g"), {QStringLiteral("a"), QStringLiteral("b")});
    g.set({QStringLiteral("1")}, 5); // a missing label value is empty
    QVERIFY(g.find({QStringLiteral("1"), QString()}));
    g.remove({QStringLiteral("1"), QString()});
    QVERIFY(g.series().empty());
    g.add({QStringLiteral("x"), QStringLiteral("y")}, 2);
    r.clearSeries();
    QVERIFY(g.series().empty());
    QCOMPARE(&r.gauge(QStringLiteral("g"), QStringLiteral("g"), {QStringLiteral("a"), QStringLiteral("b")}), &g);
}

void TestMetricsText::negotiation()
{
    // What Prometheus 2.42 sends.
    QCOMPARE(MetricsText::negotiate("application/openmetrics-text;version=1.0.0,application/openmetrics-text;version=0.0.1;q=0.75,"
                                    "text/plain;version=0.0.4;q=0.5,*/*;q=0.1"),
             MetricsText::Format::OpenMetrics);
    QCOMPARE(MetricsText::negotiate("*/*"), MetricsText::Format::Prometheus);
    QCOMPARE(MetricsText::negotiate(""), MetricsText::Format::Prometheus);
    QVERIFY(MetricsText::contentType(MetricsText::Format::Prometheus).startsWith("text/plain; version=0.0.4"));
}

void TestMetricsText::processMetrics()
{
#ifndef Q_OS_LINUX
    QSKIP("process metrics are read from /proc");
#endif
    MetricsRegistry r;
    ProcessMetrics process(r);
    process.update();
    const MetricSeries *rss = r.find(QStringLiteral("process_resident_memory_bytes"))->find({});
    QVERIFY(rss);
    QVERIFY2(rss->value > 1024 * 1024, QByteArray::number(rss->value));
    const MetricSeries *start = r.find(QStringLiteral("process_start_time_seconds"))->find({});
    QVERIFY(start);
    const double now = double(QDateTime::currentSecsSinceEpoch());
    QVERIFY2(start->value > now - 3600 && start->value <= now + 1, QByteArray::number(start->value, 'f', 0));
    QVERIFY(r.find(QStringLiteral("process_open_fds"))->find({})->value >= 3);
    QVERIFY(r.problems().isEmpty());
}

void TestMetricsText::promtoolAccepts()
{
    MetricsRegistry r;
    fillLikeTheService(r);
    ProcessMetrics(r).update();
    QVERIFY2(r.problems().isEmpty(), qPrintable(r.problems().join(QLatin1Char('\n'))));
    const QByteArray text = MetricsText::write(r, MetricsText::Format::Prometheus);
    const Promtool check = promtoolCheck(text);
    if (!check.ran)
        QSKIP("promtool is not installed (Debian: prometheus)");
    QVERIFY2(check.exitCode == 0 && check.output.trimmed().isEmpty(), check.output + "\n---\n" + text);
}

void TestMetricsText::promtoolRejectsABadExposition()
{
    // The linter is not a rubber stamp: a counter without _total and a broken label are refused.
    MetricsRegistry r;
    r.counter(QStringLiteral("mbscope_polls"), QStringLiteral("bad"), {QStringLiteral("watch")}).add({QStringLiteral("a")});
    const Promtool lint = promtoolCheck(MetricsText::write(r, MetricsText::Format::Prometheus));
    if (!lint.ran)
        QSKIP("promtool is not installed (Debian: prometheus)");
    QVERIFY2(lint.exitCode != 0 && lint.output.contains("_total"), lint.output);
    const Promtool parse = promtoolCheck("# TYPE x gauge\nx{a=\"unterminated} 1\n");
    QVERIFY2(parse.exitCode != 0, parse.output);
}

QTEST_GUILESS_MAIN(TestMetricsText)
#include "tst_metricstext.moc"
