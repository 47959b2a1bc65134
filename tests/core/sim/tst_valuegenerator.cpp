#include "sim/generatordriver.h"
#include "sim/profileapplier.h"
#include "profile/profileloader.h"
#include "sim/simrandom.h"
#include "sim/simunit.h"
#include "sim/valuegenerator.h"

#include <QtTest/QtTest>

#include <cmath>

using namespace mbscope;

namespace {

GeneratorSpec spec(GeneratorSpec::Kind kind)
{
    GeneratorSpec s;
    s.kind = kind;
    return s;
}

QList<double> run(ValueGenerator &g, int n)
{
    QList<double> out;
    for (int i = 0; i < n; ++i)
        out.append(g.next());
    return out;
}

struct Moments {
    double mean = 0;
    double variance = 0; // unbiased sample variance
};

Moments moments(const QList<double> &xs)
{
    Moments m;
    for (double x : xs)
        m.mean += x;
    m.mean /= double(xs.size());
    for (double x : xs)
        m.variance += (x - m.mean) * (x - m.mean);
    m.variance /= double(xs.size() - 1);
    return m;
}

DeviceProfile profile(const char *tables)
{
    const QByteArray json = QByteArray(R"({"name": "t", "seed": 5, "units": [{"id": 1, "tables": )") + tables + "}]}";
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("t.json"));
    if (!r.ok)
        qFatal("test profile refused: %s", qPrintable(r.errorText()));
    return r.profile;
}

} // namespace

// Generators are pure sequences of a seed and a period count: no test here waits for real time.
class TestValueGenerator : public QObject
{
    Q_OBJECT
private slots:
    // Known answers of xoshiro256** seeded through splitmix64 (computed with an independent
    // implementation of Vigna's reference code): the same seed gives the same numbers everywhere.
    void randomKnownAnswers()
    {
        SimRandom one(1);
        QCOMPARE(one.next(), 0xb3f2af6d0fc710c5ULL);
        QCOMPARE(one.next(), 0x853b559647364ceaULL);
        QCOMPARE(one.next(), 0x92f89756082a4514ULL);
        SimRandom zero(0);
        QCOMPARE(zero.next(), 0x99ec5f36cb75f2b4ULL);
        QCOMPARE(SimRandom::derive(1, 2, 3, 4), 0xd55ccd4aeb3ccafbULL);
        QVERIFY(SimRandom::derive(1, 2, 3, 4) != SimRandom::derive(1, 2, 3, 5));
        one.reseed(1);
        QCOMPARE(one.next(), 0xb3f2af6d0fc710c5ULL);
    }

    void randomRanges()
    {
        SimRandom r(77);
        int hits[6] = {};
        for (int i = 0; i < 60000; ++i) {
            const double u = r.uniform();
            QVERIFY(u >= 0 && u < 1);
            const quint64 k = r.below(6);
            QVERIFY(k < 6);
            ++hits[k];
        }
        for (int h : hits) // 10000 expected each; sd ~91
            QVERIFY2(std::abs(h - 10000) < 500, qPrintable(QString::number(h)));
        QCOMPARE(r.below(1), quint64(0));
        QVERIFY(!r.chance(0));
        QVERIFY(r.chance(1));
    }

    // Log-normal by its own mean and standard deviation: the sample moments match them, half the
    // draws fall below the median mean / sqrt(1 + cv^2), and a mean of 0 draws as much as any.
    void randomLogNormal()
    {
        SimRandom r(31);
        constexpr int n = 40000;
        constexpr double mean = 112;
        constexpr double stddev = 132;
        const double median = mean / std::sqrt(1 + (stddev / mean) * (stddev / mean));
        double sum = 0;
        double sumSquares = 0;
        int belowMedian = 0;
        for (int i = 0; i < n; ++i) {
            const double x = r.logNormal(mean, stddev);
            QVERIFY(x > 0);
            sum += x;
            sumSquares += x * x;
            belowMedian += x < median ? 1 : 0;
        }
        const double m = sum / n;
        const double sd = std::sqrt(sumSquares / n - m * m);
        QVERIFY2(std::abs(m - mean) < 5 * stddev / std::sqrt(double(n)), qPrintable(QString::number(m)));
        QVERIFY2(std::abs(sd - stddev) < 0.1 * stddev, qPrintable(QString::number(sd)));
        QVERIFY2(std::abs(belowMedian - n / 2) < 5 * std::sqrt(n / 4.0), qPrintable(QString::number(belowMedian)));
        // stddev 0: the mean itself.
        QCOMPARE(std::llround(r.logNormal(25, 0) * 1e9), std::llround(25e9));
        SimRandom a(5);
        SimRandom b(5);
        QCOMPARE(a.logNormal(0, 10), 0.0);
        (void)b.logNormal(50, 10);
        QCOMPARE(a.next(), b.next());
    }

    void constant()
    {
        GeneratorSpec s = spec(GeneratorSpec::Kind::Constant);
        s.value = 42;
        ValueGenerator g(s, 1, 7);
        QCOMPARE(g.value(), 7.0);
        QCOMPARE(run(g, 3), (QList<double>{42, 42, 42}));
        QCOMPARE(g.periods(), 3);
    }

    void counter_data()
    {
        QTest::addColumn<double>("initial");
        QTest::addColumn<double>("step");
        QTest::addColumn<double>("min");
        QTest::addColumn<double>("max");
        QTest::addColumn<bool>("wrap");
        QTest::addColumn<QList<double>>("expected");
        QTest::newRow("up, wraps to min") << 0.0 << 1.0 << 0.0 << 3.0 << true << QList<double>{1, 2, 3, 0, 1};
        QTest::newRow("up, stays at max") << 0.0 << 1.0 << 0.0 << 3.0 << false << QList<double>{1, 2, 3, 3, 3};
        QTest::newRow("down, wraps to max") << 2.0 << -1.0 << 0.0 << 3.0 << true << QList<double>{1, 0, 3, 2, 1};
        QTest::newRow("down, stays at min") << 1.0 << -1.0 << 0.0 << 3.0 << false << QList<double>{0, 0, 0};
        QTest::newRow("step 5 past max") << 0.0 << 5.0 << 0.0 << 9.0 << true << QList<double>{5, 0, 5, 0};
        QTest::newRow("16-bit roll over") << 65534.0 << 1.0 << 0.0 << 65535.0 << true << QList<double>{65535, 0, 1};
        QTest::newRow("toggle 0/1") << 1.0 << 1.0 << 0.0 << 1.0 << true << QList<double>{0, 1, 0, 1};
    }
    void counter()
    {
        QFETCH(double, initial);
        QFETCH(double, step);
        QFETCH(double, min);
        QFETCH(double, max);
        QFETCH(bool, wrap);
        QFETCH(QList<double>, expected);
        GeneratorSpec s = spec(GeneratorSpec::Kind::Counter);
        s.step = step;
        s.min = min;
        s.max = max;
        s.wrap = wrap;
        ValueGenerator g(s, 1, initial);
        QCOMPARE(run(g, int(expected.size())), expected);
    }

    void counterAdopts()
    {
        GeneratorSpec s = spec(GeneratorSpec::Kind::Counter);
        s.max = 1000;
        ValueGenerator g(s, 1, 0);
        QCOMPARE(g.next(), 1.0);
        g.adopt(500); // a client wrote 500
        QCOMPARE(g.next(), 501.0);
    }

    void randomWalk()
    {
        GeneratorSpec s = spec(GeneratorSpec::Kind::RandomWalk);
        s.step = 2;
        s.min = 60;
        s.max = 80;
        ValueGenerator a(s, 1234, 69);
        ValueGenerator b(s, 1234, 69);
        ValueGenerator c(s, 1235, 69);
        const QList<double> xs = run(a, 5000);
        QCOMPARE(run(b, 5000), xs);           // the same seed, the same walk
        QVERIFY(run(c, 5000) != xs);          // another seed, another walk
        double previous = 69;
        double sumSteps = 0;
        bool visitedLow = false;
        bool visitedHigh = false;
        for (double x : xs) {
            QVERIFY(x >= 60 && x <= 80);
            QVERIFY(std::fabs(x - previous) <= 2.0 + 1e-9 || x > 78 || x < 62); // reflection near a bound
            sumSteps += x - previous;
            previous = x;
            visitedLow = visitedLow || x < 62;
            visitedHigh = visitedHigh || x > 78;
        }
        QVERIFY(visitedLow && visitedHigh); // 5000 steps of up to 2 cover a range of 20
        QVERIFY(std::fabs(sumSteps) <= 20);
    }

    void randomWalkStepWiderThanRange()
    {
        GeneratorSpec s = spec(GeneratorSpec::Kind::RandomWalk);
        s.step = 100;
        s.min = 0;
        s.max = 1;
        ValueGenerator g(s, 9, 0.5);
        for (double x : run(g, 1000))
            QVERIFY(x >= 0 && x <= 1);
    }

    void sine_data()
    {
        QTest::addColumn<double>("phaseDeg");
        QTest::addColumn<QList<double>>("expected");
        // amplitude 10, offset 5, a value every 250 ms of a 1000 ms wave: quarter turns.
        QTest::newRow("phase 0") << 0.0 << QList<double>{15, 5, -5, 5, 15};
        QTest::newRow("phase 90") << 90.0 << QList<double>{5, -5, 5, 15, 5};
    }
    void sine()
    {
        QFETCH(double, phaseDeg);
        QFETCH(QList<double>, expected);
        GeneratorSpec s = spec(GeneratorSpec::Kind::Sine);
        s.amplitude = 10;
        s.offset = 5;
        s.periodMs = 250;
        s.wavePeriodMs = 1000;
        s.phaseDeg = phaseDeg;
        ValueGenerator g(s, 1, 0);
        for (double e : expected)
            QVERIFY2(std::fabs(g.next() - e) < 1e-9, qPrintable(QString::number(g.value())));
    }

    // Counts in a gate: mean and variance both lambda. Bounds are five standard errors, so with
    // a fixed seed the test is exact (it passes or fails the same way on every run) yet a wrong
    // sampler (a mean or a variance off by a few percent) fails it.
    void poissonMoments_data()
    {
        QTest::addColumn<double>("rate");   // counts per second
        QTest::addColumn<double>("gateMs");
        QTest::addColumn<quint64>("seed");
        QTest::newRow("GM tube, 0.5/s, 1 s (multiplication method)") << 0.5 << 1000.0 << quint64(3);
        QTest::newRow("3/s, 1 s (multiplication method)") << 3.0 << 1000.0 << quint64(4);
        QTest::newRow("9.9/s, 1 s (below the switch)") << 9.9 << 1000.0 << quint64(5);
        QTest::newRow("CsI, 150/s, 1 s (PTRS)") << 150.0 << 1000.0 << quint64(6);
        QTest::newRow("50/s, 200 ms gate (PTRS at 10)") << 50.0 << 200.0 << quint64(7);
        QTest::newRow("20000/s, 1 s (PTRS)") << 20000.0 << 1000.0 << quint64(8);
    }
    void poissonMoments()
    {
        QFETCH(double, rate);
        QFETCH(double, gateMs);
        QFETCH(quint64, seed);
        GeneratorSpec s = spec(GeneratorSpec::Kind::Poisson);
        s.rate = rate;
        s.gateMs = gateMs;
        s.periodMs = gateMs;
        ValueGenerator g(s, seed, 0);
        const int n = 20000;
        const QList<double> xs = run(g, n);
        const double lambda = rate * gateMs / 1000.0;
        const Moments m = moments(xs);
        const double meanError = std::sqrt(lambda / n);
        const double varianceError = std::sqrt((lambda + 2 * lambda * lambda) / n);
        QVERIFY2(std::fabs(m.mean - lambda) < 5 * meanError,
                 qPrintable(QStringLiteral("mean %1, lambda %2").arg(m.mean).arg(lambda)));
        QVERIFY2(std::fabs(m.variance - lambda) < 5 * varianceError,
                 qPrintable(QStringLiteral("variance %1, lambda %2").arg(m.variance).arg(lambda)));
        for (double x : xs)
            QVERIFY(x >= 0 && x == std::floor(x));
        // P(0) = e^-lambda, within five standard errors of a proportion.
        const double p0 = std::exp(-lambda);
        const double zeros = double(std::count(xs.cbegin(), xs.cend(), 0.0)) / n;
        QVERIFY2(std::fabs(zeros - p0) < 5 * std::sqrt(p0 * (1 - p0) / n) + 1e-12,
                 qPrintable(QStringLiteral("P(0) %1, expected %2").arg(zeros).arg(p0)));
        // Reproducible.
        ValueGenerator again(s, seed, 0);
        QCOMPARE(run(again, 100), xs.mid(0, 100));
    }

    void poissonAccumulates()
    {
        GeneratorSpec s = spec(GeneratorSpec::Kind::Poisson);
        s.rate = 20;
        s.accumulate = true;
        ValueGenerator total(s, 11, 100);
        s.accumulate = false;
        ValueGenerator counts(s, 11, 0);
        double expected = 100;
        for (int i = 0; i < 50; ++i) {
            expected += counts.next();
            QCOMPARE(total.next(), expected);
        }
    }

    void poissonZeroRate()
    {
        GeneratorSpec s = spec(GeneratorSpec::Kind::Poisson);
        s.rate = 0;
        ValueGenerator g(s, 1, 5);
        QCOMPARE(run(g, 3), (QList<double>{0, 0, 0}));
    }

    void copy()
    {
        ValueGenerator g(spec(GeneratorSpec::Kind::Copy), 1, 0);
        QCOMPARE(g.next(12.5), 12.5);
        QCOMPARE(g.next(-3), -3.0);
    }

    void driverTicksIntoUnit();
    void driverAdoptsClientWrites();
    void driverCopiesAndScales();
    void driverIsReproducible();
    void driverSeeds();
    void driverTimers();
};

void TestValueGenerator::driverTicksIntoUnit()
{
    const DeviceProfile p = profile(R"({"holding": [
        {"address": 0, "value": 10, "generator": {"kind": "counter", "step": 2, "periodMs": 100}},
        {"address": 1, "count": 3, "generator": {"kind": "counter", "periodMs": 250}}],
        "coils": [{"address": 0, "value": true, "generator": {"kind": "counter", "min": 0, "max": 1, "periodMs": 100}}]})");
    QObject owner;
    const QList<SimUnit *> units = ProfileApplier::createUnits(p, &owner);
    GeneratorDriver driver;
    driver.attach(p, units);
    QCOMPARE(driver.generatorCount(), 5); // one per value: 1 + 3 + 1
    QCOMPARE(driver.periods(), (QList<double>{100, 250}));
    QSignalSpy changed(units.at(0), &SimUnit::valuesChanged);
    driver.advance(99);
    QCOMPARE(units.at(0)->value(SimTable::HoldingRegisters, 0), std::optional<quint16>(10));
    driver.advance(1); // t = 100
    QCOMPARE(units.at(0)->value(SimTable::HoldingRegisters, 0), std::optional<quint16>(12));
    QCOMPARE(units.at(0)->value(SimTable::Coils, 0), std::optional<quint16>(0));
    driver.advance(400); // t = 500: five ticks of 100, two of 250
    QCOMPARE(units.at(0)->value(SimTable::HoldingRegisters, 0), std::optional<quint16>(20));
    QCOMPARE(units.at(0)->values(SimTable::HoldingRegisters, 1, 3), (QList<quint16>{2, 2, 2}));
    QCOMPARE(units.at(0)->value(SimTable::Coils, 0), std::optional<quint16>(0)); // toggled five times
    QVERIFY(changed.count() >= 5);
}

void TestValueGenerator::driverAdoptsClientWrites()
{
    const DeviceProfile p = profile(R"({"holding": [
        {"address": 0, "generator": {"kind": "counter", "periodMs": 100}}]})");
    QObject owner;
    const QList<SimUnit *> units = ProfileApplier::createUnits(p, &owner);
    GeneratorDriver driver;
    driver.attach(p, units);
    driver.advance(200);
    QCOMPARE(units.at(0)->value(SimTable::HoldingRegisters, 0), std::optional<quint16>(2));
    QVERIFY(units.at(0)->clientWrite(SimTable::HoldingRegisters, 0, {1000}));
    driver.advance(100);
    QCOMPARE(units.at(0)->value(SimTable::HoldingRegisters, 0), std::optional<quint16>(1001));
}

void TestValueGenerator::driverCopiesAndScales()
{
    const DeviceProfile p = profile(R"({"holding": [
        {"address": 0, "type": "f32", "value": 1.5, "generator": {"kind": "sine", "amplitude": 20, "offset": 1.5,
         "wavePeriodMs": 400, "periodMs": 100}},
        {"address": 2, "type": "i16", "scale": 0.1, "generator": {"kind": "copy", "address": 0, "periodMs": 100}}],
        "input": [{"address": 0, "type": "u16", "generator": {"kind": "counter", "min": 0, "max": 65535, "step": 30000,
         "periodMs": 100}}],
        "discrete": [{"address": 0, "generator": {"kind": "copy", "table": "input", "address": 0, "periodMs": 100}}]})");
    QObject owner;
    SimUnit *unit = ProfileApplier::createUnits(p, &owner).value(0);
    GeneratorDriver driver;
    driver.attach(p, {unit});
    // t=100: sine 1.5 + 20 = 21.5 (f32 0x41AC0000); the copy ran in the same tick, after it
    // (entries in address order), so it holds 21.5 as raw 215.
    driver.advance(100);
    QCOMPARE(unit->values(SimTable::HoldingRegisters, 0, 2), (QList<quint16>{0x41AC, 0x0000}));
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 2), std::optional<quint16>(215));
    QCOMPARE(unit->value(SimTable::InputRegisters, 0), std::optional<quint16>(30000));
    // Discrete inputs come before input registers: the copy saw 0 at this tick.
    QCOMPARE(unit->value(SimTable::DiscreteInputs, 0), std::optional<quint16>(0));
    driver.advance(100); // t=200: sine back to 1.5; counter 60000; the bit copies 30000 -> ON
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 2), std::optional<quint16>(15));
    QCOMPARE(unit->value(SimTable::InputRegisters, 0), std::optional<quint16>(60000));
    QCOMPARE(unit->value(SimTable::DiscreteInputs, 0), std::optional<quint16>(1));
    driver.advance(100); // t=300: sine 1.5 - 20 = -18.5 -> raw -185 (0xFF47); the counter wraps to 0
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 2), std::optional<quint16>(0xFF47));
    QCOMPARE(unit->value(SimTable::InputRegisters, 0), std::optional<quint16>(0));
}

void TestValueGenerator::driverIsReproducible()
{
    const DeviceProfile p = profile(R"({"holding": [
        {"address": 0, "count": 4, "generator": {"kind": "poisson", "rate": 100, "gateMs": 500}},
        {"address": 10, "value": 1000, "generator": {"kind": "randomWalk", "step": 50, "periodMs": 200}}]})");
    QList<QList<quint16>> runs;
    for (int i = 0; i < 2; ++i) {
        QObject owner;
        const QList<SimUnit *> units = ProfileApplier::createUnits(p, &owner);
        GeneratorDriver driver;
        driver.attach(p, units);
        QList<quint16> seen;
        for (int t = 0; t < 20; ++t) {
            driver.advance(100);
            seen += units.at(0)->values(SimTable::HoldingRegisters, 0, 4);
            seen += units.at(0)->values(SimTable::HoldingRegisters, 10, 1);
        }
        runs.append(seen);
    }
    QCOMPARE(runs.at(0), runs.at(1));
    // The four counters draw from streams of their own.
    const QList<quint16> last = runs.at(0).mid(runs.at(0).size() - 5, 4);
    QVERIFY(!(last.at(0) == last.at(1) && last.at(1) == last.at(2) && last.at(2) == last.at(3)));
}

void TestValueGenerator::driverSeeds()
{
    GeneratorSpec s = spec(GeneratorSpec::Kind::Poisson);
    const quint64 a = GeneratorDriver::valueSeed(5, s, 1, SimTable::HoldingRegisters, 0, 0);
    QCOMPARE(GeneratorDriver::valueSeed(5, s, 1, SimTable::HoldingRegisters, 0, 0), a);
    QVERIFY(GeneratorDriver::valueSeed(5, s, 1, SimTable::HoldingRegisters, 1, 1) != a);
    QVERIFY(GeneratorDriver::valueSeed(5, s, 2, SimTable::HoldingRegisters, 0, 0) != a);
    QVERIFY(GeneratorDriver::valueSeed(5, s, 1, SimTable::InputRegisters, 0, 0) != a);
    QVERIFY(GeneratorDriver::valueSeed(6, s, 1, SimTable::HoldingRegisters, 0, 0) != a);
    s.seed = 99; // the generator's own seed: the profile's seed and the place no longer matter
    QCOMPARE(GeneratorDriver::valueSeed(5, s, 1, SimTable::HoldingRegisters, 0, 0),
             GeneratorDriver::valueSeed(6, s, 2, SimTable::InputRegisters, 7, 0));
    QVERIFY(GeneratorDriver::valueSeed(5, s, 1, SimTable::HoldingRegisters, 0, 1)
            != GeneratorDriver::valueSeed(5, s, 1, SimTable::HoldingRegisters, 0, 0));
}

// The timers drive tickPeriod(); the test waits for ticks to happen, never for how long they take.
void TestValueGenerator::driverTimers()
{
    const DeviceProfile p = profile(R"({"holding": [
        {"address": 0, "generator": {"kind": "counter", "periodMs": 5}}]})");
    QObject owner;
    const QList<SimUnit *> units = ProfileApplier::createUnits(p, &owner);
    GeneratorDriver driver;
    driver.attach(p, units);
    QSignalSpy ticks(&driver, &GeneratorDriver::ticked);
    driver.start();
    QVERIFY(driver.isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(ticks.count() >= 3, 10000);
    driver.stop();
    QVERIFY(!driver.isRunning());
    const int counted = int(ticks.count());
    QCOMPARE(units.at(0)->value(SimTable::HoldingRegisters, 0), std::optional<quint16>(counted));
    QCOMPARE(ticks.at(0).at(0).toDouble(), 5.0);
    QCOMPARE(ticks.at(0).at(1).toInt(), 1);
}

QTEST_GUILESS_MAIN(TestValueGenerator)
#include "tst_valuegenerator.moc"
