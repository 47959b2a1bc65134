#include "exchange/statistics.h"
#include "exchange/statisticsset.h"

#include <QtCore/QJsonArray>
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

using namespace mbscope;

namespace {

Transaction make(TransactionStatus status, qint64 latencyNs = 0, int item = -1, quint8 exceptionCode = 0)
{
    Transaction t;
    t.item = item;
    t.status = status;
    t.exceptionCode = exceptionCode;
    t.sentNs = 1000000000;
    if (latencyNs > 0) {
        t.firstByteNs = t.sentNs + latencyNs / 2;
        t.doneNs = t.sentNs + latencyNs;
    }
    return t;
}

LatencySamples samplesOf(const std::vector<qint64> &values)
{
    LatencySamples s;
    for (const qint64 v : values)
        s.add(v);
    return s;
}

} // namespace

// Percentiles by nearest rank: the p-th percentile of n sorted values is the one at 1-based rank
// ceil(p/100 * n). Expected values below are worked out by hand from that rule.
class TestStatistics : public QObject
{
    Q_OBJECT
private slots:
    void nearestRank_data()
    {
        QTest::addColumn<QList<qint64>>("values");
        QTest::addColumn<double>("p");
        QTest::addColumn<qint64>("expected");
        const QList<qint64> five{35, 20, 50, 15, 40}; // sorted 15 20 35 40 50
        QTest::newRow("15 20 35 40 50 p5: rank ceil(0.25)=1") << five << 5.0 << 15LL;
        QTest::newRow("15 20 35 40 50 p30: rank ceil(1.5)=2") << five << 30.0 << 20LL;
        QTest::newRow("15 20 35 40 50 p40: rank 2 exactly") << five << 40.0 << 20LL;
        QTest::newRow("15 20 35 40 50 p50: rank ceil(2.5)=3") << five << 50.0 << 35LL;
        QTest::newRow("15 20 35 40 50 p100: rank 5") << five << 100.0 << 50LL;
        QTest::newRow("15 20 35 40 50 p0: the minimum") << five << 0.0 << 15LL;
        const QList<qint64> ten{20, 3, 16, 8, 13, 7, 8, 15, 10, 6}; // sorted 3 6 7 8 8 10 13 15 16 20
        QTest::newRow("ten values p25: rank ceil(2.5)=3") << ten << 25.0 << 7LL;
        QTest::newRow("ten values p50: rank 5") << ten << 50.0 << 8LL;
        QTest::newRow("ten values p75: rank ceil(7.5)=8") << ten << 75.0 << 15LL;
        QTest::newRow("ten values p90: rank 9 exactly, not 10") << ten << 90.0 << 16LL;
        QTest::newRow("ten values p95: rank ceil(9.5)=10") << ten << 95.0 << 20LL;
        QTest::newRow("ten values p99: rank ceil(9.9)=10") << ten << 99.0 << 20LL;
        QTest::newRow("ten values p10: rank 1") << ten << 10.0 << 3LL;
        QTest::newRow("ten values p10.1: rank 2") << ten << 10.1 << 6LL;
        const QList<qint64> four{4, 1, 3, 2};
        QTest::newRow("1 2 3 4 median: the lower middle, 2") << four << 50.0 << 2LL;
        QTest::newRow("1 2 3 4 p50.01: 3") << four << 50.01 << 3LL;
        QTest::newRow("one value p1") << QList<qint64>{7} << 1.0 << 7LL;
        QTest::newRow("one value p99") << QList<qint64>{7} << 99.0 << 7LL;
        QTest::newRow("above 100 clamps to the maximum") << four << 150.0 << 4LL;
        QTest::newRow("negative p clamps to the minimum") << four << -3.0 << 1LL;
        QTest::newRow("empty: 0") << QList<qint64>{} << 50.0 << 0LL;
    }
    void nearestRank()
    {
        QFETCH(QList<qint64>, values);
        QFETCH(double, p);
        QFETCH(qint64, expected);
        const LatencySamples s = samplesOf(std::vector<qint64>(values.begin(), values.end()));
        QCOMPARE(s.percentileNs(p), expected);
    }

    // Samples added after a query are sorted and merged into the ones already sorted.
    void percentilesAfterMoreSamples()
    {
        LatencySamples s = samplesOf({50, 10, 30});
        QCOMPARE(s.medianNs(), 30LL);
        s.add(5);
        s.add(60);
        s.add(20); // 5 10 20 30 50 60
        QCOMPARE(s.medianNs(), 20LL);
        QCOMPARE(s.percentileNs(100), 60LL);
        const std::span<const qint64> sorted = s.sorted();
        QCOMPARE(std::vector<qint64>(sorted.begin(), sorted.end()), (std::vector<qint64>{5, 10, 20, 30, 50, 60}));
        s.clear();
        QCOMPARE(s.count(), 0LL);
        QCOMPARE(s.medianNs(), 0LL);
    }

    void welford()
    {
        // 2 4 4 4 5 5 7 9: mean 5, squared distances 9 1 1 1 0 0 4 16 = 32, population variance 4.
        const LatencySamples s = samplesOf({2, 4, 4, 4, 5, 5, 7, 9});
        QCOMPARE(s.meanNs(), 5.0);
        QCOMPARE(s.varianceNs2(), 4.0);
        QCOMPARE(s.stddevNs(), 2.0);
        QCOMPARE(s.minNs(), 2LL);
        QCOMPARE(s.maxNs(), 9LL);
        // The same spread 100 s up the clock: the sum of squares would lose it, Welford does not.
        std::vector<qint64> shifted{2, 4, 4, 4, 5, 5, 7, 9};
        for (qint64 &v : shifted)
            v += 100000000000LL;
        const LatencySamples far = samplesOf(shifted);
        QVERIFY(qAbs(far.stddevNs() - 2.0) < 1e-3);
        QCOMPARE(far.meanNs(), 100000000005.0);
        QCOMPARE(samplesOf({42}).stddevNs(), 0.0);
    }

    // A million samples, every percentile exact: a shuffled 1..1,000,000 has its p-th percentile
    // at p * 10,000 by nearest rank.
    void millionSamplesExact()
    {
        std::vector<qint64> values(1000000);
        std::iota(values.begin(), values.end(), 1);
        std::mt19937_64 random(20260101);
        std::shuffle(values.begin(), values.end(), random);
        LatencySamples s;
        s.reserve(values.size());
        for (const qint64 v : values)
            s.add(v);
        QCOMPARE(s.count(), 1000000LL);
        QCOMPARE(s.minNs(), 1LL);
        QCOMPARE(s.maxNs(), 1000000LL);
        QCOMPARE(s.medianNs(), 500000LL);
        QCOMPARE(s.percentileNs(90), 900000LL);
        QCOMPARE(s.percentileNs(95), 950000LL);
        QCOMPARE(s.percentileNs(99), 990000LL);
        QCOMPARE(s.percentileNs(99.9), 999000LL);
        QCOMPARE(s.percentileNs(99.9999), 999999LL);
        QCOMPARE(s.percentileNs(0.0001), 1LL);
        QVERIFY(qAbs(s.meanNs() - 500000.5) < 1e-6);
        // Population standard deviation of 1..n: sqrt((n^2 - 1) / 12).
        QVERIFY(qAbs(s.stddevNs() - std::sqrt((1e12 - 1.0) / 12.0)) < 1e-6);
        QVERIFY(s.memoryBytes() <= 8 * 1000000 + 64);
    }

    // Large batches are radix sorted over their range: every shape of range gives std::sort's order,
    // and samples added after a query are sorted and merged into the ones already sorted.
    void sortedLikeStdSort_data()
    {
        QTest::addColumn<qint64>("low");
        QTest::addColumn<qint64>("high");
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("queryAfter"); // a percentile asked after this many samples, 0: only at the end
        QTest::newRow("microseconds: 2 passes") << 100000LL << 2200000LL << 100000 << 0;
        QTest::newRow("seconds: 3 passes") << 0LL << 5000000000LL << 100000 << 0;
        QTest::newRow("all equal") << 7LL << 7LL << 10000 << 0;
        QTest::newRow("negative and positive") << -3000000LL << 3000000LL << 50000 << 0;
        QTest::newRow("the whole 64-bit range") << std::numeric_limits<qint64>::min() << std::numeric_limits<qint64>::max() << 50000 << 0;
        QTest::newRow("few distinct values") << 1000LL << 1003LL << 20000 << 0;
        QTest::newRow("below the radix threshold") << 0LL << 1000000LL << 4000 << 0;
        QTest::newRow("sorted, then a large batch merged") << 0LL << 3000000LL << 60000 << 20000;
        QTest::newRow("large batch, then a small one merged") << 0LL << 3000000LL << 30000 << 29000;
    }
    void sortedLikeStdSort()
    {
        QFETCH(qint64, low);
        QFETCH(qint64, high);
        QFETCH(int, count);
        QFETCH(int, queryAfter);
        std::mt19937_64 random(42);
        std::uniform_int_distribution<qint64> draw(low, high);
        std::vector<qint64> values;
        LatencySamples s;
        for (int i = 0; i < count; ++i) {
            values.push_back(draw(random));
            s.add(values.back());
            if (i + 1 == queryAfter)
                (void)s.medianNs();
        }
        std::sort(values.begin(), values.end());
        const std::span<const qint64> sorted = s.sorted();
        QVERIFY(std::equal(sorted.begin(), sorted.end(), values.begin(), values.end()));
        QCOMPARE(s.percentileNs(99), values[std::size_t(std::ceil(0.99 * count - 1e-9)) - 1]);
    }

    // Issue 31: a store with an exact limit keeps at most maxBins() counters after any number of
    // samples, and each percentile stays within kRelativeError of the exact one (a spread of
    // latencies over five decades, from 200 ns to 20 s); count, min, max, mean, stddev exact.
    void exactLimitBinsWithinStatedError()
    {
        std::mt19937_64 random(31);
        std::lognormal_distribution<double> spread(std::log(2e6), 2.0);
        LatencySamples exact;
        LatencySamples bounded;
        bounded.setExactLimit(1000);
        for (int i = 0; i < 300000; ++i) {
            const auto ns = std::clamp<qint64>(qint64(spread(random)), 200, qint64(20e9));
            exact.add(ns);
            bounded.add(ns);
        }
        QVERIFY(exact.isExact());
        QVERIFY(!bounded.isExact());
        QVERIFY(bounded.sorted().empty());
        QVERIFY2(bounded.memoryBytes() <= LatencySamples::maxBins() * sizeof(quint64),
                 qPrintable(QString::number(bounded.memoryBytes())));
        QVERIFY(LatencySamples::maxBins() * sizeof(quint64) < 240 * 1024);
        QCOMPARE(bounded.count(), exact.count());
        QCOMPARE(bounded.minNs(), exact.minNs());
        QCOMPARE(bounded.maxNs(), exact.maxNs());
        QCOMPARE(bounded.meanNs(), exact.meanNs());
        QCOMPARE(bounded.stddevNs(), exact.stddevNs());
        for (const double p : {0.0, 0.1, 1.0, 10.0, 25.0, 50.0, 75.0, 90.0, 95.0, 99.0, 99.9, 99.99, 100.0}) {
            const double want = double(exact.percentileNs(p));
            const double got = double(bounded.percentileNs(p));
            QVERIFY2(std::abs(got - want) <= want * LatencySamples::kRelativeError,
                     qPrintable(QStringLiteral("p%1: %2 binned, %3 exact").arg(p).arg(got).arg(want)));
        }
        // A million more samples: the bins do not grow.
        const std::size_t before = bounded.memoryBytes();
        for (int i = 0; i < 1000000; ++i)
            bounded.add(std::clamp<qint64>(qint64(spread(random)), 200, qint64(20e9)));
        QCOMPARE(bounded.memoryBytes(), before);
        QCOMPARE(bounded.count(), 1300000);
    }

    // Under the limit nothing changes; latencies under 1024 ns have a bin each (exact); clear()
    // keeps the limit and gives the memory back.
    void exactLimitBelowAndSmallValues()
    {
        LatencySamples s;
        s.setExactLimit(10);
        for (qint64 v = 1; v <= 10; ++v)
            s.add(v * 100);
        QVERIFY(s.isExact());
        QCOMPARE(s.percentileNs(50), 500);
        s.add(1000);
        QVERIFY(!s.isExact());
        QCOMPARE(s.percentileNs(50), 600); // rank 6 of 11, in a bin of its own
        QCOMPARE(s.countBelow(550), 5);
        s.clear();
        QVERIFY(s.isExact());
        QCOMPARE(s.exactLimit(), std::size_t(10));
        QCOMPARE(s.memoryBytes(), std::size_t(0));
    }

    // Histogram::addSamples counts as addSorted does while every sample is kept, and the binned
    // store's counts differ only by samples within kRelativeError of an edge.
    void histogramFromBinnedSamples()
    {
        std::mt19937_64 random(7);
        std::uniform_int_distribution<qint64> spread(1000000, 9000000);
        LatencySamples exact;
        LatencySamples bounded;
        bounded.setExactLimit(100);
        for (int i = 0; i < 50000; ++i) {
            const qint64 ns = spread(random);
            exact.add(ns);
            bounded.add(ns);
        }
        Histogram fromSorted = Histogram::autoFixed(exact.sorted());
        Histogram fromExact = Histogram::autoFixed(exact);
        QCOMPARE(fromExact.counts(), fromSorted.counts());
        QCOMPARE(fromExact.edgesNs(), fromSorted.edgesNs());
        Histogram fromBins = Histogram::autoFixed(bounded);
        QCOMPARE(fromBins.edgesNs(), fromExact.edgesNs());
        QCOMPARE(fromBins.total(), fromExact.total());
        for (int bin = 0; bin < fromBins.binCount(); ++bin) {
            const double edge = fromBins.edgesNs()[std::size_t(bin)];
            const double next = fromBins.edgesNs()[std::size_t(bin) + 1];
            qint64 nearEdges = 0; // samples that a bin's middle may put on the other side of an edge
            for (const qint64 v : exact.sorted()) {
                if (std::abs(double(v) - edge) <= edge * LatencySamples::kRelativeError
                    || std::abs(double(v) - next) <= next * LatencySamples::kRelativeError)
                    ++nearEdges;
            }
            QVERIFY2(std::abs(qint64(fromBins.count(bin)) - qint64(fromExact.count(bin))) <= nearEdges,
                     qPrintable(QStringLiteral("bin %1: %2 binned, %3 exact").arg(bin).arg(fromBins.count(bin)).arg(fromExact.count(bin))));
        }
    }

    // A StatisticsSet's limit reaches every item, and survives clear().
    void statisticsSetLimit()
    {
        StatisticsSet set;
        set.setExactLatencyLimit(5);
        for (int i = 0; i < 20; ++i)
            set.add(make(TransactionStatus::Ok, 1000000 + i, i % 2));
        QVERIFY(!set.overall().latency().isExact());
        QVERIFY(!set.item(0).latency().isExact());
        QVERIFY(!set.item(1).latency().isExact());
        set.clear();
        for (int i = 0; i < 20; ++i)
            set.add(make(TransactionStatus::Ok, 1000000 + i, 0));
        QVERIFY(!set.overall().latency().isExact());
        QVERIFY(!set.item(0).latency().isExact());
    }

    void counters()
    {
        Statistics stats;
        stats.add(make(TransactionStatus::Ok, 5000000));
        stats.add(make(TransactionStatus::Ok, 7000000));
        stats.add(make(TransactionStatus::Exception, 3000000, -1, 0x02));
        stats.add(make(TransactionStatus::Exception, 4000000, -1, 0x02));
        stats.add(make(TransactionStatus::Exception, 9000000, -1, 0x0B));
        stats.add(make(TransactionStatus::Timeout));
        stats.add(make(TransactionStatus::Timeout));
        stats.add(make(TransactionStatus::CrcError, 6000000));
        stats.add(make(TransactionStatus::Malformed, 6000000));
        stats.add(make(TransactionStatus::Unexpected, 6000000));
        stats.add(make(TransactionStatus::LinkError));
        stats.add(make(TransactionStatus::Broadcast));
        stats.add(make(TransactionStatus::Late, 1500000000));

        QCOMPARE(stats.count(), quint64(12)); // the late answer is not another transaction
        QCOMPARE(stats.ok(), quint64(2));
        QCOMPARE(stats.exceptions(), quint64(3));
        QCOMPARE(stats.exceptions(0x02), quint64(2));
        QCOMPARE(stats.exceptions(0x0B), quint64(1));
        QCOMPARE(stats.exceptions(0x01), quint64(0));
        QCOMPARE(stats.timeouts(), quint64(2));
        QCOMPARE(stats.crcErrors(), quint64(1));
        QCOMPARE(stats.malformed(), quint64(1));
        QCOMPARE(stats.unexpected(), quint64(1));
        QCOMPARE(stats.linkErrors(), quint64(1));
        QCOMPARE(stats.broadcasts(), quint64(1));
        QCOMPARE(stats.late(), quint64(1));
        QCOMPARE(stats.failed(), quint64(9));
        QCOMPARE(stats.count(), stats.ok() + stats.broadcasts() + stats.failed());
        QCOMPARE(stats.errorRate(), 9.0 / 11.0);
        // Latency of Ok and Exception only: 3 4 5 7 9 ms.
        QCOMPARE(stats.latency().count(), 5LL);
        QCOMPARE(stats.latency().minNs(), 3000000LL);
        QCOMPARE(stats.latency().maxNs(), 9000000LL);
        QCOMPARE(stats.latency().medianNs(), 5000000LL);
        QCOMPARE(stats.latency().meanNs(), 5600000.0);

        stats.clear();
        QCOMPARE(stats.count(), quint64(0));
        QCOMPARE(stats.exceptions(0x02), quint64(0));
        QCOMPARE(stats.latency().count(), 0LL);
        QCOMPARE(stats.errorRate(), 0.0);
    }

    void jsonKeys()
    {
        Statistics stats;
        for (const qint64 ns : {5663000LL, 7000000LL, 13771000LL})
            stats.add(make(TransactionStatus::Ok, ns));
        stats.add(make(TransactionStatus::Exception, 6000000, -1, 0x0A));
        stats.add(make(TransactionStatus::Timeout));
        const QJsonObject json = stats.toJson();
        for (const char *key : {"count", "ok", "exceptions", "timeouts", "crc_errors", "malformed", "late",
                                "link_errors", "latency_us", "histogram", "unexpected", "broadcasts",
                                "exceptions_by_code"})
            QVERIFY2(json.contains(QLatin1String(key)), key);
        QCOMPARE(json.value(QStringLiteral("count")).toInt(), 5);
        QCOMPARE(json.value(QStringLiteral("ok")).toInt(), 3);
        QCOMPARE(json.value(QStringLiteral("exceptions")).toInt(), 1);
        QCOMPARE(json.value(QStringLiteral("timeouts")).toInt(), 1);
        QCOMPARE(json.value(QStringLiteral("exceptions_by_code")).toObject(),
                 (QJsonObject{{QStringLiteral("0x0A"), 1}}));

        // 5.663 6 7 13.771 ms: min 5663 us, median (rank 2) 6000 us, p90/p95/p99 (rank 4) 13771 us.
        const QJsonObject latency = json.value(QStringLiteral("latency_us")).toObject();
        for (const char *key : {"min", "mean", "median", "p90", "p95", "p99", "max", "stddev"})
            QVERIFY2(latency.value(QLatin1String(key)).isDouble(), key);
        QCOMPARE(latency.value(QStringLiteral("min")).toDouble(), 5663.0);
        QCOMPARE(latency.value(QStringLiteral("median")).toDouble(), 6000.0);
        QCOMPARE(latency.value(QStringLiteral("p90")).toDouble(), 13771.0);
        QCOMPARE(latency.value(QStringLiteral("max")).toDouble(), 13771.0);
        QCOMPARE(latency.value(QStringLiteral("mean")).toDouble(), 8108.5);

        const QJsonObject histogram = json.value(QStringLiteral("histogram")).toObject();
        QVERIFY(histogram.value(QStringLiteral("bin_edges_us")).isArray());
        QVERIFY(histogram.value(QStringLiteral("counts")).isArray());
        qint64 total = 0;
        for (const QJsonValue c : histogram.value(QStringLiteral("counts")).toArray())
            total += c.toInteger();
        QCOMPARE(total, 4LL);
    }

    void jsonWithoutAnswers()
    {
        Statistics stats;
        stats.add(make(TransactionStatus::Timeout));
        const QJsonObject latency = stats.toJson().value(QStringLiteral("latency_us")).toObject();
        for (const char *key : {"min", "mean", "median", "p90", "p95", "p99", "max", "stddev"})
            QVERIFY2(latency.value(QLatin1String(key)).isNull(), key);
    }

    // With fixed bins the histogram is kept in add(), counting the answered latencies only.
    void fixedHistogram()
    {
        Statistics stats(HistogramSpec::fixed(1000000, 0, 10000000)); // 1 ms bins up to 10 ms
        stats.add(make(TransactionStatus::Ok, 500000));
        stats.add(make(TransactionStatus::Ok, 1000000));
        stats.add(make(TransactionStatus::Ok, 1999999));
        stats.add(make(TransactionStatus::Exception, 9999999, -1, 1));
        stats.add(make(TransactionStatus::Ok, 25000000));
        stats.add(make(TransactionStatus::CrcError, 3000000));
        const Histogram h = stats.histogram();
        QCOMPARE(h.counts(), (std::vector<quint64>{1, 2, 0, 0, 0, 0, 0, 0, 0, 1}));
        QCOMPARE(h.overflow(), quint64(1));
        QCOMPARE(h.total(), quint64(5));
    }

    void summaryText()
    {
        Statistics stats;
        for (const qint64 ns : {5663000LL, 7000000LL, 13771000LL})
            stats.add(make(TransactionStatus::Ok, ns));
        stats.add(make(TransactionStatus::Exception, 7001000, -1, 0x02)); // mean 33.435 / 4 = 8.35875
        const QString text = stats.summary();
        QVERIFY2(text.contains(QStringLiteral("latency ms")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("min 5.663  mean 8.359  median 7.000")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("max 13.771")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("0x02 Illegal Data Address: 1")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("ok 3 (75.0 %)  failed 1")), qPrintable(text));
        // Counter values end in one column.
        const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        for (const char *label : {"transactions", "exceptions", "timeouts", "crc errors", "link errors"}) {
            const auto line = std::find_if(lines.begin(), lines.end(),
                                           [label](const QString &l) { return l.startsWith(QLatin1String(label)); });
            QVERIFY2(line != lines.end(), label);
            QVERIFY2(line->size() >= 22 && line->at(21).isDigit() && (line->size() == 22 || line->at(22) == QLatin1Char(' ')),
                     qPrintable(*line));
        }

        Statistics fast;
        fast.add(make(TransactionStatus::Ok, 45200));
        fast.add(make(TransactionStatus::Ok, 61800));
        QVERIFY2(fast.summary().contains(QStringLiteral("latency µs    min 45.2  mean 53.5")), qPrintable(fast.summary()));

        Statistics none;
        none.add(make(TransactionStatus::Timeout));
        QVERIFY2(none.summary().contains(QStringLiteral("no answers")), qPrintable(none.summary()));
    }

    void perItem()
    {
        StatisticsSet set;
        set.setItemNames({QStringLiteral("write bits"), QStringLiteral("write words")});
        set.add(make(TransactionStatus::Ok, 1000000, 0));
        set.add(make(TransactionStatus::Ok, 3000000, 0));
        set.add(make(TransactionStatus::Timeout, 0, 1));
        set.add(make(TransactionStatus::Ok, 2000000, 1));
        set.add(make(TransactionStatus::Ok, 9000000, -1)); // a single send: overall only
        set.add(make(TransactionStatus::Late, 2000000000, 1));

        QCOMPARE(set.overall().count(), quint64(5));
        QCOMPARE(set.overall().ok(), quint64(4));
        QCOMPARE(set.itemCount(), 2);
        QCOMPARE(set.item(0).count(), quint64(2));
        QCOMPARE(set.item(0).latency().maxNs(), 3000000LL);
        QCOMPARE(set.item(1).count(), quint64(2));
        QCOMPARE(set.item(1).timeouts(), quint64(1));
        QCOMPARE(set.item(1).late(), quint64(1));
        QCOMPARE(set.item(7).count(), quint64(0));
        QCOMPARE(set.item(-1).count(), quint64(0));

        const QJsonObject json = set.toJson();
        QCOMPARE(json.value(QStringLiteral("count")).toInt(), 5);
        const QJsonArray items = json.value(QStringLiteral("items")).toArray();
        QCOMPARE(items.size(), 2);
        QCOMPARE(items.at(0).toObject().value(QStringLiteral("name")).toString(), QStringLiteral("write bits"));
        QCOMPARE(items.at(1).toObject().value(QStringLiteral("item")).toInt(), 1);
        QCOMPARE(items.at(1).toObject().value(QStringLiteral("timeouts")).toInt(), 1);
        QVERIFY(set.summary().contains(QStringLiteral("item 1 (write words)")));

        set.clear();
        QCOMPARE(set.overall().count(), quint64(0));
        QCOMPARE(set.item(0).count(), quint64(0));
    }
};

QTEST_GUILESS_MAIN(TestStatistics)
#include "tst_statistics.moc"
