// The shipped profile scada-rs485 against the SCADA paper's measurements: 300 requests per poll
// interval on its noisy RS485 bus, error rates 50.66 % at 100 ms, 32.66 % at 200 ms, 27.66 % at
// 300 ms, 22.66 % at 333 ms, 22 % at 350 ms, 22.33 % at 400 ms. The request path
// (Simulator::handleFrame with the profile's fault rules, scadasweep.h) is driven with arrival
// times made up by the test, so the curve is exact and reproducible; each answer goes through a
// client's delimited framer, as mbscope's engine reads it. One run with the profile's own seed,
// as `mbscope simulate --profile scada-rs485` draws them: 300 requests spread a rate by about 2.4
// to 2.9 points, so each interval is checked to a few points; tests/bench/bench_scadacurve
// averages many seeds and checks the model's mean to 1.5 points. The measured curve is printed
// beside the paper's; tests/sim/tst_simulate_scada runs the real `mbscope sweep`.

#include "scadasweep.h"

#include "profile/profileloader.h"

#include <QtTest/QtTest>

#include <cmath>

using namespace mbscope;

namespace {

constexpr double kFewPoints = 4.0; // "within a few percentage points"

} // namespace

class TestScadaCurve : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void curve();
};

void TestScadaCurve::curve()
{
    const ProfileLoadResult loaded = ProfileLoader::loadFile(QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../../resources/profiles/scada-rs485.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    QString error;
    const std::vector<int> errors = scadasweep::run(loaded.profile, loaded.profile.seed, scadasweep::kPaperRequests, &error);
    QVERIFY2(errors.size() == std::size(scadasweep::kPaper), qPrintable(error));

    QString table = QStringLiteral("interval ms   paper %   measured % (seed %1)\n").arg(loaded.profile.seed);
    QString failed;
    for (size_t i = 0; i < errors.size(); ++i) {
        const scadasweep::PaperPoint &p = scadasweep::kPaper[i];
        const double measured = 100.0 * errors[i] / scadasweep::kPaperRequests;
        table += QStringLiteral("%1  %2  %3\n").arg(p.intervalMs, 11).arg(p.percent, 8, 'f', 2).arg(measured, 11, 'f', 2);
        if (std::abs(measured - p.percent) > kFewPoints)
            failed += QStringLiteral("%1 ms: %2 %% measured, the paper %3 %%\n").arg(p.intervalMs).arg(measured).arg(p.percent);
    }
    qInfo().noquote() << "\n" << table;
    QVERIFY2(failed.isEmpty(), qPrintable(failed));
}

QTEST_GUILESS_MAIN(TestScadaCurve)
#include "tst_scadacurve.moc"
