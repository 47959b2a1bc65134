// PlotSaver / PlotExportMenu: every plot in the window saves as PNG, SVG or PDF by the file name
// and copies to the clipboard; TableCsv: every table exports as RFC 4180 CSV.
#include "common/plotexportmenu.h"
#include "common/plotsaver.h"
#include "common/tablecsv.h"

#include <QtCore/QTemporaryDir>
#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtGui/QStandardItemModel>
#include <QtTest/QtTest>
#include <qcustomplot.h>

using namespace mbscope;

class TestPlotExport : public QObject
{
    Q_OBJECT

private slots:
    void savesByFileName_data();
    void savesByFileName();
    void refusesUnknownFormat_data();
    void refusesUnknownFormat();
    void copiesToClipboard();
    void csvEscaping_data();
    void csvEscaping();
    void csvSaveReportsUnwritablePath();

private:
    static void drawSomething(QCustomPlot &plot)
    {
        plot.resize(400, 300);
        QCPGraph *graph = plot.addGraph();
        graph->setData({0, 1, 2, 3}, {1, 4, 2, 5});
        plot.rescaleAxes();
    }
};

void TestPlotExport::savesByFileName_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("magic");
    QTest::newRow("png") << QStringLiteral("plot.png") << QByteArray("\x89PNG");
    QTest::newRow("PNG upper case") << QStringLiteral("PLOT.PNG") << QByteArray("\x89PNG");
    QTest::newRow("pdf") << QStringLiteral("plot.pdf") << QByteArray("%PDF");
    QTest::newRow("svg") << QStringLiteral("plot.svg") << QByteArray("<?xml");
}

void TestPlotExport::savesByFileName()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, magic);
    if (name.endsWith(QLatin1String(".svg")) && !PlotSaver::formatProblem(name).isEmpty())
        QSKIP("built without Qt SVG (Debian: qt6-svg-dev)");
    QTemporaryDir dir;
    QCustomPlot plot;
    drawSomething(plot);
    PlotExportMenu menu(&plot, QStringLiteral("latency"));
    QString error;
    const QString path = dir.filePath(name);
    QVERIFY2(menu.saveTo(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray head = file.read(64);
    QVERIFY2(head.startsWith(magic), head.toHex(' ').constData());
    QVERIFY(file.size() > 200);
}

void TestPlotExport::refusesUnknownFormat_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("gif") << QStringLiteral("plot.gif");
    QTest::newRow("no extension") << QStringLiteral("plot");
    QTest::newRow("png inside the name") << QStringLiteral("plot.png.txt");
}

void TestPlotExport::refusesUnknownFormat()
{
    QFETCH(QString, name);
    QTemporaryDir dir;
    QCustomPlot plot;
    drawSomething(plot);
    QString error;
    QVERIFY(!PlotSaver::save(plot, dir.filePath(name), 400, 300, &error));
    QVERIFY2(error.contains(name) && error.contains(QLatin1String(".png")), qPrintable(error));
    QVERIFY(!QFile::exists(dir.filePath(name)));
}

void TestPlotExport::copiesToClipboard()
{
    QCustomPlot plot;
    drawSomething(plot);
    PlotExportMenu menu(&plot, QStringLiteral("latency"));
    QGuiApplication::clipboard()->clear();
    menu.copyAction()->trigger();
    const QPixmap copied = QGuiApplication::clipboard()->pixmap();
    QVERIFY(!copied.isNull());
    QCOMPARE(copied.size() / copied.devicePixelRatio(), plot.size());
}

void TestPlotExport::csvEscaping_data()
{
    QTest::addColumn<QString>("cell");
    QTest::addColumn<QString>("field");
    QTest::newRow("plain") << QStringLiteral("12.5") << QStringLiteral("12.5");
    QTest::newRow("comma") << QStringLiteral("1,2") << QStringLiteral("\"1,2\"");
    QTest::newRow("quote") << QStringLiteral("say \"hi\"") << QStringLiteral("\"say \"\"hi\"\"\"");
    QTest::newRow("line break") << QStringLiteral("a\nb") << QStringLiteral("\"a\nb\"");
    QTest::newRow("empty") << QString() << QString();
    QTest::newRow("non-ASCII") << QStringLiteral("µs ≥ 5") << QStringLiteral("µs ≥ 5");
}

void TestPlotExport::csvEscaping()
{
    QFETCH(QString, cell);
    QFETCH(QString, field);
    QStandardItemModel model(1, 2);
    model.setHorizontalHeaderLabels({QStringLiteral("name"), QStringLiteral("value, ms")});
    model.setItem(0, 0, new QStandardItem(QStringLiteral("p95")));
    model.setItem(0, 1, new QStandardItem(cell));
    QCOMPARE(TableCsv::toCsv(model), QStringLiteral("name,\"value, ms\"\r\np95,") + field + QStringLiteral("\r\n"));

    QTemporaryDir dir;
    QString error;
    QVERIFY2(TableCsv::save(model, dir.filePath(QStringLiteral("t.csv")), &error), qPrintable(error));
    QFile file(dir.filePath(QStringLiteral("t.csv")));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(file.readAll()), TableCsv::toCsv(model));
}

void TestPlotExport::csvSaveReportsUnwritablePath()
{
    QStandardItemModel model(1, 1);
    QString error;
    const QString path = QStringLiteral("/nonexistent-dir/t.csv");
    QVERIFY(!TableCsv::save(model, path, &error));
    QVERIFY2(error.contains(path), qPrintable(error));
}

QTEST_MAIN(TestPlotExport)
#include "tst_plotexport.moc"
