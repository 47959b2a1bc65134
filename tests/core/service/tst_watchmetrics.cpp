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

QTEST_GUILESS_MAIN(TestWatchMetrics)
#include "tst_watchmetrics.moc"
