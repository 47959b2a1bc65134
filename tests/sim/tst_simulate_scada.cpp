// The shipped profile scada-rs485 swept as its paper's lab did, through the product's own path:
// `mbscope simulate --profile scada-rs485` and `mbscope sweep --intervals 100,200,300,333,350,400`
// sending '$01R#' over delimited framing. Fewer requests per interval than the paper's 300 (a
// full run takes eight minutes), so each error rate is checked against the paper's within 3.5
// binomial standard deviations for the count used; tests/core/sim/tst_scadacurve checks 300 per
// interval to a few points with made-up arrival times, and tests/bench/bench_scadacurve the mean
// of 100 such seeded sweeps to 1.5 points. Both curves are printed beside the paper's.
#include "simcli.h"

#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

#include <cmath>

using namespace mbscope::simtest;

class tst_SimulateScada : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void sweepCurve();
};

void tst_SimulateScada::sweepCurve()
{
    constexpr int kCount = 50;
    const QList<std::pair<int, double>> paper = {{100, 50.66}, {200, 32.66}, {300, 27.66}, {333, 22.66}, {350, 22.0}, {400, 22.33}};
    SimCli sim;
    QString why;
    QVERIFY2(sim.start({QStringLiteral("--profile"), QStringLiteral("scada-rs485"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0?framing=delimited&start=24&end=23"), QStringLiteral("--quiet")},
                       1, &why),
             qPrintable(why));
    const QString target = QStringLiteral("tcp://127.0.0.1:%1?framing=delimited&start=24&end=23").arg(sim.port(0));
    // The timeout stays under the shortest interval, so that a lost answer does not push the
    // next request later (the interval is what the bus's faults depend on).
    const Run r = runProcess(mbscopePath(), {QStringLiteral("sweep"), QStringLiteral("--target"), target, QStringLiteral("--hex"),
                                             QStringLiteral("24 30 31 52 23"), QStringLiteral("--intervals"),
                                             QStringLiteral("100,200,300,333,350,400"), QStringLiteral("--count"),
                                             QString::number(kCount), QStringLiteral("--timeout"), QStringLiteral("90ms")},
                             300000);
    QVERIFY2(r.exitCode == 0 || r.exitCode == 1, (r.out + r.err).constData());
    QString table = QStringLiteral("interval ms   paper %   measured % (mbscope sweep, %1 per interval)\n").arg(kCount);
    for (const auto &[interval, expected] : paper) {
        // "100 ms        50         0     50  25      25     50.00 %  ..." (cycles, overruns, count, ok, failed)
        const QRegularExpression row(QStringLiteral("^%1 ms\\s+\\d+\\s+\\d+\\s+(\\d+)\\s+\\d+\\s+(\\d+)\\s+([0-9.]+) %").arg(interval),
                                     QRegularExpression::MultilineOption);
        const QRegularExpressionMatch m = row.match(QString::fromUtf8(r.out));
        QVERIFY2(m.hasMatch(), r.out.constData());
        QCOMPARE(m.captured(1).toInt(), kCount);
        const double measured = m.captured(3).toDouble();
        table += QStringLiteral("%1  %2  %3\n").arg(interval, 11).arg(expected, 8, 'f', 2).arg(measured, 11, 'f', 2);
        const double p = expected / 100.0;
        const double bound = 100.0 * 3.5 * std::sqrt(p * (1 - p) / kCount);
        QVERIFY2(std::abs(measured - expected) <= bound,
                 qPrintable(QStringLiteral("%1 ms: %2 %% measured, the paper %3 %% (+- %4)\n%5")
                                .arg(interval).arg(measured).arg(expected).arg(bound).arg(QString::fromUtf8(r.out))));
    }
    qInfo().noquote() << "\n" << table;
    QCOMPARE(sim.stop(), 0);
}

QTEST_GUILESS_MAIN(tst_SimulateScada)
#include "tst_simulate_scada.moc"
