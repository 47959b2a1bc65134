// PlotCursor: what it reads from line graphs (the latest sample at or before the cursor) and from
// point graphs (the nearest point within reach), placed in code and by a mouse click.
#include "guitestsupport.h"
#include "common/plotcursor.h"

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>
#include <qcustomplot.h>

using namespace mbscope;

class TestPlotCursor : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void lineGraphHoldsTheLatestSample_data();
    void lineGraphHoldsTheLatestSample();
    void pointGraphTakesTheNearestPoint_data();
    void pointGraphTakesTheNearestPoint();
    void readoutNamesEachGraph();
    void clickPinsAndDoubleClickFollows();
};

namespace {

// A plot 600 px wide over x 0..10, a step line (1, 2, 3 at x 0, 4, 8) and points at 2 and 6.
struct TestPlot {
    QCustomPlot plot;
    QCPGraph *line = nullptr;
    QCPGraph *points = nullptr;
    PlotCursor *cursor = nullptr;

    TestPlot()
    {
        plot.resize(600, 400);
        line = plot.addGraph();
        line->setName(QStringLiteral("level"));
        line->setLineStyle(QCPGraph::lsStepLeft);
        line->setData({0, 4, 8}, {1, 2, 3});
        points = plot.addGraph();
        points->setName(QStringLiteral("events"));
        points->setLineStyle(QCPGraph::lsNone);
        points->setScatterStyle(QCPScatterStyle::ssDisc);
        points->setData({2, 6}, {20, 60});
        plot.xAxis->setRange(0, 10);
        plot.yAxis->setRange(0, 70);
        cursor = new PlotCursor(&plot);
        plot.replot();
    }
};

} // namespace

void TestPlotCursor::lineGraphHoldsTheLatestSample_data()
{
    QTest::addColumn<double>("x");
    QTest::addColumn<bool>("has");
    QTest::addColumn<double>("value");
    QTest::newRow("before the first sample") << -1.0 << false << 0.0;
    QTest::newRow("on the first sample") << 0.0 << true << 1.0;
    QTest::newRow("between samples: the earlier one") << 3.9 << true << 1.0;
    QTest::newRow("on the second sample") << 4.0 << true << 2.0;
    QTest::newRow("after the last sample") << 100.0 << true << 3.0;
}

void TestPlotCursor::lineGraphHoldsTheLatestSample()
{
    QFETCH(double, x);
    QFETCH(bool, has);
    QFETCH(double, value);
    TestPlot t;
    double read = -99;
    QCOMPARE(t.cursor->valueAt(t.line, x, &read), has);
    if (has)
        QCOMPARE(read, value);
}

void TestPlotCursor::pointGraphTakesTheNearestPoint_data()
{
    // 600 px over 10 units (less the axis margins): one unit is about 50 px, so 0.3 is within
    // reach (24 px) and 1.5 is not.
    QTest::addColumn<double>("x");
    QTest::addColumn<bool>("has");
    QTest::addColumn<double>("value");
    QTest::newRow("on a point") << 2.0 << true << 20.0;
    QTest::newRow("just after a point") << 2.3 << true << 20.0;
    QTest::newRow("just before the next") << 5.7 << true << 60.0;
    QTest::newRow("between, out of reach") << 4.0 << false << 0.0;
    QTest::newRow("far after the last") << 9.0 << false << 0.0;
}

void TestPlotCursor::pointGraphTakesTheNearestPoint()
{
    QFETCH(double, x);
    QFETCH(bool, has);
    QFETCH(double, value);
    TestPlot t;
    double read = -99;
    QCOMPARE(t.cursor->valueAt(t.points, x, &read), has);
    if (has)
        QCOMPARE(read, value);
}

void TestPlotCursor::readoutNamesEachGraph()
{
    TestPlot t;
    QSignalSpy changed(t.cursor, &PlotCursor::readoutChanged);
    t.cursor->setXFormatter([](double x) { return QStringLiteral("x = %1").arg(x); });
    t.cursor->setValueFormatter(t.line, [](double v) { return QStringLiteral("%1 V").arg(v); });
    QVERIFY(t.cursor->readout().isEmpty()); // not shown yet
    t.cursor->setX(6.1);
    QVERIFY(t.cursor->isPinned());
    QCOMPARE(t.cursor->readout(), QStringLiteral("x = 6.1\nlevel: 2 V\nevents: 60"));
    QCOMPARE(changed.count(), 1);
    // New data changes the readout at the next replot without the cursor moving.
    t.line->addData(5, 7);
    t.plot.replot();
    QCOMPARE(t.cursor->readout(), QStringLiteral("x = 6.1\nlevel: 7 V\nevents: 60"));
    QCOMPARE(changed.count(), 2);
    t.plot.resize(700, 420);
    QVERIFY(guitest::saveShot(&t.plot, QStringLiteral("plotcursor.png")));
}

void TestPlotCursor::clickPinsAndDoubleClickFollows()
{
    TestPlot t;
    t.plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&t.plot));
    const int pixel = int(t.plot.xAxis->coordToPixel(8.5));
    const int y = int(t.plot.yAxis->coordToPixel(30));
    QTest::mouseMove(&t.plot, QPoint(pixel, y));
    QTest::mouseClick(&t.plot, Qt::LeftButton, {}, QPoint(pixel, y));
    QVERIFY(t.cursor->isPinned());
    QVERIFY2(qAbs(t.cursor->x() - 8.5) < 0.05, qPrintable(QString::number(t.cursor->x())));
    QVERIFY2(t.cursor->readout().contains(QLatin1String("level: 3")), qPrintable(t.cursor->readout()));
    QTest::mouseDClick(&t.plot, Qt::LeftButton, {}, QPoint(pixel, y));
    QVERIFY(!t.cursor->isPinned());
}

QTEST_MAIN(TestPlotCursor)
#include "tst_plotcursor.moc"
