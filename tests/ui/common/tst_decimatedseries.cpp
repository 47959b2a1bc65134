// Issue 31: the latency-over-time plot's points stay within a fixed budget however long the poll,
// and a spike stays visible where it happened.
#include "common/decimatedseries.h"

#include <QtTest/QtTest>

#include <algorithm>

using namespace mbscope;

class TestDecimatedSeries : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void keepsEveryPointWithinBudget()
    {
        DecimatedSeries series(100);
        for (int i = 0; i < 100; ++i)
            series.add(i, i % 7);
        QCOMPARE(series.size(), 100);
        QCOMPARE(series.bucketWidth(), 0.0);
        QCOMPARE(series.keys().size(), 100);
        QCOMPARE(series.values().at(13), 13.0 - 7.0);
    }

    void boundedAndSpikesKept()
    {
        DecimatedSeries series(1000);
        for (int i = 0; i < 1'000'000; ++i) {
            const double value = i == 777'777 ? 500.0 : (i == 123'456 ? -1.0 : 5.0 + (i % 3));
            series.add(double(i) / 1000.0, value);
            QVERIFY(series.size() <= series.budget());
        }
        QCOMPARE(series.added(), 1'000'000);
        QVERIFY(series.bucketWidth() > 0);
        const QList<double> keys = series.keys();
        const QList<double> values = series.values();
        QCOMPARE(keys.size(), series.size());
        QCOMPARE(values.size(), series.size());
        QVERIFY(std::is_sorted(keys.begin(), keys.end()));
        // The spike and the dip are points, at their own time.
        const qsizetype spike = values.indexOf(500.0);
        QVERIFY(spike >= 0);
        QCOMPARE(keys.at(spike), 777.777);
        const qsizetype dip = values.indexOf(-1.0);
        QVERIFY(dip >= 0);
        QCOMPARE(keys.at(dip), 123.456);
        // The first and the last stretch of time are still there.
        QVERIFY(keys.first() < 1.0);
        QVERIFY(keys.last() > 999.0 - series.bucketWidth());
        series.clear();
        QCOMPARE(series.size(), 0);
        QCOMPARE(series.added(), 0);
    }
};

QTEST_GUILESS_MAIN(TestDecimatedSeries)
#include "tst_decimatedseries.moc"
