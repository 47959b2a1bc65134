// WatchMetrics::reset, as SIGHUP's reload of `mbscope watch` uses it: the series of the watches
// that went (every family, rule states and exceptions by code included) are gone, the new
// watches start at zero, and the version's series stays.
#include "service/watchmetrics.h"

#include <QtTest/QtTest>

using namespace mbscope;

namespace {

SessionWatches session(const QString &name)
{
    SessionWatches s;
    WatchDefinition w;
    w.name = name;
    w.target = QStringLiteral("tcp://127.0.0.1:5020");
    w.address = 0;
    w.quantity = 2;
    s.watches.append(w);
    return s;
}

// The series of every family whose label values include value.
int seriesNaming(const MetricsRegistry &registry, const QString &value)
{
    int n = 0;
    for (const MetricFamily *family : registry.families()) {
        for (const auto &[labels, series] : family->series())
            n += labels.contains(value) ? 1 : 0;
    }
    return n;
}

} // namespace

class TestWatchMetrics : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void resetStartsOver();
    void valuesFollowTheSamples();
};

void TestWatchMetrics::resetStartsOver()
{
    WatchMetrics metrics(QStringLiteral("9.9.9"));
    metrics.reset(session(QStringLiteral("old")));
    WatchCounters c;
    c.watch = 0;
    c.watchName = QStringLiteral("old");
    c.polls = 5;
    c.exceptions = 1;
    c.exceptionsByCode[2] = 1;
    metrics.setCounters({c});
    WatchRuleEvent e;
    e.watch = 0;
    e.watchName = QStringLiteral("old");
    e.rule = 0;
    e.point = QStringLiteral("0x0000");
    metrics.addRuleEvent(e);
    QVERIFY(seriesNaming(metrics.registry(), QStringLiteral("old")) > 10);
    QVERIFY(metrics.registry().find(QStringLiteral("mbscope_watch_rule_active"))->find({QStringLiteral("old"), QStringLiteral("0"),
                                                                                       QStringLiteral("0x0000"), QStringLiteral("warning")}));

    metrics.reset(session(QStringLiteral("new")));
    QCOMPARE(seriesNaming(metrics.registry(), QStringLiteral("old")), 0);
    QVERIFY(metrics.registry().find(QStringLiteral("mbscope_watch_rule_active"))->series().empty());
    QVERIFY(metrics.registry().find(QStringLiteral("mbscope_watch_exceptions_total"))->series().empty());
    const MetricSeries *polls = metrics.registry().find(QStringLiteral("mbscope_watch_polls_total"))
                                    ->find({QStringLiteral("new"), QStringLiteral("tcp://127.0.0.1:5020")});
    QVERIFY(polls);
    QCOMPARE(polls->value, 0.0);
    QVERIFY(metrics.registry().find(QStringLiteral("mbscope_build_info"))->find({QStringLiteral("9.9.9")}));
}

namespace {

WatchSample okSample(double first, const QString &name, quint32 field)
{
    WatchSample s;
    s.watch = 0;
    s.status = WatchSample::Status::Ok;
    s.latencyNs = 2'000'000;
    WatchPointValue a;
    a.address = 0;
    a.name = name;
    a.unit = QStringLiteral("V");
    a.value = first;
    a.bitFields.append(WatchBitFieldValue{QStringLiteral("alarm"), field, {}});
    WatchPointValue b;
    b.address = 1;
    b.value = 7;
    s.values = {a, b};
    return s;
}

const MetricSeries *valueOf(const WatchMetrics &m, const QString &address, const QString &name, const QString &unit)
{
    return m.registry().find(QStringLiteral("mbscope_watch_value"))
        ->find({QStringLiteral("w"), QStringLiteral("tcp://127.0.0.1:5020"), QStringLiteral("1"), QStringLiteral("holding_registers"),
                address, name, unit});
}

} // namespace

// The service keeps each value's series from poll to poll (issue 32): what it shows must still
// follow every sample: new values, a failed poll's gap, values back after it, a renamed point.
void TestWatchMetrics::valuesFollowTheSamples()
{
    WatchMetrics metrics(QStringLiteral("9.9.9"));
    metrics.reset(session(QStringLiteral("w")));
    metrics.addSamples({okSample(230.5, QStringLiteral("voltage"), 1)});
    metrics.addSamples({okSample(231.5, QStringLiteral("voltage"), 0)});
    QCOMPARE(valueOf(metrics, QStringLiteral("0"), QStringLiteral("voltage"), QStringLiteral("V"))->value, 231.5);
    QCOMPARE(valueOf(metrics, QStringLiteral("1"), QString(), QString())->value, 7.0);
    const MetricFamily *fields = metrics.registry().find(QStringLiteral("mbscope_watch_bit_field_value"));
    QCOMPARE(fields->series().size(), std::size_t(1));
    QCOMPARE(fields->series().begin()->second.value, 0.0);
    const MetricFamily *latency = metrics.registry().find(QStringLiteral("mbscope_watch_latency_seconds"));
    QCOMPARE(latency->find({QStringLiteral("w"), QStringLiteral("tcp://127.0.0.1:5020")})->count, quint64(2));

    WatchSample failed;
    failed.watch = 0;
    failed.status = WatchSample::Status::Timeout;
    metrics.addSamples({failed});
    QVERIFY(!valueOf(metrics, QStringLiteral("0"), QStringLiteral("voltage"), QStringLiteral("V")));
    QVERIFY(fields->series().empty());
    QCOMPARE(metrics.registry().find(QStringLiteral("mbscope_watch_up"))->series().begin()->second.value, 0.0);

    metrics.addSamples({okSample(229.0, QStringLiteral("voltage"), 1)});
    QCOMPARE(valueOf(metrics, QStringLiteral("0"), QStringLiteral("voltage"), QStringLiteral("V"))->value, 229.0);
    QCOMPARE(fields->series().begin()->second.value, 1.0);
    QCOMPARE(metrics.registry().find(QStringLiteral("mbscope_watch_up"))->series().begin()->second.value, 1.0);

    // A point named otherwise (a reloaded definition) is a series of its own.
    metrics.addSamples({okSample(228.0, QStringLiteral("mains"), 1)});
    QCOMPARE(valueOf(metrics, QStringLiteral("0"), QStringLiteral("mains"), QStringLiteral("V"))->value, 228.0);
    QCOMPARE(valueOf(metrics, QStringLiteral("0"), QStringLiteral("voltage"), QStringLiteral("V"))->value, 229.0);
}

QTEST_GUILESS_MAIN(TestWatchMetrics)
#include "tst_watchmetrics.moc"
