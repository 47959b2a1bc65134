// Tools > Scan (ScanDialog) offscreen against the embedded simulator (rosrao-gamma: units 1 and 3
// behind an rtu-tcp device server, 0B for the rest): the list fills as ids are asked, the progress
// bar follows, Stop ends a scan, found units become watches (clipboard JSON and
// watchesRequested()), and the window's Tools menu opens the dialog on its current target. "Map
// unit" maps a found unit's registers, and the map saved as a profile draft is served by a second
// simulator that maps the same.

#include "discovery/mapresulttree.h"
#include "discovery/mapscanner.h"
#include "job/job.h"
#include "discovery/linescandialog.h"
#include "discovery/inferdialog.h"
#include "discovery/mapscandialog.h"
#include "discovery/scandialog.h"
#include "discovery/timingresulttree.h"
#include "discovery/timingscandialog.h"
#include "discovery/scanresultmodel.h"
#include "profile/profileloader.h"
#include "guitestsupport.h"
#include "shell/mainwindow.h"
#include "shell/translationloader.h"
#include <QtWidgets/QStatusBar>
#include "watch/watchworkspace.h"
#include "sim/embeddedsimulator.h"
#include "link/connectionbar.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtGui/QAction>
#include <QtGui/QClipboard>
#include <QtCore/QProcess>
#include <QtCore/QScopeGuard>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtCore/QTimer>
#include <QtWidgets/QTreeWidget>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>

using namespace mbscope;

namespace {

// Clicks button, whose slot opens a file dialog, and picks path in it; whether it was picked.
bool clickPickingFile(QPushButton *button, const QString &path)
{
    bool picked = false;
    QTimer::singleShot(0, button, [&] {
        QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()));
        auto *files = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        files->selectFile(path);
        QMetaObject::invokeMethod(files, "accept");
        picked = true;
    });
    QTest::mouseClick(button, Qt::LeftButton);
    return picked;
}

bool writeTestFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

} // namespace

class TestScanDialog : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void scanListsEveryId();
    void stopEndsTheScan();
    void badTargetIsSaid();
    void toolsMenuOpensIt();
    void mapUnitClonesIt();
    void mapScanLeavesTheWindowLoopAlone();
    void timingOfAFoundUnit();
    void serialSettingsFound();
    void accessKeysAreUnique_data();
    void accessKeysAreUnique();

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
    QCOMPARE(finished.first().first().value<JobEnd>(), JobEnd::Completed);
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

    // "Record in profile…": the units that answered go into a profile picked in the file dialog,
    // and unknownUnit from what the others got (0B: exception), as scan --units --profile-out.
    QTemporaryDir dir;
    const QString profilePath = dir.filePath(QStringLiteral("gateway.json"));
    QVERIFY(writeTestFile(profilePath, R"({"name": "gateway", "units": [{"id": 1}]})"));
    auto *record = dialog.findChild<QPushButton *>(QStringLiteral("scanRecordUnits"));
    QVERIFY(record->isEnabled());
    QVERIFY(clickPickingFile(record, profilePath));
    QFile saved(profilePath);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    const QJsonObject profile = QJsonDocument::fromJson(saved.readAll()).object();
    QCOMPARE(profile.value(QStringLiteral("units")).toArray().size(), 2);
    QCOMPARE(profile.value(QStringLiteral("units")).toArray().at(1).toObject().value(QStringLiteral("id")).toInt(), 3);
    QCOMPARE(profile.value(QStringLiteral("unknownUnit")).toString(), QStringLiteral("exception"));
    const QString said = dialog.findChild<QLabel *>(QStringLiteral("scanStatus"))->text();
    QVERIFY2(said.startsWith(QLatin1String("Recorded in ")) && said.contains(QLatin1String("units answering: 1, 3 (1 added)")),
             qPrintable(said));

    if (const QString path = qEnvironmentVariable("MBSCOPE_SCAN_SCREENSHOT"); !path.isEmpty())
        dialog.grab().save(path);

    // A file that is no profile is left alone (an empty object was written back without a name,
    // which the simulator then refused).
    const QString emptyPath = dir.filePath(QStringLiteral("empty.json"));
    QVERIFY(writeTestFile(emptyPath, "{}"));
    QVERIFY(clickPickingFile(record, emptyPath));
    QFile empty(emptyPath);
    QVERIFY(empty.open(QIODevice::ReadOnly));
    QCOMPARE(empty.readAll(), QByteArray("{}"));
    const QString refused = dialog.findChild<QLabel *>(QStringLiteral("scanStatus"))->text();
    QVERIFY2(refused.contains(QLatin1String("is not a profile the simulator loads, so nothing was recorded in it: "))
                 && refused.contains(QLatin1String("'name' is missing")),
             qPrintable(refused));
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
    QCOMPARE(finished.first().first().value<JobEnd>(), JobEnd::Stopped);
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

// Maps unit 1's holding registers 100-160 through the dialog's fields and Start button.
static RegisterMap mapThroughDialog(MapScanDialog *map)
{
    map->findChild<QSpinBox *>(QStringLiteral("mapFirstAddress"))->setValue(100);
    map->findChild<QSpinBox *>(QStringLiteral("mapLastAddress"))->setValue(160);
    for (const int table : {1, 2, 4})
        map->findChild<QCheckBox *>(QStringLiteral("mapTable%1").arg(table))->setChecked(false);
    map->findChild<QCheckBox *>(QStringLiteral("mapOptional"))->setChecked(false);
    QSignalSpy finished(map, &MapScanDialog::scanFinished);
    // The scan runs to its end inside the click (local event loops keep the dialog live).
    QTest::mouseClick(map->findChild<QPushButton *>(QStringLiteral("mapStart")), Qt::LeftButton);
    if (finished.isEmpty() && !finished.wait(30000))
        return {};
    return map->map().value_or(RegisterMap{});
}

void TestScanDialog::mapUnitClonesIt()
{
    ScanDialog dialog;
    dialog.setTarget(m_url);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanLastUnit"))->setValue(3);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanAddress"))->setValue(0x79);
    auto *mapButton = dialog.findChild<QPushButton *>(QStringLiteral("scanMapUnit"));
    QVERIFY(!mapButton->isEnabled()); // nothing found yet
    QSignalSpy finished(&dialog, &ScanDialog::scanFinished);
    dialog.show();
    dialog.start();
    QVERIFY(finished.wait(20000));
    QVERIFY(mapButton->isEnabled());
    dialog.findChild<QTableView *>(QStringLiteral("scanResults"))->selectRow(2); // unit 3
    QTest::mouseClick(mapButton, Qt::LeftButton);
    auto *map = dialog.findChild<MapScanDialog *>();
    QVERIFY(map && map->isVisible());
    QCOMPARE(map->settings()->unit, quint8(3));
    QCOMPARE(map->settings()->url.port, m_url.port);
    QVERIFY(!map->findChild<QPushButton *>(QStringLiteral("mapSaveDraft"))->isEnabled());

    const RegisterMap found = mapThroughDialog(map);
    QCOMPARE(found.unit, quint8(3));
    const TableMap *holding = found.table(3);
    QVERIFY(holding);
    QCOMPARE(holding->blocks.size(), 1);
    QCOMPARE(int(holding->blocks.first().address), 0x79);
    QCOMPARE(holding->blocks.first().last(), 0x8E); // settings, gate counts and results
    QCOMPARE(holding->blocks.first().values.first(), quint16(1050));
    auto *tree = map->findChild<MapResultTree *>();
    QCOMPARE(tree->topLevelItemCount(), 1);
    QCOMPARE(tree->topLevelItem(0)->childCount(), 1);
    QVERIFY(tree->topLevelItem(0)->child(0)->text(MapResultTree::ItemColumn).startsWith(QLatin1String("121-142")));
    QVERIFY(map->findChild<QLabel *>(QStringLiteral("mapStatus"))->text().contains(QLatin1String("22")));

    // A watch per block, through the scan dialog to whoever shows watches.
    QSignalSpy requested(&dialog, &ScanDialog::watchesRequested);
    QTest::mouseClick(map->findChild<QPushButton *>(QStringLiteral("mapAddWatches")), Qt::LeftButton);
    QCOMPARE(requested.size(), 1);
    const QList<WatchDefinition> watches = requested.first().first().value<QList<WatchDefinition>>();
    QCOMPARE(watches.size(), 1);
    QCOMPARE(watches.first().unit, quint8(3));
    QCOMPARE(watches.first().address, quint16(0x79));
    QCOMPARE(watches.first().quantity, quint16(22));

    // The draft is a profile: loaded, served, and mapped the same.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("clone.json"));
    QVERIFY(map->saveDraft(path));
    const ProfileLoadResult loaded = ProfileLoader::loadFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    EmbeddedSimulator clone;
    const EmbeddedSimulator::Started started = clone.start(path, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    map->setTarget(started.url, 3);
    const RegisterMap again = mapThroughDialog(map);
    QVERIFY(again.table(3));
    QCOMPARE(again.table(3)->blocks.size(), 1);
    QCOMPARE(int(again.table(3)->blocks.first().address), 0x79);
    QCOMPARE(again.table(3)->blocks.first().last(), 0x8E);
    QCOMPARE(again.table(3)->blocks.first().values.first(), quint16(1050));

    if (const QString shot = qEnvironmentVariable("MBSCOPE_MAP_SCREENSHOT"); !shot.isEmpty())
        map->grab().save(shot);

    // A bad field is said, and nothing runs.
    map->findChild<QLineEdit *>(QStringLiteral("mapTarget"))->setText(QStringLiteral("nowhere"));
    QVERIFY(!map->settings());
    QVERIFY(map->findChild<QLabel *>(QStringLiteral("mapStatus"))->text().contains(QLatin1String("scheme")));
}

// The map scan runs on a job thread (JobThread), not in local event loops on the window's thread:
// a timer on the window's thread never sees a nested loop while it runs (before: level 2, the
// scan's wait inside the click's), its frames still reach the scan dialog's framesLogged() (the
// window's traffic list), and Stop mid-scan keeps the block found.
void TestScanDialog::mapScanLeavesTheWindowLoopAlone()
{
    ScanDialog dialog;
    dialog.setTarget(m_url);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanLastUnit"))->setValue(3);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanAddress"))->setValue(0x79);
    QSignalSpy scanned(&dialog, &ScanDialog::scanFinished);
    dialog.show();
    dialog.start();
    QVERIFY(scanned.wait(20000));
    dialog.findChild<QTableView *>(QStringLiteral("scanResults"))->selectRow(2); // unit 3
    MapScanDialog *map = dialog.mapSelectedUnit();
    QVERIFY(map);
    map->findChild<QSpinBox *>(QStringLiteral("mapFirstAddress"))->setValue(0x70);
    map->findChild<QSpinBox *>(QStringLiteral("mapLastAddress"))->setValue(65535);
    for (const int table : {1, 2, 4})
        map->findChild<QCheckBox *>(QStringLiteral("mapTable%1").arg(table))->setChecked(false);
    map->findChild<QCheckBox *>(QStringLiteral("mapOptional"))->setChecked(false);
    map->findChild<QSpinBox *>(QStringLiteral("mapMaxRequests"))->setValue(1000000);

    QSignalSpy frames(&dialog, &ScanDialog::framesLogged);
    QSignalSpy finished(map, &MapScanDialog::scanFinished);
    int deepest = 0;
    int samples = 0;
    QTimer probe;
    connect(&probe, &QTimer::timeout, this, [&] {
        deepest = qMax(deepest, QThread::currentThread()->loopLevel());
        ++samples;
    });
    probe.start(2);
    // Stop once the scan is past the block at 0x79-0x8E, far from the end of the table.
    const QMetaObject::Connection stopper = connect(map->job(), &Job::progressChanged, this, [&](const JobProgress &p) {
        if (p.done > 0x30 && map->isRunning())
            QTest::mouseClick(map->findChild<QPushButton *>(QStringLiteral("mapStop")), Qt::LeftButton);
    });
    // Clicked from inside the test's event loop, as a user clicks inside the window's.
    QTimer::singleShot(0, map, [map] { QTest::mouseClick(map->findChild<QPushButton *>(QStringLiteral("mapStart")), Qt::LeftButton); });
    QVERIFY(finished.wait(60000));
    probe.stop();
    QVERIFY(samples > 0);
    QCOMPARE(deepest, 1);
    QCOMPARE(finished.first().first().value<JobEnd>(), JobEnd::Stopped);
    QVERIFY(!map->isRunning());
    QVERIFY(map->map());
    const TableMap *holding = map->map()->table(3);
    QVERIFY(holding);
    QCOMPARE(holding->blocks.size(), 1);
    QCOMPARE(int(holding->blocks.first().address), 0x79);
    QCOMPARE(holding->blocks.first().last(), 0x8E);
    QVERIFY(map->findChild<QLabel *>(QStringLiteral("mapStatus"))->text().startsWith(QLatin1String("Stopped")));
    QVERIFY(map->findChild<QPushButton *>(QStringLiteral("mapSaveDraft"))->isEnabled());
    QVERIFY(!frames.isEmpty());
    bool sawRead = false;
    for (const QList<QVariant> &args : std::as_const(frames)) {
        for (const TrafficFrame &f : args.first().value<QList<TrafficFrame>>())
            sawRead = sawRead || (f.direction == TrafficDirection::Out && f.bytes.contains(QByteArray::fromHex("0300700001")));
    }
    QVERIFY(sawRead); // the map's first read (the unit scan asked 0x79), from the scan's thread

    // Esc mid-scan: the dialog closes, the scan stops, what it found is kept.
    disconnect(stopper);
    finished.clear();
    QTimer::singleShot(0, map, [map] { QTest::mouseClick(map->findChild<QPushButton *>(QStringLiteral("mapStart")), Qt::LeftButton); });
    connect(map->job(), &Job::progressChanged, this, [&](const JobProgress &p) {
        if (p.done > 0x30 && map->isVisible())
            QTest::keyClick(map, Qt::Key_Escape);
    });
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.first().first().value<JobEnd>(), JobEnd::Stopped);
    QVERIFY(!map->isVisible());
    QVERIFY(map->map() && map->map()->table(3) && map->map()->table(3)->blocks.size() == 1);

    // Infer types on that map: its reads reach the scan dialog's framesLogged() too (the window's
    // traffic list and recording); before, its sampler's channel was nobody's.
    InferDialog *infer = map->inferTypes();
    QVERIFY(infer);
    infer->findChild<QSpinBox *>(QStringLiteral("inferSamples"))->setValue(2);
    infer->findChild<QSpinBox *>(QStringLiteral("inferInterval"))->setValue(10);
    frames.clear();
    QSignalSpy inferred(infer, &InferDialog::inferred);
    infer->start();
    QVERIFY(inferred.wait(30000));
    bool sawBlockRead = false;
    for (const QList<QVariant> &args : std::as_const(frames)) {
        for (const TrafficFrame &f : args.first().value<QList<TrafficFrame>>())
            sawBlockRead = sawBlockRead || (f.direction == TrafficDirection::Out && f.bytes.contains(QByteArray::fromHex("0300790016")));
    }
    QVERIFY(sawBlockRead); // the block 0x79-0x8E read whole, from the sampler's thread
}

// Timing on a found unit: the read the scan asked, measured through the dialog's Start, the
// recommended settings on the clipboard; a gap that is not a number is said.
void TestScanDialog::timingOfAFoundUnit()
{
    ScanDialog dialog;
    dialog.setTarget(m_url);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanLastUnit"))->setValue(2);
    dialog.findChild<QSpinBox *>(QStringLiteral("scanAddress"))->setValue(0x79);
    auto *timingButton = dialog.findChild<QPushButton *>(QStringLiteral("scanTimeUnit"));
    QVERIFY(!timingButton->isEnabled());
    QSignalSpy scanned(&dialog, &ScanDialog::scanFinished);
    dialog.show();
    dialog.start();
    QVERIFY(scanned.wait(20000));
    QTest::mouseClick(timingButton, Qt::LeftButton);
    auto *timing = dialog.findChild<TimingScanDialog *>();
    QVERIFY(timing && timing->isVisible());
    std::optional<TimingScanSettings> s = timing->settings();
    QVERIFY(s);
    QCOMPARE(s->unit, quint8(1));
    QCOMPARE(s->address, quint16(0x79));
    QCOMPARE(s->function, quint8(3));

    auto *gaps = timing->findChild<QLineEdit *>(QStringLiteral("timingGaps"));
    gaps->setText(QStringLiteral("20, x"));
    QVERIFY(!timing->settings());
    QVERIFY(timing->findChild<QLabel *>(QStringLiteral("timingStatus"))->text().contains(QLatin1String("is not a number")));
    gaps->setText(QStringLiteral("0, 20"));
    timing->findChild<QSpinBox *>(QStringLiteral("timingPerGap"))->setValue(5);
    timing->findChild<QSpinBox *>(QStringLiteral("timingClients"))->setValue(3);
    auto *copy = timing->findChild<QPushButton *>(QStringLiteral("timingCopySettings"));
    QVERIFY(!copy->isEnabled());
    QSignalSpy finished(timing, &TimingScanDialog::scanFinished);
    // What the dialog shows as the scan goes: the bar at steps done of the plan (before, a busy
    // bar without a count), the status "Measuring gap 20 ms: 4 of 22 steps, about 1.2 s left".
    auto *bar = timing->findChild<QProgressBar *>(QStringLiteral("timingProgress"));
    auto *status = timing->findChild<QLabel *>(QStringLiteral("timingStatus"));
    QList<int> values;
    QStringList texts;
    connect(timing->scanner(), &TimingScanner::progressChanged, this, [&](const JobProgress &) {
        QCOMPARE(bar->maximum(), 1 + 2 * 5 + 8 + 3); // first answer, 2 gaps x 5, largest read, 3 clients (rtu-tcp: no pipelining)
        values.append(bar->value());
        texts.append(status->text());
        // The dialog as it runs, for a look (MBSCOPE_TIMING_PROGRESS_SCREENSHOT=file.png).
        if (const QString shot = qEnvironmentVariable("MBSCOPE_TIMING_PROGRESS_SCREENSHOT");
            !shot.isEmpty() && bar->value() == 8)
            timing->grab().save(shot);
    });
    QTest::mouseClick(timing->findChild<QPushButton *>(QStringLiteral("timingStart")), Qt::LeftButton);
    QVERIFY(!finished.isEmpty() || finished.wait(60000));
    QVERIFY(values.size() > 10);
    QCOMPARE(values.first(), 0);
    for (qsizetype i = 1; i < values.size(); ++i)
        QVERIFY(values.at(i) >= values.at(i - 1));
    QCOMPARE(values.last(), bar->maximum());
    QCOMPARE(bar->value(), bar->maximum());
    QVERIFY2(texts.first().startsWith(QLatin1String("Measuring first answer after connecting: 0 of 22 steps, about ")),
             qPrintable(texts.first()));
    QVERIFY2(texts.filter(QRegularExpression(QStringLiteral("^Measuring gap 20 ms: \\d+ of 22 steps, about .+ left$"))).size() >= 5,
             qPrintable(texts.join(QLatin1Char('\n'))));
    QVERIFY2(texts.last().endsWith(QLatin1String("22 of 22 steps, about 0.0 s left")), qPrintable(texts.last()));
    QVERIFY(timing->report());
    const TimingReport &r = *timing->report();
    QVERIFY(r.firstAnswerMs >= 0);
    QVERIFY(!r.gaps.isEmpty());
    QCOMPARE(r.gaps.first().gapMs, 20); // longest first, whatever order typed
    QCOMPARE(r.gaps.first().ok, 5);
    QCOMPARE(r.largestQuantity, 22); // 0x79-0x8E: the 22 registers from the address on
    QVERIFY(r.largestEndsMap);       // 23 got 02: the map ends there, no quantity limit
    QCOMPARE(r.clientsTried, 3);
    auto *tree = timing->findChild<TimingResultTree *>();
    QVERIFY(!tree->findItems(QStringLiteral("Recommended"), Qt::MatchExactly).isEmpty());
    QVERIFY(timing->findChild<QLabel *>(QStringLiteral("timingStatus"))->text().contains(QLatin1String("recommended")));
    QVERIFY(copy->isEnabled());
    QTest::mouseClick(copy, Qt::LeftButton);
    const QString copied = QGuiApplication::clipboard()->text();
    QVERIFY2(copied.contains(QStringLiteral("\"gapMs\": %1").arg(r.recommendedGapMs())), qPrintable(copied));
    QVERIFY(copied.contains(QLatin1String("pause_between_requests")));

    // "Record limits in profile…" merges what was measured into a profile picked in the file
    // dialog (before, the window wrote the limits nowhere): what the device showed it lacks (no
    // gap, no warm-up); the largest read is not a limit here (22 registers is where the map ends:
    // before, maxQuantity 0x03 22 was written); the profile's name and units stay.
    QTemporaryDir dir;
    const QString profilePath = dir.filePath(QStringLiteral("device.json"));
    QFile profile(profilePath);
    QVERIFY(profile.open(QIODevice::WriteOnly));
    profile.write(R"({"name": "device", "units": [{"id": 1, "tables": {"holding": [{"address": 121, "count": 22}]}}]})");
    profile.close();
    auto *saveLimits = timing->findChild<QPushButton *>(QStringLiteral("timingSaveLimits"));
    QVERIFY(saveLimits->isEnabled());
    QVERIFY(clickPickingFile(saveLimits, profilePath));
    QVERIFY(profile.open(QIODevice::ReadOnly));
    const QJsonObject saved = QJsonDocument::fromJson(profile.readAll()).object();
    QCOMPARE(saved.value(QStringLiteral("name")).toString(), QStringLiteral("device"));
    QCOMPARE(saved.value(QStringLiteral("units")).toArray().size(), 1);
    QVERIFY2(!saved.value(QStringLiteral("limits")).toObject().contains(QStringLiteral("maxQuantity")), QJsonDocument(saved).toJson().constData());
    QVERIFY2(status->text().startsWith(QLatin1String("Recorded ")) && status->text().contains(QLatin1String("no limit seen"))
                 && !status->text().contains(QLatin1String("maxQuantity")),
             qPrintable(status->text()));
    QVERIFY(!tree->findItems(QStringLiteral("22 at address 121"), Qt::MatchStartsWith | Qt::MatchRecursive, 1).isEmpty());
    if (const QString shot = qEnvironmentVariable("MBSCOPE_TIMING_SCREENSHOT"); !shot.isEmpty())
        timing->grab().save(shot);
}

// Serial settings: the simulated Arduino at 19200 8E1 behind tests/peers/line_harness.py (two
// ptys relayed only when the client's baud rate and stop bits are the device's); the dialog finds
// 19200 with every parity (a pty carries no parity bit, which it says), "Use this setting" makes
// it the unit scan's target, and the unit scan then finds unit 1 through it.
void TestScanDialog::serialSettingsFound()
{
    QProcess harness;
    harness.start(QStringLiteral("/usr/bin/python3"),
                  {QStringLiteral(MBSCOPE_TEST_DATA_DIR "/../peers/line_harness.py"), QStringLiteral("--baud"), QStringLiteral("19200"),
                   QStringLiteral("--stop"), QStringLiteral("1")});
    QVERIFY2(harness.waitForStarted(5000), qPrintable(harness.errorString()));
    const auto stopHarness = qScopeGuard([&harness] {
        harness.kill();
        harness.waitForFinished(5000);
    });
    QTRY_VERIFY_WITH_TIMEOUT(harness.canReadLine(), 10000);
    const QString where = QString::fromUtf8(harness.readLine()).trimmed(); // LISTENING client=A device=B
    QVERIFY2(where.startsWith(QLatin1String("LISTENING")), qPrintable(where));
    const QString client = where.section(QLatin1Char(' '), 1, 1).section(QLatin1Char('='), 1);
    const QString device = where.section(QLatin1Char(' '), 2, 2).section(QLatin1Char('='), 1);
    EmbeddedSimulator arduino;
    const EmbeddedSimulator::Started started =
        arduino.start(QStringLiteral("arduino-rs485"), QStringLiteral("rtu://%1?baud=19200&parity=E&stop=1").arg(device));
    QVERIFY2(started.ok, qPrintable(started.error));

    ScanDialog dialog;
    auto *lineButton = dialog.findChild<QPushButton *>(QStringLiteral("scanLineSettings"));
    dialog.setTarget(m_url);
    QVERIFY(!lineButton->isEnabled()); // rtu-tcp is no serial port
    dialog.setTarget(*LinkUrl::parse(QStringLiteral("rtu://") + client).url);
    QVERIFY(lineButton->isEnabled());
    dialog.show();
    QTest::mouseClick(lineButton, Qt::LeftButton);
    auto *line = dialog.findChild<LineScanDialog *>();
    QVERIFY(line && line->isVisible());
    line->findChild<QLineEdit *>(QStringLiteral("lineBauds"))->setText(QStringLiteral("9600, 19200, x"));
    QVERIFY(!line->settings());
    QVERIFY(line->findChild<QLabel *>(QStringLiteral("lineStatus"))->text().contains(QLatin1String("is not a baud rate")));
    line->findChild<QLineEdit *>(QStringLiteral("lineBauds"))->setText(QStringLiteral("9600, 19200"));
    line->findChild<QLineEdit *>(QStringLiteral("lineUnits"))->setText(QStringLiteral("1"));
    // The relay is a Python process: on a loaded machine an answer can take longer than 200 ms.
    line->findChild<QSpinBox *>(QStringLiteral("lineTimeout"))->setValue(1000);
    auto *use = line->findChild<QPushButton *>(QStringLiteral("lineUseSetting"));
    QVERIFY(!use->isEnabled());
    QSignalSpy finished(line, &LineScanDialog::scanFinished);
    auto *bar = line->findChild<QProgressBar *>(QStringLiteral("lineProgress"));
    QStringList texts;
    connect(line->scanner(), &LineScanner::progressChanged, this, [&](const JobProgress &) {
        QCOMPARE(bar->maximum(), 12);
        texts.append(line->findChild<QLabel *>(QStringLiteral("lineStatus"))->text());
    });
    QTest::mouseClick(line->findChild<QPushButton *>(QStringLiteral("lineStart")), Qt::LeftButton);
    QVERIFY(!finished.isEmpty() || finished.wait(60000));
    QCOMPARE(finished.first().first().value<JobEnd>(), JobEnd::Completed);
    // The bar at the trials of the plan, the status with the time left: none at the end.
    QVERIFY2(texts.first().startsWith(QLatin1String("0 of 12 tried, 0 answered, about ")), qPrintable(texts.first()));
    QVERIFY2(texts.last() == QLatin1String("12 of 12 tried, 3 answered, about 0.0 s left"), qPrintable(texts.last()));
    QCOMPARE(bar->value(), 12);
    QCOMPARE(line->trials().size(), 2 * 3 * 2);
    QCOMPARE(line->findChild<QTreeWidget *>(QStringLiteral("lineTrials"))->topLevelItemCount(), 12);
    QStringList working;
    for (const LineTrial &t : line->trials()) {
        if (t.works())
            working.append(t.settingText());
    }
    QCOMPARE(working, (QStringList{QStringLiteral("19200 8E1"), QStringLiteral("19200 8N1"), QStringLiteral("19200 8O1")}));
    const QString status = line->findChild<QLabel *>(QStringLiteral("lineStatus"))->text();
    QVERIFY2(status.contains(QLatin1String("19200 8E1 (unit 1)")) && status.contains(QLatin1String("parity bit")), qPrintable(status));
    if (const QString shot = qEnvironmentVariable("MBSCOPE_LINE_SCREENSHOT"); !shot.isEmpty()) {
        QTest::qWait(50); // the status line's new height laid out
        line->grab().save(shot);
    }

    QTest::mouseClick(use, Qt::LeftButton);
    const std::optional<UnitScanSettings> s = dialog.settings();
    QVERIFY(s);
    QCOMPARE(s->url.serial.baud, 19200);
    QCOMPARE(s->url.serial.parity, 'E');
    QCOMPARE(s->url.serial.stopBits, 1);
    line->close();
    dialog.findChild<QSpinBox *>(QStringLiteral("scanLastUnit"))->setValue(2);
    QSignalSpy scanned(&dialog, &ScanDialog::scanFinished);
    dialog.start();
    QVERIFY(scanned.wait(20000));
    QCOMPARE(dialog.model()->probes().first().kind, UnitProbeKind::Answers);
}

void TestScanDialog::accessKeysAreUnique_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("English") << QStringLiteral("en");
    QTest::newRow("Indonesian") << QStringLiteral("id");
}

// Each Alt+letter of both scan dialogs reaches one control, in both languages (in Indonesian
// "&Tujuan" and "&Tambahkan sebagai pantauan" both took T).
void TestScanDialog::accessKeysAreUnique()
{
    QFETCH(QString, language);
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(*TranslationLoader::parse(language)));
    {
        ScanDialog scan;
        scan.show();
        QVERIFY(QTest::qWaitForWindowExposed(&scan));
        QStringList clashes = guitest::mnemonicClashes(&scan);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
        MapScanDialog map;
        map.show();
        QVERIFY(QTest::qWaitForWindowExposed(&map));
        clashes = guitest::mnemonicClashes(&map);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
        LineScanDialog line;
        line.show();
        QVERIFY(QTest::qWaitForWindowExposed(&line));
        clashes = guitest::mnemonicClashes(&line);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
        TimingScanDialog timing;
        timing.show();
        QVERIFY(QTest::qWaitForWindowExposed(&timing));
        clashes = guitest::mnemonicClashes(&timing);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
    }
    TranslationLoader::install(*qApp, TranslationLoader::localeFor(TranslationLoader::Choice::English));
}

QTEST_MAIN(TestScanDialog)
#include "tst_scandialog.moc"
