// The Latency histogram and Compare tabs: a poll against the built-in simulator fills the
// histogram with the counts the engine's own statistics report; linear and logarithmic bins;
// one request item against all; two runs overlaid; the statistics table model; exports.
// Screenshots of both panels go to the test output.
#include "analysis/analysisdock.h"
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "analysis/latencyanalysis.h"
#include "analysis/latencycomparepanel.h"
#include "analysis/latencyhistogrampanel.h"
#include "analysis/latencyruns.h"
#include "analysis/latencystatisticsmodel.h"
#include "link/linkcontroller.h"
#include "common/plotexportmenu.h"
#include "common/tablecsv.h"

#include <QtCore/QFileInfo>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <qcustomplot.h>

#include <cmath>
#include <numeric>

using namespace mbscope;

class TestLatencyHistogram : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void pollFillsHistogramAsEngineCounts();
    void bins_data();
    void bins();
    void itemOrOverall();
    void compareOverlaysTwoRuns();
    void redrawsAreBatched();
    void captureIsShown();
    void statisticsModel();
    void serialLineOutrun();
    void exports_data();
    void exports();
};

namespace {

quint64 barTotal(const Histogram &h)
{
    return std::accumulate(h.counts().begin(), h.counts().end(), quint64(0));
}

Transaction answered(qint64 latencyNs, int item = 0, TransactionStatus status = TransactionStatus::Ok, quint8 code = 0)
{
    Transaction t;
    t.item = item;
    t.status = status;
    t.exceptionCode = code;
    t.sentNs = 1000000;
    t.doneNs = t.sentNs + latencyNs;
    return t;
}

Transaction timedOut(int item = 0)
{
    Transaction t;
    t.item = item;
    t.status = TransactionStatus::Timeout;
    t.sentNs = 1000000;
    return t;
}

// n latencies spread evenly in log space from lowNs to highNs: a tail over several decades.
QList<Transaction> logSpread(int n, double lowNs, double highNs, int item = 0)
{
    QList<Transaction> list;
    for (int i = 0; i < n; ++i)
        list.append(answered(qint64(lowNs * std::pow(highNs / lowNs, double(i) / (n - 1))), item));
    return list;
}

} // namespace

void TestLatencyHistogram::initTestCase()
{
    guitest::isolateSettings();
}

void TestLatencyHistogram::pollFillsHistogramAsEngineCounts()
{
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    LinkController controller;
    AnalysisDock dock;
    LatencyAnalysis analysis(&dock, &controller);
    QCOMPARE(dock.tabs()->count(), 2);
    QSignalSpy finished(&controller, &LinkController::pollFinished);
    controller.connectTo(started.url);
    // A single send before the poll: the poll starts a run of its own without it.
    QVERIFY(controller.send(QByteArray::fromHex("01030079001615DD")) > 0);
    QTRY_COMPARE_WITH_TIMEOUT(analysis.runs()->statistics(LatencyRuns::Current).overall().count(), quint64(1), 5000);
    QVERIFY(controller.startPoll(QByteArray::fromHex("01030079001615DD"), 0, 300));
    QVERIFY(finished.wait(30000));
    const PollReport report = finished.first().first().value<PollReport>();
    QCOMPARE(report.runs.size(), 1);
    const Statistics &engine = report.runs.constFirst().statistics.overall();
    QCOMPARE(engine.count(), quint64(300));
    const Statistics &shown = analysis.runs()->statistics(LatencyRuns::Current, -1);
    QTRY_COMPARE_WITH_TIMEOUT(shown.count(), engine.count(), 5000);

    LatencyHistogramPanel *panel = analysis.histogramPanel();
    dock.resize(1100, 460);
    dock.show();
    panel->redrawNow();
    const Histogram &histogram = panel->histogram();
    QVERIFY(histogram.isValid());
    // Every answer in a bar (auto bins cover them all), and the bars hold exactly the ok ones.
    QCOMPARE(histogram.underflow() + histogram.overflow(), quint64(0));
    QCOMPARE(engine.exceptions(), quint64(0));
    QCOMPARE(barTotal(histogram), engine.ok());
    QCOMPARE(histogram.edgesNs(), engine.histogram().edgesNs()); // the same auto bins as poll --json
    QCOMPARE(histogram.counts(), engine.histogram().counts());

    const LatencyStatisticsModel *table = panel->statisticsModel();
    QCOMPARE(table->value(QStringLiteral("count")).toULongLong(), engine.count());
    QCOMPARE(table->value(QStringLiteral("ok")).toULongLong(), engine.ok());
    QCOMPARE(table->value(QStringLiteral("exceptions")).toULongLong(), engine.exceptions());
    QCOMPARE(table->value(QStringLiteral("timeouts")).toULongLong(), engine.timeouts());
    QCOMPARE(table->value(QStringLiteral("crc_errors")).toULongLong(), engine.crcErrors());
    QCOMPARE(table->value(QStringLiteral("malformed")).toULongLong(), engine.malformed());
    QCOMPARE(table->value(QStringLiteral("late")).toULongLong(), engine.late());
    QCOMPARE(table->value(QStringLiteral("link_errors")).toULongLong(), engine.linkErrors());
    QCOMPARE(table->value(QStringLiteral("latency_min")).toDouble(), double(engine.latency().minNs()));
    QCOMPARE(table->value(QStringLiteral("latency_median")).toDouble(), double(engine.latency().medianNs()));
    QCOMPARE(table->value(QStringLiteral("latency_p99")).toDouble(), double(engine.latency().percentileNs(99)));
    QCOMPARE(table->value(QStringLiteral("latency_max")).toDouble(), double(engine.latency().maxNs()));
    // Five labelled lines: min, median, p95, p99, max.
    QCOMPARE(panel->plot()->itemCount(), 10);
    QVERIFY(guitest::saveShot(panel, QStringLiteral("latency-histogram-poll.png")));

    // The poll's item 0 is the whole poll.
    panel->setItem(0);
    QCOMPARE(barTotal(panel->histogram()), engine.ok());
    sim.stop();
}

void TestLatencyHistogram::bins_data()
{
    QTest::addColumn<LatencyBinning::Scale>("scale");
    QTest::newRow("linear") << LatencyBinning::Scale::Linear;
    QTest::newRow("logarithmic") << LatencyBinning::Scale::Logarithmic;
}

void TestLatencyHistogram::bins()
{
    QFETCH(LatencyBinning::Scale, scale);
    LatencyRuns runs;
    LatencyHistogramPanel panel(&runs);
    panel.resize(1100, 420);
    // 2000 answers from 200 us to 200 ms, and 7 timeouts (counted, no latency).
    runs.addTransactions(logSpread(2000, 2e5, 2e8));
    runs.addTransactions(QList<Transaction>(7, timedOut()));
    panel.setScale(scale);
    const Histogram &h = panel.histogram();
    QVERIFY(h.isValid());
    QCOMPARE(barTotal(h) + h.underflow() + h.overflow(), quint64(2000));
    QCOMPARE(h.underflow() + h.overflow(), quint64(0));
    QVERIFY(h.binCount() > 5);
    QVERIFY(h.binCount() <= LatencyBinning::kMaxBins + 1);
    const std::vector<double> &edges = h.edgesNs();
    const bool log = scale == LatencyBinning::Scale::Logarithmic;
    QCOMPARE(h.isLogarithmic(), log);
    if (log) {
        // A constant factor between edges (the last edge may be cut at the range's end).
        const double ratio = edges[1] / edges[0];
        QVERIFY(ratio > 1.05);
        for (std::size_t i = 1; i + 1 < edges.size() - 1; ++i)
            QVERIFY2(std::abs(edges[i + 1] / edges[i] - ratio) < 1e-6, qPrintable(QString::number(i)));
        QCOMPARE(panel.plot()->xAxis->scaleType(), QCPAxis::stLogarithmic);
        // Log bins put the tail's decades side by side: no bin holds most of the answers.
        QVERIFY(*std::max_element(h.counts().begin(), h.counts().end()) < 2000 / 4);
    } else {
        const double width = edges[1] - edges[0];
        for (std::size_t i = 1; i < edges.size(); ++i)
            QCOMPARE(edges[i] - edges[i - 1], width);
        QCOMPARE(panel.plot()->xAxis->scaleType(), QCPAxis::stLinear);
        // The engine's automatic bins, counted from the sorted latencies the same way.
        const Histogram engine = runs.statistics(LatencyRuns::Current, -1).histogram();
        QCOMPARE(edges, engine.edgesNs());
        QCOMPARE(h.counts(), engine.counts());
        // Linear bins put half the answers (those under 6.3 ms) in the first bin or two.
        QVERIFY(h.counts()[0] + h.counts()[1] >= 1000);
    }
    QCOMPARE(panel.statisticsModel()->value(QStringLiteral("count")).toULongLong(), quint64(2007));
    QCOMPARE(panel.statisticsModel()->value(QStringLiteral("timeouts")).toULongLong(), quint64(7));
    QVERIFY(guitest::saveShot(&panel, QStringLiteral("latency-histogram-%1.png").arg(QString::fromLatin1(QTest::currentDataTag()))));
}

void TestLatencyHistogram::itemOrOverall()
{
    LatencyRuns runs;
    LatencyHistogramPanel panel(&runs);
    runs.addTransactions(logSpread(300, 1e6, 3e6, 0));     // item 0: 1-3 ms
    runs.addTransactions(logSpread(500, 20e6, 40e6, 1));   // item 1: 20-40 ms
    runs.addTransactions({answered(5e6, 1, TransactionStatus::Exception, 0x02), timedOut(1)});
    panel.redrawNow();
    QCOMPARE(panel.item(), -1);
    QCOMPARE(barTotal(panel.histogram()), quint64(801)); // an exception is an answer: it has a latency
    QCOMPARE(panel.statisticsModel()->value(QStringLiteral("count")).toULongLong(), quint64(802));
    auto *items = panel.findChild<QComboBox *>(QStringLiteral("itemChoice"));
    QVERIFY(items);
    QCOMPARE(items->count(), 3); // overall, item 0, item 1

    panel.setItem(0);
    QCOMPARE(barTotal(panel.histogram()), quint64(300));
    QVERIFY(panel.histogram().edgesNs().back() <= 3.5e6); // bins of 200 us up to 3.2 ms
    QCOMPARE(panel.statisticsModel()->value(QStringLiteral("count")).toULongLong(), quint64(300));
    QCOMPARE(panel.statisticsModel()->rowOf(QStringLiteral("exception 0x02")), -1);

    panel.setItem(1);
    QCOMPARE(barTotal(panel.histogram()), quint64(501));
    QVERIFY(panel.histogram().edgesNs().front() >= 4e6);
    QCOMPARE(panel.statisticsModel()->value(QStringLiteral("exception 0x02")).toULongLong(), quint64(1));
    QCOMPARE(panel.statisticsModel()->value(QStringLiteral("timeouts")).toULongLong(), quint64(1));
    QCOMPARE(items->currentData().toInt(), 1);
}

void TestLatencyHistogram::compareOverlaysTwoRuns()
{
    LatencyRuns runs;
    LatencyComparePanel compare(&runs);
    compare.resize(1100, 420);
    // The reference: answers at 2-4 ms; the current run after it: 3-8 ms and a timeout.
    runs.addTransactions(logSpread(400, 2e6, 4e6));
    runs.keepReference();
    runs.clearCurrent();
    runs.addTransactions(logSpread(600, 3e6, 8e6));
    runs.addTransactions({timedOut()});
    compare.setSides({LatencyRuns::Current, -1}, {LatencyRuns::Reference, -1});
    QCOMPARE(compare.histograms().size(), 2);
    const Histogram &current = compare.histograms().at(0);
    const Histogram &reference = compare.histograms().at(1);
    QCOMPARE(current.edgesNs(), reference.edgesNs()); // common bins
    QCOMPARE(barTotal(current), quint64(600));
    QCOMPARE(barTotal(reference), quint64(400));
    QCOMPARE(compare.plot()->graphCount(), 2);
    QVERIFY(compare.plot()->legend->visible());
    QCOMPARE(compare.plot()->legend->itemCount(), 2);
    QVERIFY(compare.plot()->graph(0)->name().contains(runs.title(LatencyRuns::Current)));
    QVERIFY(compare.plot()->graph(1)->name().contains(runs.title(LatencyRuns::Reference)));

    const LatencyStatisticsModel *table = compare.statisticsModel();
    QCOMPARE(table->columnCount(), 3);
    QCOMPARE(table->value(QStringLiteral("count"), 0).toULongLong(), quint64(601));
    QCOMPARE(table->value(QStringLiteral("count"), 1).toULongLong(), quint64(400));
    QCOMPARE(table->value(QStringLiteral("timeouts"), 0).toULongLong(), quint64(1));
    QCOMPARE(table->value(QStringLiteral("latency_max"), 1).toDouble(), 4e6);
    QVERIFY(guitest::saveShot(&compare, QStringLiteral("latency-compare.png")));

    // Two request items of one run, on logarithmic bins.
    runs.addTransactions(logSpread(200, 10e6, 30e6, 1));
    compare.setScale(LatencyBinning::Scale::Logarithmic);
    compare.setSides({LatencyRuns::Current, 0}, {LatencyRuns::Current, 1});
    QCOMPARE(barTotal(compare.histograms().at(0)), quint64(600));
    QCOMPARE(barTotal(compare.histograms().at(1)), quint64(200));
    QVERIFY(compare.histograms().at(0).isLogarithmic());
    QCOMPARE(compare.histograms().at(0).edgesNs(), compare.histograms().at(1).edgesNs());
    QCOMPARE(compare.plot()->graphCount(), 2);
    auto *first = compare.findChild<QComboBox *>(QStringLiteral("firstChoice"));
    QVERIFY(first);
    QCOMPARE(first->count(), 5); // current: overall, items 0 and 1; reference: overall, item 0
    QVERIFY(guitest::saveShot(&compare, QStringLiteral("latency-compare-items-log.png")));
}

void TestLatencyHistogram::redrawsAreBatched()
{
    LatencyRuns runs;
    LatencyHistogramPanel panel(&runs);
    const int before = panel.redrawCount();
    for (int batch = 0; batch < 100; ++batch)
        runs.addTransactions(logSpread(10, 1e6, 2e6));
    QCOMPARE(panel.redrawCount(), before); // nothing drawn per batch...
    QTRY_COMPARE_WITH_TIMEOUT(panel.redrawCount(), before + 1, 5000); // ...one redraw for them all
    QCOMPARE(barTotal(panel.histogram()), quint64(1000));
    QTest::qWait(2 * LatencyHistogramPanel::kRedrawMs);
    QCOMPARE(panel.redrawCount(), before + 1); // and none while nothing changes
}

void TestLatencyHistogram::captureIsShown()
{
    LatencyRuns runs;
    LatencyHistogramPanel panel(&runs);
    runs.addTransactions(logSpread(50, 1e6, 2e6));
    panel.showTransactions(QStringLiteral("plant.pcapng"), logSpread(70, 5e6, 9e6));
    QCOMPARE(panel.run(), LatencyRuns::Capture);
    QCOMPARE(barTotal(panel.histogram()), quint64(70));
    auto *choice = panel.findChild<QComboBox *>(QStringLiteral("runChoice"));
    QVERIFY(choice);
    QCOMPARE(choice->count(), 2);
    QVERIFY(choice->currentText().contains(QLatin1String("plant.pcapng")));
    // New poll transactions do not disturb the capture shown.
    runs.addTransactions(logSpread(10, 1e6, 2e6));
    panel.redrawNow();
    QCOMPARE(barTotal(panel.histogram()), quint64(70));
    panel.setRun(LatencyRuns::Current);
    QCOMPARE(barTotal(panel.histogram()), quint64(60));
}

void TestLatencyHistogram::statisticsModel()
{
    LatencyStatisticsModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    StatisticsSet set;
    Statistics empty;
    model.setColumns({{QStringLiteral("a"), &empty}});
    QCOMPARE(model.columnCount(), 2);
    QVERIFY(!model.value(QStringLiteral("latency_min")).isValid()); // no answers: no latency
    QCOMPARE(model.index(model.rowOf(QStringLiteral("latency_min")), 1).data().toString(), QStringLiteral("–"));
    const int rows = model.rowCount();
    set.add(answered(1500000));
    set.add(answered(2500000, 0, TransactionStatus::Exception, 0x04));
    model.setColumns({{QStringLiteral("a"), &set.overall()}, {QStringLiteral("b"), &empty}});
    QCOMPARE(model.rowCount(), rows + 1); // the exception code's row
    QCOMPARE(model.columnCount(), 3);
    QCOMPARE(model.headerData(2, Qt::Horizontal).toString(), QStringLiteral("b"));
    QCOMPARE(model.value(QStringLiteral("exception 0x04")).toULongLong(), quint64(1));
    QCOMPARE(model.value(QStringLiteral("exception 0x04"), 1).toULongLong(), quint64(0));
    QCOMPARE(model.value(QStringLiteral("latency_mean")).toDouble(), 2e6);
    QCOMPARE(model.index(model.rowOf(QStringLiteral("latency_mean")), 1).data().toString(), QLocale().toString(2.0, 'f', 3) + QStringLiteral(" ms"));
    set.add(answered(3500000));
    model.setColumns({{QStringLiteral("a"), &set.overall()}, {QStringLiteral("c"), &empty}}); // same shape: dataChanged
    QCOMPARE(model.value(QStringLiteral("count")).toULongLong(), quint64(3));
    QCOMPARE(model.headerData(2, Qt::Horizontal).toString(), QStringLiteral("c"));
    const QString csv = TableCsv::toCsv(model);
    QVERIFY2(csv.startsWith(QLatin1String("Figure,a,c\r\n")), qPrintable(csv));
    QVERIFY2(csv.contains(QLatin1String("\r\nTransactions,3,0\r\n")), qPrintable(csv));
    const auto name = [&model](const char *key) {
        return model.index(model.rowOf(QLatin1String(key)), 0).data().toString();
    };
    QCOMPARE(name("latency_p99"), QStringLiteral("Latency p99")); // every sample kept: exact

    // Past the exact limit the percentiles come from bins: their rows say how close they are.
    Statistics binned;
    binned.setExactLatencyLimit(2);
    for (const qint64 ns : {1000000, 2000000, 3000000})
        binned.add(answered(ns));
    model.setColumns({{QStringLiteral("binned"), &binned}});
    QCOMPARE(name("latency_p99"), QStringLiteral("Latency p99 (within 0.1 %)"));
    QCOMPARE(name("latency_median"), QStringLiteral("Latency median (within 0.1 %)"));
    QCOMPARE(name("latency_max"), QStringLiteral("Latency max")); // min, max, mean stay exact
}

// Serial answers that came before the line could have carried them (a pty, a buffering USB
// adapter: issue 19) are measured from the write, and the window says so: a warning in the
// summary (the explanation in its tooltip) and a row of the table.
void TestLatencyHistogram::serialLineOutrun()
{
    LatencyRuns runs;
    LatencyHistogramPanel panel(&runs);
    auto *summary = panel.findChild<QLabel *>(QStringLiteral("latencySummary"));
    QVERIFY(summary);
    QList<Transaction> list;
    for (int i = 0; i < 10; ++i) {
        Transaction t = answered(10'000'000 + i * 1000);
        t.writeNs = t.sentNs;
        t.transmitNs = 8'333'333; // 8 bytes at 9600 baud
        t.outranLine = i < 4;
        list.append(t);
    }
    runs.addTransactions(list);
    panel.redrawNow();
    QVERIFY2(summary->text().contains(QLatin1String("latency from the computed end of transmission (6) or the write (4)")),
             qPrintable(summary->text()));
    QVERIFY2(summary->text().contains(QLatin1String("warning: 4 answers faster than the serial line")), qPrintable(summary->text()));
    QVERIFY(summary->toolTip().contains(QLatin1String("pseudo terminal")));
    QCOMPARE(panel.statisticsModel()->value(QStringLiteral("outran_line")).toULongLong(), quint64(4));

    LatencyRuns network;
    LatencyHistogramPanel plain(&network);
    network.addTransactions(logSpread(10, 1e6, 2e6));
    plain.redrawNow();
    auto *plainSummary = plain.findChild<QLabel *>(QStringLiteral("latencySummary"));
    QVERIFY(plainSummary->text().endsWith(QLatin1String("; latency from each request's write")));
    QVERIFY(plainSummary->toolTip().isEmpty());
    QCOMPARE(plain.statisticsModel()->rowOf(QStringLiteral("outran_line")), -1);
}

void TestLatencyHistogram::exports_data()
{
    QTest::addColumn<QString>("fileName");
    QTest::newRow("png") << QStringLiteral("latency-histogram-export.png");
    QTest::newRow("svg") << QStringLiteral("latency-histogram-export.svg");
    QTest::newRow("pdf") << QStringLiteral("latency-histogram-export.pdf");
    QTest::newRow("csv") << QStringLiteral("latency-statistics-export.csv");
}

void TestLatencyHistogram::exports()
{
    QFETCH(QString, fileName);
    LatencyRuns runs;
    LatencyHistogramPanel panel(&runs);
    panel.resize(1000, 400);
    runs.addTransactions(logSpread(500, 1e6, 9e6));
    panel.redrawNow();
    const QString path = guitest::outputPath(fileName);
    QFile::remove(path);
    QString error;
    if (fileName.endsWith(QLatin1String(".csv"))) {
        QVERIFY2(TableCsv::save(*panel.statisticsModel(), path, &error), qPrintable(error));
    } else {
        const bool saved = panel.exportMenu()->saveTo(path, &error);
        if (!saved && fileName.endsWith(QLatin1String(".svg")) && error.contains(QLatin1String("SVG")))
            QSKIP("this build has no Qt SVG (Debian: qt6-svg-dev)");
        QVERIFY2(saved, qPrintable(error));
    }
    QVERIFY(QFileInfo(path).size() > 200);
    panel.exportMenu()->copyToClipboard();
}

QTEST_MAIN(TestLatencyHistogram)
#include "tst_latencyhistogram.moc"
