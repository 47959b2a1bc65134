// Tools > Scan (ScanDialog) offscreen against the embedded simulator (rosrao-gamma: units 1 and 3
// behind an rtu-tcp device server, 0B for the rest): the list fills as ids are asked, the progress
// bar follows, Stop ends a scan, found units become watches (clipboard JSON and
// watchesRequested()), and the window's Tools menu opens the dialog on its current target.

#include "discovery/scandialog.h"
#include "discovery/scanresultmodel.h"
#include "shell/mainwindow.h"
#include <QtWidgets/QStatusBar>
#include "watch/watchworkspace.h"
#include "sim/embeddedsimulator.h"
#include "link/connectionbar.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtGui/QAction>
#include <QtGui/QClipboard>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>

using namespace mbscope;

class TestScanDialog : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void scanListsEveryId();
    void stopEndsTheScan();
    void badTargetIsSaid();
    void toolsMenuOpensIt();

private:
    EmbeddedSimulator m_sim;
    LinkUrl m_url;
};

void TestScanDialog::initTestCase()
{
    const EmbeddedSimulator::Started started = m_sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    m_url = started.url;
}

void TestScanDialog::scanListsEveryId()
{
    ScanDialog dialog;
    QAbstractItemModelTester tester(dialog.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    dialog.setTarget(m_url);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanLastUnit"))->setValue(6);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanAddress"))->setValue(0x79);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanQuantity"))->setValue(4);
    auto *copy = dialog.findChild<QPushButton *>(QStringLiteral("scanCopyWatches"));
    QVERIFY(!copy->isEnabled());
    dialog.show();
    QSignalSpy finished(&dialog, &ScanDialog::scanFinished);
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("scanStart")), Qt::LeftButton);
    QVERIFY(dialog.isRunning());
    QVERIFY(!dialog.findChild<QPushButton *>(QStringLiteral("scanStart"))->isEnabled());
    QVERIFY(finished.wait(20000));
    QCOMPARE(finished.first().first().value<ScanEnd>(), ScanEnd::Completed);
    QCOMPARE(dialog.model()->rowCount(), 6);
    QCOMPARE(dialog.findChild<QProgressBar *>(QStringLiteral("scanProgress"))->value(), 6);
    const auto kind = [&](int row) { return dialog.model()->probes().at(row).kind; };
    QCOMPARE(kind(0), UnitProbeKind::Answers);
    QCOMPARE(kind(1), UnitProbeKind::GatewayTargetFailed);
    QCOMPARE(kind(2), UnitProbeKind::Answers);
    QCOMPARE(dialog.model()->index(0, ScanResultModel::ResultColumn).data().toString(), ScanResultModel::kindText(UnitProbeKind::Answers));
    QVERIFY(dialog.model()->index(1, ScanResultModel::DetailColumn).data().toString().contains(QStringLiteral("0B")));
    QVERIFY(copy->isEnabled());

    // Every found unit without a selection; the selected one with.
    QCOMPARE(dialog.watches().size(), 2);
    dialog.findChild<QTableView *>(QStringLiteral("scanResults"))->selectRow(2);
    const QList<WatchDefinition> selected = dialog.watches();
    QCOMPARE(selected.size(), 1);
    QCOMPARE(selected.first().unit, quint8(3));
    QCOMPARE(selected.first().address, quint16(0x79));
    QCOMPARE(selected.first().quantity, quint16(4));
    QCOMPARE(selected.first().target, m_url.toString());
    QTest::mouseClick(copy, Qt::LeftButton);
    const QJsonArray copied = QJsonDocument::fromJson(QGuiApplication::clipboard()->text().toUtf8()).array();
    QCOMPARE(copied.size(), 1);
    QCOMPARE(copied.first().toObject().value(QStringLiteral("unit")).toInt(), 3);
    QSignalSpy requested(&dialog, &ScanDialog::watchesRequested);
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("scanAddWatches")), Qt::LeftButton);
    QCOMPARE(requested.size(), 1);
    QCOMPARE(requested.first().first().value<QList<WatchDefinition>>().size(), 1);

    if (const QString path = qEnvironmentVariable("MBSCOPE_SCAN_SCREENSHOT"); !path.isEmpty())
        dialog.grab().save(path);
}

void TestScanDialog::stopEndsTheScan()
{
    ScanDialog dialog;
    dialog.setTarget(m_url);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanGap"))->setValue(40);
    dialog.show();
    QSignalSpy finished(&dialog, &ScanDialog::scanFinished);
    dialog.start();
    QTRY_VERIFY_WITH_TIMEOUT(dialog.model()->rowCount() >= 3, 10000);
    QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("scanStop")), Qt::LeftButton);
    QVERIFY(finished.wait(5000) || finished.size() == 1);
    QCOMPARE(finished.first().first().value<ScanEnd>(), ScanEnd::Stopped);
    QVERIFY(!dialog.isRunning());
    const int rows = dialog.model()->rowCount();
    QVERIFY(rows < 247);
    QTest::qWait(200);
    QCOMPARE(dialog.model()->rowCount(), rows); // nothing more after Stop
    QVERIFY(dialog.findChild<QPushButton *>(QStringLiteral("scanStart"))->isEnabled());
}

void TestScanDialog::badTargetIsSaid()
{
    ScanDialog dialog;
    dialog.setTarget(m_url);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanFirstUnit"))->setValue(0);
    QVERIFY(!dialog.settings()); // unit 0 on an RTU framing is the broadcast
    QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("scanStatus"))->text().contains(QStringLiteral("broadcast")));
    dialog.start();
    QVERIFY(!dialog.isRunning());
    QCOMPARE(dialog.model()->rowCount(), 0);
}

void TestScanDialog::toolsMenuOpensIt()
{
    MainWindow window;
    window.connectionBar()->setUrl(m_url);
    auto *action = window.findChild<QAction *>(QStringLiteral("scanAction"));
    QVERIFY(action);
    action->trigger();
    ScanDialog *dialog = window.scanDialog();
    QVERIFY(dialog->isVisible());
    const std::optional<UnitScanSettings> settings = dialog->settings();
    QVERIFY(settings);
    QCOMPARE(settings->url.port, m_url.port);
    QCOMPARE(settings->url.kind, m_url.kind);
    QCOMPARE(settings->lastUnit, 247);

    // "Add as watches" puts the units found in the workspace, twice under names of their own.
    QSignalSpy finished(dialog, &ScanDialog::scanFinished);
    dialog->findChild<QSpinBox *>(QStringLiteral("scanLastUnit"))->setValue(5);
    dialog->findChild<QSpinBox *>(QStringLiteral("scanAddress"))->setValue(0x79);
    dialog->findChild<QSpinBox *>(QStringLiteral("scanQuantity"))->setValue(4);
    dialog->start();
    QVERIFY(finished.wait(20000));
    QVERIFY(dialog->model()->rowCount() > 0);
    const int found = int(dialog->watches().size());
    QVERIFY(found >= 1);
    auto *add = dialog->findChild<QPushButton *>(QStringLiteral("scanAddWatches"));
    QTest::mouseClick(add, Qt::LeftButton);
    QTest::mouseClick(add, Qt::LeftButton);
    QCOMPARE(window.watchWorkspace()->count(), 2 * found);
    QStringList names;
    for (const WatchDefinition &w : window.watchWorkspace()->watches().watches)
        names.append(w.name);
    names.removeDuplicates();
    QCOMPARE(int(names.size()), 2 * found);
    QVERIFY(window.statusBar()->currentMessage().contains(QLatin1String("from the scan")));
    dialog->close();
}

QTEST_MAIN(TestScanDialog)
#include "tst_scandialog.moc"
