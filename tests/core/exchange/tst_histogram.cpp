#include "exchange/histogram.h"

#include <QtCore/QJsonArray>
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace mbscope;

// Bins are [edge[i], edge[i+1]); below the first edge is underflow (-1), at or above the last
// overflow (binCount()). Every expected bin and count here is worked out by hand.
class TestHistogram : public QObject
{
    Q_OBJECT
private slots:
    void fixedBinOf_data()
    {
        QTest::addColumn<qint64>("width");
        QTest::addColumn<qint64>("low");
        QTest::addColumn<qint64>("high");
        QTest::addColumn<qint64>("value");
        QTest::addColumn<int>("bin");
        // 1 us bins over [0, 5 us): 5 bins.
        QTest::newRow("1us [0,5us) 0 -> 0") << 1000LL << 0LL << 5000LL << 0LL << 0;
        QTest::newRow("1us [0,5us) 999 -> 0") << 1000LL << 0LL << 5000LL << 999LL << 0;
        QTest::newRow("1us [0,5us) 1000 on an edge -> 1") << 1000LL << 0LL << 5000LL << 1000LL << 1;
        QTest::newRow("1us [0,5us) 4999 -> 4") << 1000LL << 0LL << 5000LL << 4999LL << 4;
        QTest::newRow("1us [0,5us) 5000 the last edge -> overflow") << 1000LL << 0LL << 5000LL << 5000LL << 5;
        QTest::newRow("1us [0,5us) -1 -> underflow") << 1000LL << 0LL << 5000LL << -1LL << -1;
        // A range that is not a whole number of widths: the last bin is [2000, 2500).
        QTest::newRow("1us [0,2.5us) 2499 -> 2") << 1000LL << 0LL << 2500LL << 2499LL << 2;
        QTest::newRow("1us [0,2.5us) 2500 -> overflow") << 1000LL << 0LL << 2500LL << 2500LL << 3;
        // Starting above zero, and below it.
        QTest::newRow("500ns [5ms,6ms) 5000000 -> 0") << 500LL << 5000000LL << 6000000LL << 5000000LL << 0;
        QTest::newRow("500ns [5ms,6ms) 4999999 -> underflow") << 500LL << 5000000LL << 6000000LL << 4999999LL << -1;
        QTest::newRow("500ns [5ms,6ms) 5000500 -> 1") << 500LL << 5000000LL << 6000000LL << 5000500LL << 1;
        QTest::newRow("10 [-20,20) -20 -> 0") << 10LL << -20LL << 20LL << -20LL << 0;
        QTest::newRow("10 [-20,20) -11 -> 0") << 10LL << -20LL << 20LL << -11LL << 0;
        QTest::newRow("10 [-20,20) -10 -> 1") << 10LL << -20LL << 20LL << -10LL << 1;
        QTest::newRow("10 [-20,20) 19 -> 3") << 10LL << -20LL << 20LL << 19LL << 3;
    }
    void fixedBinOf()
    {
        QFETCH(qint64, width);
        QFETCH(qint64, low);
        QFETCH(qint64, high);
        QFETCH(qint64, value);
        QFETCH(int, bin);
        const Histogram h = Histogram::fixed(width, low, high);
        QVERIFY(h.isValid());
        QCOMPARE(h.binOf(value), bin);
    }

    void fixedEdges()
    {
        const Histogram h = Histogram::fixed(1000, 0, 2500);
        QCOMPARE(h.binCount(), 3);
        QCOMPARE(h.edgesNs(), (std::vector<double>{0, 1000, 2000, 2500}));
    }

    void fixedCountsExactly()
    {
        Histogram h = Histogram::fixed(1000, 1000, 4000); // [1,2) [2,3) [3,4) us
        for (const qint64 v : {999, 1000, 1500, 1999, 2000, 2999, 3000, 3001, 3999, 4000, 10000, -5})
            h.add(v);
        QCOMPARE(h.counts(), (std::vector<quint64>{3, 2, 3}));
        QCOMPARE(h.underflow(), quint64(2));
        QCOMPARE(h.overflow(), quint64(2));
        QCOMPARE(h.total(), quint64(12));
        h.clear();
        QCOMPARE(h.counts(), (std::vector<quint64>{0, 0, 0}));
        QCOMPARE(h.total(), quint64(0));
        QCOMPARE(h.binCount(), 3);
    }

    void logBinOf_data()
    {
        QTest::addColumn<int>("perDecade");
        QTest::addColumn<qint64>("low");
        QTest::addColumn<qint64>("high");
        QTest::addColumn<qint64>("value");
        QTest::addColumn<int>("bin");
        // One bin a decade from 1 us to 1 ms: [1,10) [10,100) [100,1000) us.
        QTest::newRow("1/decade 999 -> underflow") << 1 << 1000LL << 1000000LL << 999LL << -1;
        QTest::newRow("1/decade 1000 -> 0") << 1 << 1000LL << 1000000LL << 1000LL << 0;
        QTest::newRow("1/decade 9999 -> 0") << 1 << 1000LL << 1000000LL << 9999LL << 0;
        QTest::newRow("1/decade 10000 on an edge -> 1") << 1 << 1000LL << 1000000LL << 10000LL << 1;
        QTest::newRow("1/decade 100000 on an edge -> 2") << 1 << 1000LL << 1000000LL << 100000LL << 2;
        QTest::newRow("1/decade 999999 -> 2") << 1 << 1000LL << 1000000LL << 999999LL << 2;
        QTest::newRow("1/decade 1000000 -> overflow") << 1 << 1000LL << 1000000LL << 1000000LL << 3;
        // Two a decade from 1 us: edges 1000, 3162.28, 10000, 31622.8, 100000.
        QTest::newRow("2/decade 3162 -> 0") << 2 << 1000LL << 100000LL << 3162LL << 0;
        QTest::newRow("2/decade 3163 -> 1") << 2 << 1000LL << 100000LL << 3163LL << 1;
        QTest::newRow("2/decade 10000 -> 2") << 2 << 1000LL << 100000LL << 10000LL << 2;
        QTest::newRow("2/decade 31622 -> 2") << 2 << 1000LL << 100000LL << 31622LL << 2;
        QTest::newRow("2/decade 31623 -> 3") << 2 << 1000LL << 100000LL << 31623LL << 3;
        QTest::newRow("2/decade 99999 -> 3") << 2 << 1000LL << 100000LL << 99999LL << 3;
    }
    void logBinOf()
    {
        QFETCH(int, perDecade);
        QFETCH(qint64, low);
        QFETCH(qint64, high);
        QFETCH(qint64, value);
        QFETCH(int, bin);
        const Histogram h = Histogram::logarithmic(perDecade, low, high);
        QVERIFY(h.isValid());
        QVERIFY(h.isLogarithmic());
        QCOMPARE(h.binOf(value), bin);
    }

    void logEdges()
    {
        const Histogram decades = Histogram::logarithmic(1, 1000, 1000000);
        QCOMPARE(decades.edgesNs(), (std::vector<double>{1000, 10000, 100000, 1000000}));
        // 10 a decade over 1 us .. 1 s: 60 bins, 61 edges, the last exactly 1 s.
        const Histogram fine = Histogram::logarithmic(10, 1000, 1000000000);
        QCOMPARE(fine.binCount(), 60);
        QCOMPARE(fine.edgesNs().front(), 1000.0);
        QVERIFY(qAbs(fine.edgesNs().back() - 1e9) < 1e-3);
        // A high bound between edges: the bins go up to the first edge above it.
        const Histogram cut = Histogram::logarithmic(3, 1000, 5000);
        QCOMPARE(cut.binCount(), 3);
        QVERIFY(qAbs(cut.edgesNs().back() - 10000.0) < 1e-6);
    }

    // Every value from 1 us to 1 ms lands in the bin whose edges enclose it, on the edges included.
    void logBinsAgreeWithEdges()
    {
        const Histogram h = Histogram::logarithmic(10, 1000, 1000000);
        const std::vector<double> &edges = h.edgesNs();
        int previous = 0;
        for (qint64 v = 1000; v < 1000000; v += 7) {
            const int bin = h.binOf(v);
            QVERIFY2(bin >= 0 && bin < h.binCount(), qPrintable(QString::number(v)));
            QVERIFY2(edges[std::size_t(bin)] <= double(v) && double(v) < edges[std::size_t(bin) + 1],
                     qPrintable(QString::number(v)));
            QVERIFY(bin >= previous);
            previous = bin;
        }
    }

    void logCountsExactly()
    {
        Histogram h = Histogram::logarithmic(1, 1000, 1000000);
        for (const qint64 v : {500, 1000, 5000, 9999, 10000, 50000, 99999, 100000, 999999, 1000000, 5000000})
            h.add(v);
        QCOMPARE(h.counts(), (std::vector<quint64>{3, 3, 2}));
        QCOMPARE(h.underflow(), quint64(1));
        QCOMPARE(h.overflow(), quint64(2));
        QCOMPARE(h.total(), quint64(11));
    }

    void invalidLayouts_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<qint64>("a");
        QTest::addColumn<qint64>("low");
        QTest::addColumn<qint64>("high");
        QTest::newRow("fixed width 0") << 0 << 0LL << 0LL << 1000LL;
        QTest::newRow("fixed width -1") << 0 << -1LL << 0LL << 1000LL;
        QTest::newRow("fixed high = low") << 0 << 10LL << 1000LL << 1000LL;
        QTest::newRow("fixed 1 ns over 1 hour: too many bins") << 0 << 1LL << 0LL << 3600000000000LL;
        QTest::newRow("log 0 a decade") << 1 << 0LL << 1000LL << 10000LL;
        QTest::newRow("log from 0") << 1 << 10LL << 0LL << 10000LL;
        QTest::newRow("log high < low") << 1 << 10LL << 10000LL << 1000LL;
    }
    void invalidLayouts()
    {
        QFETCH(int, kind);
        QFETCH(qint64, a);
        QFETCH(qint64, low);
        QFETCH(qint64, high);
        Histogram h = kind == 0 ? Histogram::fixed(a, low, high) : Histogram::logarithmic(int(a), low, high);
        QVERIFY(!h.isValid());
        QCOMPARE(h.binCount(), 0);
        h.add(5);
        QCOMPARE(h.overflow(), quint64(1)); // still counted, never lost
        QCOMPARE(h.total(), quint64(1));
    }

    void autoFromData()
    {
        // 100 values 1 us .. 100 us: about sqrt(100) = 10 bins at most; widths 1, 2, 5, 10 us
        // give 100, 51, 21, 11 bins, 20 us gives 6: [0,20) ... [100,120) us.
        std::vector<qint64> values;
        for (qint64 us = 1; us <= 100; ++us)
            values.push_back(us * 1000);
        const Histogram h = Histogram::autoFixed(values);
        QCOMPARE(h.binCount(), 6);
        QCOMPARE(h.edgesNs(), (std::vector<double>{0, 20000, 40000, 60000, 80000, 100000, 120000}));
        QCOMPARE(h.counts(), (std::vector<quint64>{19, 20, 20, 20, 20, 1}));
        QCOMPARE(h.underflow() + h.overflow(), quint64(0));

        // The M221 figures (5.663, 7.249, 13.771 ms): 2 bins at most; 2 ms bins would need
        // floor(13.771 / 2) - floor(5.663 / 2) + 1 = 5, 5 ms bins need 2: [5,10) [10,15) ms.
        const std::vector<qint64> m221{5663000, 7249000, 13771000};
        const Histogram m = Histogram::autoFixed(m221);
        QCOMPARE(m.edgesNs(), (std::vector<double>{5000000, 10000000, 15000000}));
        QCOMPARE(m.counts(), (std::vector<quint64>{2, 1}));

        // One value: one 1 us bin around it.
        const std::vector<qint64> one{12345};
        const Histogram single = Histogram::autoFixed(one);
        QCOMPARE(single.edgesNs(), (std::vector<double>{12000, 13000}));
        QCOMPARE(single.counts(), (std::vector<quint64>{1}));

        QVERIFY(!Histogram::autoFixed(std::span<const qint64>{}).isValid());
        // maxBins is honoured.
        QVERIFY(Histogram::autoFixed(values, 3).binCount() <= 3);
    }

    void specs()
    {
        QCOMPARE(Histogram::fromSpec(HistogramSpec::fixed(1000, 0, 5000)).binCount(), 5);
        QCOMPARE(Histogram::fromSpec(HistogramSpec::logarithmic(1, 1000, 1000000)).binCount(), 3);
        QVERIFY(!Histogram::fromSpec(HistogramSpec::automatic()).isValid());
    }

    void json()
    {
        Histogram h = Histogram::fixed(500, 1000, 2000);
        h.add(1200);
        h.add(1700);
        h.add(1800);
        h.add(2000);
        const QJsonObject json = h.toJson();
        QCOMPARE(json.value(QStringLiteral("bin_edges_us")).toArray(), (QJsonArray{1.0, 1.5, 2.0}));
        QCOMPARE(json.value(QStringLiteral("counts")).toArray(), (QJsonArray{1, 2}));
        QCOMPARE(json.value(QStringLiteral("underflow")).toInt(), 0);
        QCOMPARE(json.value(QStringLiteral("overflow")).toInt(), 1);
    }

    // addSorted() counts ascending values as add() counts them one by one: values on edges,
    // below the first and at or above the last edge included.
    void addSortedAgreesWithAdd_data()
    {
        QTest::addColumn<bool>("logarithmic");
        QTest::newRow("fixed") << false;
        QTest::newRow("logarithmic") << true;
    }

    void addSortedAgreesWithAdd()
    {
        QFETCH(bool, logarithmic);
        Histogram one = logarithmic ? Histogram::logarithmic(7, 1000, 3000000) : Histogram::fixed(700, 1000, 300000);
        Histogram sorted = one;
        std::vector<qint64> values;
        for (const double edge : one.edgesNs()) {
            const auto e = qint64(std::ceil(edge));
            values.insert(values.end(), {e - 1, e, e, e + 1});
        }
        for (qint64 v = 0; v < 4000000; v += 997)
            values.push_back(v);
        std::sort(values.begin(), values.end());
        for (const qint64 v : values)
            one.add(v);
        sorted.addSorted(values);
        QCOMPARE(sorted.counts(), one.counts());
        QCOMPARE(sorted.underflow(), one.underflow());
        QCOMPARE(sorted.overflow(), one.overflow());
        QCOMPARE(sorted.total(), quint64(values.size()));
        QVERIFY(one.underflow() > 0);
        QVERIFY(one.overflow() > 0);
        Histogram none;
        none.addSorted(values);
        QCOMPARE(none.overflow(), quint64(values.size()));
    }
};

QTEST_GUILESS_MAIN(TestHistogram)
#include "tst_histogram.moc"
