// SweepPanel and SweepTableModel: a sweep against the built-in simulator gives one point and one
// table row per interval, with the figures of the engine's PollReport; bad interval lists are
// refused saying which item is wrong.
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "analysis/sweeppanel.h"
#include "analysis/sweeptablemodel.h"
#include "common/tablecsv.h"

#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>
#include <qcustomplot.h>

using namespace mbscope;

class TestSweepPanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void parseIntervals_data();
    void parseIntervals();
    void notStartedSaysWhy();
    void sweepAgainstTheSimulator();
    void stopEndsTheSweep();
};

void TestSweepPanel::parseIntervals_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QList<int>>("intervals");
    QTest::addColumn<QString>("error"); // a part of the message
    QTest::newRow("the student's list") << "100,200,300,333,350,400" << QList<int>{100, 200, 300, 333, 350, 400} << QString();
    QTest::newRow("spaces") << " 5 , 10 " << QList<int>{5, 10} << QString();
    QTest::newRow("back to back") << "0" << QList<int>{0} << QString();
    QTest::newRow("empty") << "  " << QList<int>{} << "no intervals";
    QTest::newRow("a word") << "100, fast, 300" << QList<int>{} << "interval 2 ('fast')";
    QTest::newRow("negative") << "-5" << QList<int>{} << "interval 1 ('-5')";
    QTest::newRow("a fraction") << "100, 2.5" << QList<int>{} << "interval 2 ('2.5')";
    QTest::newRow("empty item") << "100,,300" << QList<int>{} << "interval 2 of 3 is empty";
}

void TestSweepPanel::parseIntervals()
{
    QFETCH(QString, text);
    QFETCH(QList<int>, intervals);
    QFETCH(QString, error);
    QString message;
    const std::optional<QList<int>> parsed = SweepPanel::parseIntervals(text, &message);
    QCOMPARE(parsed.has_value(), error.isEmpty());
    if (parsed)
        QCOMPARE(*parsed, intervals);
    else
        QVERIFY2(message.contains(error), qPrintable(message));
}

void TestSweepPanel::notStartedSaysWhy()
{
    SweepPanel panel;
    QVERIFY(!panel.start());
    QVERIFY2(panel.message().contains(QLatin1String("connect")), qPrintable(panel.message()));
    panel.setIntervalsText(QStringLiteral("100, x"));
    QVERIFY(!panel.start());
    QVERIFY2(panel.message().contains(QLatin1String("'x'")), qPrintable(panel.message()));
    LinkController controller;
    LinkUrl url;
    url.kind = LinkKind::RtuTcp;
    url.host = QStringLiteral("127.0.0.1");
    url.port = 9;
    controller.connectTo(url);
    panel.setController(&controller);
    panel.setIntervalsText(QStringLiteral("100"));
    QVERIFY(!panel.start()); // no request source
    QVERIFY2(panel.message().contains(QLatin1String("no request")), qPrintable(panel.message()));
}

void TestSweepPanel::sweepAgainstTheSimulator()
{
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    FaultRule drop;
    drop.kind = FaultRule::Kind::Drop;
    drop.probability = 0.2;
    sim.host()->setFaultRules(FaultRuleSet{11, {drop}});
    LinkUrl url = started.url;
    url.responseTimeoutMs = 100;

    LinkController controller;
    controller.connectTo(url);
    SweepPanel panel;
    QAbstractItemModelTester tester(panel.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    panel.setController(&controller);
    panel.setRequestSource([] { return QByteArray::fromHex("01030079001615DD"); });
    panel.setIntervalsText(QStringLiteral("0, 5, 20, 10"));
    panel.setCount(12);
    QSignalSpy finished(&panel, &SweepPanel::sweepFinished);
    QVERIFY2(panel.start(), qPrintable(panel.message()));
    QVERIFY(panel.isRunning());
    QVERIFY(!panel.start()); // one at a time
    QVERIFY(finished.wait(60000));
    QVERIFY(!panel.isRunning());
    const PollReport report = finished.first().first().value<PollReport>();
    QVERIFY(report.sweep);
    QCOMPARE(report.runs.size(), 4);

    // One point per interval on each graph, one row per interval in the table.
    QCOMPARE(panel.errorRateGraph()->dataCount(), 4);
    QCOMPARE(panel.medianGraph()->dataCount(), 4);
    QCOMPARE(panel.p95Graph()->dataCount(), 4);
    QCOMPARE(panel.model()->rowCount(), 4);
    quint64 timeouts = 0;
    const QList<qint64> expectedIntervals{0, 5'000'000, 20'000'000, 10'000'000};
    for (int i = 0; i < 4; ++i) {
        const PollRun &run = report.runs.at(i);
        const Statistics &s = run.statistics.overall();
        QCOMPARE(run.intervalNs, expectedIntervals.at(i));
        const auto cell = [&](int column) { return panel.model()->index(i, column).data().toString(); };
        QCOMPARE(cell(SweepTableModel::IntervalColumn), QString::number(double(run.intervalNs) / 1e6));
        QCOMPARE(cell(SweepTableModel::CountColumn), QString::number(s.count()));
        QCOMPARE(cell(SweepTableModel::OkColumn), QString::number(s.ok()));
        QCOMPARE(cell(SweepTableModel::FailedColumn), QString::number(s.failed()));
        QCOMPARE(cell(SweepTableModel::TimeoutsColumn), QString::number(s.timeouts()));
        QCOMPARE(cell(SweepTableModel::ErrorRateColumn), QString::number(100.0 * s.errorRate(), 'f', 2));
        QCOMPARE(cell(SweepTableModel::MedianColumn), QString::number(double(s.latency().medianNs()) / 1e6, 'f', 3));
        QCOMPARE(cell(SweepTableModel::P95Column), QString::number(double(s.latency().percentileNs(95)) / 1e6, 'f', 3));
        QCOMPARE(s.count(), quint64(12));
        timeouts += s.timeouts();
        // The plot's points are the same figures, at the interval.
        const double ms = double(run.intervalNs) / 1e6;
        const auto point = panel.errorRateGraph()->data()->findBegin(ms, false);
        QCOMPARE(point->key, ms);
        QCOMPARE(point->value, 100.0 * s.errorRate());
        QCOMPARE(panel.medianGraph()->data()->findBegin(ms, false)->value, double(s.latency().medianNs()) / 1e6);
    }
    QVERIFY2(timeouts > 0, "the drop rule made no timeouts: the error rate would be 0 everywhere");
    QVERIFY2(panel.message().contains(QLatin1String("4 intervals")), qPrintable(panel.message()));
    const QString csv = TableCsv::toCsv(*panel.model());
    QCOMPARE(csv.count(QLatin1String("\r\n")), 5);
    QVERIFY(csv.startsWith(QLatin1String("Interval (ms),Cycles,Transactions,OK,Failed,Timeouts")));

    panel.resize(1000, 420);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("sweep.png")));
}

void TestSweepPanel::stopEndsTheSweep()
{
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    LinkController controller;
    controller.connectTo(started.url);
    SweepPanel panel;
    panel.setController(&controller);
    panel.setRequestSource([] { return QByteArray::fromHex("01030079001615DD"); });
    panel.setIntervalsText(QStringLiteral("50, 100, 200"));
    panel.setCount(1000);
    QSignalSpy finished(&panel, &SweepPanel::sweepFinished);
    QVERIFY(panel.start());
    QTRY_VERIFY_WITH_TIMEOUT(panel.message().startsWith(QLatin1String("Interval 50 ms (1 of 3)")), 10000);
    panel.stop();
    QVERIFY(finished.wait(10000));
    const PollReport report = finished.first().first().value<PollReport>();
    QVERIFY(report.stopped);
    QCOMPARE(report.runs.size(), 1);
    QCOMPARE(panel.model()->rowCount(), 1);
    QVERIFY2(panel.model()->index(0, 0).data().toString().contains(QLatin1String("stopped")),
             qPrintable(panel.model()->index(0, 0).data().toString()));
    QVERIFY2(panel.message().contains(QLatin1String("1 of 3")), qPrintable(panel.message()));
}

QTEST_MAIN(TestSweepPanel)
#include "tst_sweeppanel.moc"
