// The workspace reaching the rest of the window (issue 16, the window's side): a watch started and
// stopped on its own (menu, context menu, Ctrl+F5) while the others go on; a watch's value plotted
// in Register trends ("Trend this value", or chosen by watch and point name) and the choice kept;
// the latency panels showing one watch or one link; the status bar counting the watches' traffic;
// and the polish users asked for (the Reference header whole, no dot before the tab names,
// upper-case hex). Against the M221 simulator over TCP on loopback.
#include "analysis/analysisdock.h"
#include "analysis/latencyanalysis.h"
#include "analysis/latencyhistogrampanel.h"
#include "analysis/latencyruns.h"
#include "analysis/latencysource.h"
#include "analysis/latencytimepanel.h"
#include "analysis/registertrendpanel.h"
#include "analysis/trendpanels.h"
#include "shell/linkstatuswidget.h"
#include "shell/mainwindow.h"
#include "watch/watchfactory.h"
#include "watch/watchtablemodel.h"
#include "watch/watchwindow.h"
#include "watch/watchworkspace.h"

#include "guitestsupport.h"

#include "profile/profileloader.h"
#include "sim/simulatorhost.h"

#include <QtGui/QAction>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QMdiArea>
#include <QtWidgets/QMdiSubWindow>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QTableView>
#include <qcustomplot.h>

#include <memory>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 20000;

std::unique_ptr<SimulatorHost> servePlc(QString *url, QString *error)
{
    const ProfileLoadResult loaded = ProfileLoader::load(QStringLiteral("m221-plc"));
    if (!loaded.ok) {
        *error = loaded.errorText();
        return nullptr;
    }
    auto host = std::make_unique<SimulatorHost>();
    if (!host->load(loaded.profile, error))
        return nullptr;
    const std::optional<LinkUrl> listening = host->listen(QStringLiteral("tcp://127.0.0.1:0"), error);
    if (!listening)
        return nullptr;
    *url = listening->toString();
    host->start();
    return host;
}

WatchDefinition words(const QString &target, const QString &name = QStringLiteral("plc words"))
{
    WatchDefinition watch;
    watch.name = name;
    watch.target = target;
    watch.function = 3;
    watch.address = 0;
    watch.quantity = 4;
    watch.intervalMs = 100;
    WatchPoint setpoint;
    setpoint.address = 0;
    setpoint.name = QStringLiteral("setpoint");
    setpoint.unit = QStringLiteral("rpm");
    setpoint.scale = 0.5;
    setpoint.writable = true;
    watch.points = {setpoint};
    return watch;
}

WatchDefinition coils(const QString &target)
{
    WatchDefinition watch;
    watch.name = QStringLiteral("plc coils");
    watch.target = target;
    watch.function = 1;
    watch.address = 0;
    watch.quantity = 8;
    watch.intervalMs = 100;
    return watch;
}

QString subTitle(WatchWorkspace *workspace, int index)
{
    return workspace->window(index)->windowTitle();
}

} // namespace

class TestWorkspaceWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void oneWatchStartedAndStoppedAlone();
    void watchValueTrended();
    void latencyOfOneWatchOrLink();
    void statusBarCountsWatchTraffic();
    void polish();
    void profileKeepsEveryBlock();
    void profileLimitsHonoured();
};

// Ctrl+F5, the Workspace menu's "Poll this watch" and the window's context menu start and stop the
// current watch alone; its title and status line say so; Start all and Stop all still do all.
void TestWorkspaceWindow::oneWatchStartedAndStoppedAlone()
{
    QString url, error;
    std::unique_ptr<SimulatorHost> plc = servePlc(&url, &error);
    QVERIFY2(plc, qPrintable(error));
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.showTab(QStringLiteral("watches"));
    WatchWorkspace *workspace = window.watchWorkspace();
    workspace->addWatch(words(url));
    workspace->addWatch(coils(url));
    // Reachable from the window's context menu and the Workspace menu.
    QVERIFY(workspace->windowMenuActions().contains(workspace->pollThisAction()));
    QVERIFY(workspace->windowMenuActions().contains(workspace->trendAction()));
    QVERIFY(workspace->menuActions().contains(workspace->pollThisAction()));
    QCOMPARE(workspace->pollThisAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_F5));

    // Ctrl+F5 on the first watch: it alone polls.
    workspace->setCurrentIndex(0);
    workspace->window(0)->view()->setFocus();
    QTest::keyClick(workspace->window(0)->view(), Qt::Key_F5, Qt::ControlModifier);
    QVERIFY(workspace->isRunning());
    QVERIFY(workspace->isPolling(0));
    QVERIFY(!workspace->isPolling(1));
    QVERIFY(workspace->pollThisAction()->isChecked());
    QCOMPARE(subTitle(workspace, 0), QStringLiteral("plc words"));
    QCOMPARE(subTitle(workspace, 1), QStringLiteral("plc coils (stopped)"));
    QTRY_VERIFY_WITH_TIMEOUT(workspace->window(0)->counters().ok >= 3, kWaitMs);
    QVERIFY(workspace->window(0)->countersLabel()->text().startsWith(QStringLiteral("Polling")));
    QVERIFY(workspace->window(1)->countersLabel()->text().startsWith(QStringLiteral("Stopped")));
    QCOMPARE(workspace->window(1)->counters().polls, quint64(0));

    // The second from the menu action: both poll. The runner's links open again for the new set;
    // the first watch's window carries on counting from where it was.
    QTRY_VERIFY_WITH_TIMEOUT(workspace->window(0)->counters().ok >= 10, kWaitMs);
    const quint64 firstBefore = workspace->window(0)->counters().polls;
    workspace->setCurrentIndex(1);
    QVERIFY(!workspace->pollThisAction()->isChecked());
    workspace->pollThisAction()->trigger();
    QVERIFY(workspace->isPolling(0) && workspace->isPolling(1));
    QCOMPARE(subTitle(workspace, 1), QStringLiteral("plc coils"));
    QTRY_VERIFY_WITH_TIMEOUT(workspace->window(1)->counters().ok >= 3, kWaitMs);
    // The two take turns on one link: the first's new run has about as many polls as the second's
    // (3), the window shows them on top of the 10 or more it had.
    QVERIFY2(workspace->window(0)->counters().polls >= firstBefore,
             qPrintable(QStringLiteral("%1 polls shown, %2 before").arg(workspace->window(0)->counters().polls).arg(firstBefore)));
    QCOMPARE(workspace->window(0)->counters().ok, workspace->window(0)->counters().polls);
    QCOMPARE(workspace->window(0)->counters().latencyCount, workspace->window(0)->counters().polls);

    // The first stopped alone: the second goes on, the first's polls stay where they were.
    workspace->setCurrentIndex(0);
    QVERIFY(workspace->pollThisAction()->isChecked());
    workspace->pollThisAction()->trigger();
    QVERIFY(!workspace->isPolling(0));
    QVERIFY(workspace->isPolling(1));
    QCOMPARE(subTitle(workspace, 0), QStringLiteral("plc words (stopped)"));
    QTest::qWait(300); // the last batch of the first watch's polls may still arrive
    const quint64 stoppedAt = workspace->window(0)->counters().polls;
    const quint64 otherAt = workspace->window(1)->counters().polls;
    QTRY_VERIFY_WITH_TIMEOUT(workspace->window(1)->counters().polls >= otherAt + 3, kWaitMs);
    QCOMPARE(workspace->window(0)->counters().polls, stoppedAt);
    // Started again alone: it goes on from its count.
    workspace->startWatch(0);
    QTRY_VERIFY_WITH_TIMEOUT(workspace->window(0)->counters().polls != stoppedAt, kWaitMs);
    QVERIFY(workspace->window(0)->counters().polls > stoppedAt);
    workspace->stopWatch(0);

    // The last one stopped: the runner stops; titles lose "(stopped)".
    workspace->setCurrentIndex(1);
    workspace->pollThisAction()->trigger();
    QVERIFY(!workspace->isRunning());
    QCOMPARE(subTitle(workspace, 0), QStringLiteral("plc words"));
    QVERIFY(workspace->window(0)->countersLabel()->text().startsWith(QStringLiteral("Stopped")));

    // A watch that is off ("Poll this watch" unticked) started by name is turned on.
    WatchDefinition off = workspace->watches().watches.at(1);
    off.enabled = false;
    workspace->replaceWatch(1, off);
    QCOMPARE(subTitle(workspace, 1), QStringLiteral("plc coils (off)"));
    workspace->startWatch(1);
    QVERIFY(workspace->watches().watches.at(1).enabled);
    QVERIFY(workspace->isPolling(1));
    QVERIFY(!workspace->isPolling(0));
    // Start all and Stop all act on every watch, as before.
    workspace->startAll();
    QVERIFY(workspace->isPolling(0) && workspace->isPolling(1));
    // "Poll this watch" unticked in the dialog stops it; ticked again while the others poll, it polls.
    off = workspace->watches().watches.at(1);
    off.enabled = false;
    workspace->replaceWatch(1, off);
    QVERIFY(!workspace->isPolling(1));
    QCOMPARE(subTitle(workspace, 1), QStringLiteral("plc coils (off)"));
    off.enabled = true;
    workspace->replaceWatch(1, off);
    QVERIFY(workspace->isPolling(1));
    QCOMPARE(subTitle(workspace, 1), QStringLiteral("plc coils"));
    workspace->stopAll();
    QVERIFY(!workspace->isPolling(0) && !workspace->isPolling(1));
    plc->stop();
}

// "Trend this value" in a watch window plots the value in Register trends as the watch decodes it
// (its point's name, unit and scale); the panel offers every watch's values by name; the choice
// survives a restart of the window.
void TestWorkspaceWindow::watchValueTrended()
{
    QString url, error;
    std::unique_ptr<SimulatorHost> plc = servePlc(&url, &error);
    QVERIFY2(plc, qPrintable(error));
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.showTab(QStringLiteral("watches"));
        WatchWorkspace *workspace = window.watchWorkspace();
        RegisterTrendPanel *trends = window.trendPanels()->trends();
        workspace->addWatch(words(url));
        workspace->addWatch(coils(url));
        // The panel offers the watches by name, and their values by point name or address.
        QCOMPARE(trends->watchChoice()->count(), 2);
        QCOMPARE(trends->watchChoice()->itemText(0), QStringLiteral("plc words"));
        QCOMPARE(trends->watchValueChoice()->itemText(0), QStringLiteral("setpoint (rpm)"));
        QCOMPARE(trends->watchValueChoice()->count(), 4); // setpoint, then addresses 1-3
        workspace->startAll();
        QTRY_VERIFY_WITH_TIMEOUT(workspace->window(0)->counters().ok >= 2, kWaitMs);
        QString ignored;
        QVERIFY2(workspace->writeValue(0, 0, QStringLiteral("600"), &ignored), qPrintable(ignored)); // raw 1200
        QTRY_COMPARE_WITH_TIMEOUT(workspace->window(0)->model()->index(0, WatchTableModel::ValueColumn).data().toString(),
                                  QStringLiteral("600"), kWaitMs);

        // The context menu's action on the setpoint's row.
        workspace->setCurrentIndex(0);
        QVERIFY(!workspace->trendAction()->isEnabled() || workspace->window(0)->view()->currentIndex().isValid());
        workspace->window(0)->view()->setCurrentIndex(workspace->window(0)->model()->index(0, WatchTableModel::ValueColumn));
        QVERIFY(workspace->trendAction()->isEnabled());
        workspace->trendAction()->trigger();
        QCOMPARE(trends->seriesCount(), 1);
        QCOMPARE(trends->series(0).watchName, QStringLiteral("plc words"));
        QCOMPARE(trends->series(0).label(), QStringLiteral("plc words \u203a setpoint (rpm)"));
        QCOMPARE(window.analysisDock()->tabs()->currentWidget(), trends);
        QTRY_VERIFY_WITH_TIMEOUT(trends->graphOf(0) && trends->graphOf(0)->dataCount() >= 3, kWaitMs);
        // The value as decoded: 1200 raw x 0.5.
        const auto last = trends->graphOf(0)->data()->constEnd() - 1;
        QCOMPARE(last->value, 600.0);

        // From the panel: the coils' address 2, which no point names.
        trends->watchChoice()->setCurrentIndex(1);
        trends->watchValueChoice()->setCurrentIndex(2);
        trends->findChild<QPushButton *>(QStringLiteral("trendAddWatchValue"))->click();
        QCOMPARE(trends->seriesCount(), 2);
        QCOMPARE(trends->series(1).watchName, QStringLiteral("plc coils"));
        QCOMPARE(trends->series(1).address, 2);
        QTRY_VERIFY_WITH_TIMEOUT(trends->graphOf(1)->dataCount() >= 2, kWaitMs);
        workspace->stopAll();
        trends->redrawNow();
        QVERIFY(guitest::saveShot(&window, QStringLiteral("workspace-trends.png")));
    }
    // A new window (a restart): the chosen watch values are plotted again.
    MainWindow again;
    RegisterTrendPanel *trends = again.trendPanels()->trends();
    QCOMPARE(trends->seriesCount(), 2);
    QCOMPARE(trends->series(0).watchName, QStringLiteral("plc words"));
    QCOMPARE(trends->series(0).address, 0);
    QCOMPARE(trends->series(1).watchName, QStringLiteral("plc coils"));
    QVERIFY(trends->graphOf(0) && trends->graphOf(0)->visible());
    plc->stop();
}

// The latency panels' source: all bench traffic, a watch link, or a watch. The histogram's
// current run then counts that watch's polls (or the link's, one item per watch), and Latency over
// time plots them.
void TestWorkspaceWindow::latencyOfOneWatchOrLink()
{
    QString url, error;
    std::unique_ptr<SimulatorHost> plc = servePlc(&url, &error);
    QVERIFY2(plc, qPrintable(error));
    MainWindow window;
    WatchWorkspace *workspace = window.watchWorkspace();
    LatencySource *source = window.latencyAnalysis()->source();
    LatencyRuns *runs = window.latencyAnalysis()->runs();
    workspace->addWatch(words(url));
    workspace->addWatch(coils(url));
    QCOMPARE(source->choiceCount(), 4);
    QCOMPARE(source->choiceText(0), QStringLiteral("All bench traffic"));
    QCOMPARE(source->choiceText(1), QStringLiteral("Watch link %1").arg(url));
    QCOMPARE(source->choiceText(2), QStringLiteral("Watch plc words"));
    QCOMPARE(source->choiceText(3), QStringLiteral("Watch plc coils"));
    // The choice is in the histogram's and the time panel's tool bars.
    auto *histogramBox = window.latencyAnalysis()->histogramPanel()->findChild<QComboBox *>(QStringLiteral("latencySourceChoice"));
    auto *timeBox = window.trendPanels()->latency()->findChild<QComboBox *>(QStringLiteral("latencySourceChoice"));
    QVERIFY(histogramBox && timeBox);
    QCOMPARE(histogramBox->count(), 4);

    workspace->startAll();
    QTRY_VERIFY_WITH_TIMEOUT(workspace->window(0)->counters().ok >= 5 && workspace->window(1)->counters().ok >= 5, kWaitMs);
    QCOMPARE(runs->statistics(LatencyRuns::Current).overall().count(), quint64(0)); // the bench sent nothing

    // One watch: its polls, answered, with latencies.
    histogramBox->setCurrentIndex(2);
    Q_EMIT histogramBox->activated(2);
    QCOMPARE(source->choice(), 2);
    QCOMPARE(timeBox->currentIndex(), 2);
    QVERIFY(runs->statistics(LatencyRuns::Current).overall().count() >= 5);
    workspace->stopAll();
    QTest::qWait(300);
    const Statistics &watchStats = runs->statistics(LatencyRuns::Current).overall();
    QCOMPARE(watchStats.count(), workspace->window(0)->counters().polls);
    QCOMPARE(quint64(watchStats.latency().count()), workspace->window(0)->counters().latencyCount);
    QCOMPARE(window.trendPanels()->latency()->graphs().answered->dataCount(), int(workspace->window(0)->counters().ok));

    // The link: both watches, one item each.
    source->setChoice(1);
    QCOMPARE(runs->statistics(LatencyRuns::Current).overall().count(),
             workspace->window(0)->counters().polls + workspace->window(1)->counters().polls);
    QCOMPARE(runs->statistics(LatencyRuns::Current, 1).count(), workspace->window(1)->counters().polls);

    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    if (auto *dock = window.findChild<QDockWidget *>(QStringLiteral("analysisDock")))
        dock->raise();
    window.analysisDock()->showPanel(window.latencyAnalysis()->histogramPanel());
    source->setChoice(2);
    window.latencyAnalysis()->histogramPanel()->redrawNow();
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workspace-latency.png")));
    // Back to the bench: nothing of the watches.
    source->setChoice(0);
    QCOMPARE(runs->statistics(LatencyRuns::Current).overall().count(), quint64(0));
    plc->stop();
}

// The status bar counts what the watches send and receive beside the bench's TX and RX.
void TestWorkspaceWindow::statusBarCountsWatchTraffic()
{
    QString url, error;
    std::unique_ptr<SimulatorHost> plc = servePlc(&url, &error);
    QVERIFY2(plc, qPrintable(error));
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    WatchWorkspace *workspace = window.watchWorkspace();
    workspace->addWatch(words(url));
    QVERIFY(window.linkStatus()->watchTrafficText().isEmpty());
    workspace->startAll();
    QTRY_VERIFY_WITH_TIMEOUT(workspace->window(0)->counters().ok >= 3, kWaitMs);
    workspace->stopAll();
    QTest::qWait(300);
    const quint64 polls = workspace->window(0)->counters().polls;
    // Modbus TCP: a read of 4 registers is 12 bytes out, 7 + 2 + 8 = 17 back.
    const QString text = window.linkStatus()->watchTrafficText();
    QCOMPARE(text, QStringLiteral("Watches: TX %1 B  RX %2 B  \u00B7  %3 polls")
                       .arg(QLocale().toString(polls * 12), QLocale().toString(polls * 17)).arg(polls));
    plc->stop();
}

// What users noticed: the Reference header clipped, a dot before each tab's name, lower-case hex.
void TestWorkspaceWindow::polish()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.showTab(QStringLiteral("watches"));
    WatchWorkspace *workspace = window.watchWorkspace();
    WatchDefinition watch = words(QStringLiteral("tcp://127.0.0.1:1"));
    watch.address = 0xAB;
    watch.points.clear();
    workspace->addWatch(watch);
    QTableView *view = workspace->window(0)->view();
    QHeaderView *header = view->horizontalHeader();
    for (int column : {int(WatchTableModel::AddressColumn), int(WatchTableModel::ReferenceColumn), int(WatchTableModel::UnitColumn),
                       int(WatchTableModel::ValueColumn), int(WatchTableModel::ChangedColumn)}) {
        const QString title = workspace->window(0)->model()->headerData(column, Qt::Horizontal, Qt::DisplayRole).toString();
        QVERIFY2(header->sectionSize(column) >= header->fontMetrics().horizontalAdvance(title) + 12,
                 qPrintable(QStringLiteral("%1: %2 px").arg(title).arg(header->sectionSize(column))));
    }
    // The tab's icon is see-through: no stray dot before the name.
    QMdiSubWindow *sub = workspace->area()->subWindowList().value(0);
    QVERIFY(sub);
    const QImage icon = sub->windowIcon().pixmap(16, 16).toImage();
    for (int y = 0; y < icon.height(); ++y) {
        for (int x = 0; x < icon.width(); ++x)
            QCOMPARE(qAlpha(icon.pixel(x, y)), 0);
    }
    // Upper-case hex, as the rest of the window writes it.
    QCOMPARE(workspace->window(0)->model()->index(0, WatchTableModel::AddressColumn).data().toString(), QStringLiteral("171 (0x00AB)"));
    QCOMPARE(WatchFactory::describeBlock(3, 0xAB, 2), QStringLiteral("holding 0x00AB x2"));
}

// Issue 26 item 5: New watches from a device profile on the M221, whose 8000 %MW are one entry
// (longer than a read) and whose 1024 %M are another. Every address of both lands in a watch, the
// long one cut into reads of 125 registers, and each value named as the PLC names it (%MW7999,
// %M5), never "%M0-%M1023[5]". The last block is polled and answered.
void TestWorkspaceWindow::profileKeepsEveryBlock()
{
    QString url, error;
    std::unique_ptr<SimulatorHost> plc = servePlc(&url, &error);
    QVERIFY2(plc, qPrintable(error));
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.showTab(QStringLiteral("watches"));
    WatchWorkspace *workspace = window.watchWorkspace();
    const int made = workspace->addFromProfile(QStringLiteral("m221-plc"), 1, url, 1000, &error);
    QVERIFY2(made > 0, qPrintable(error));
    QCOMPARE(made, 64 + 1); // 8000 / 125 holding reads, the 1024 coils in one
    QSet<int> holding, coils;
    int lastHolding = -1;
    for (int i = 0; i < workspace->count(); ++i) {
        const WatchDefinition &watch = workspace->watches().watches.at(i);
        QVERIFY(watch.quantity <= (watch.function <= 2 ? WatchFactory::kMaxBits : WatchFactory::kMaxRegisters));
        for (const WatchPoint &point : watch.points) {
            const QString prefix = watch.function == 1 ? QStringLiteral("%M") : QStringLiteral("%MW");
            QCOMPARE(point.name, prefix + QString::number(point.address));
            (watch.function == 1 ? coils : holding).insert(point.address);
        }
        if (watch.function == 3 && watch.address + watch.quantity == 8000)
            lastHolding = i;
    }
    QCOMPARE(holding.size(), 8000);
    QCOMPARE(coils.size(), 1024);
    QVERIFY(lastHolding >= 0);
    // The window shows the names; the last block of %MW is read like the first.
    WatchWindow *last = workspace->window(lastHolding);
    const int rows = last->model()->rowCount();
    QCOMPARE(last->model()->index(rows - 1, WatchTableModel::NameColumn).data().toString(), QStringLiteral("%MW7999"));
    workspace->startWatch(lastHolding);
    QTRY_VERIFY_WITH_TIMEOUT(last->counters().ok >= 1, kWaitMs);
    workspace->stopAll();
}

// Issue 28: watches from a profile whose device takes 16 registers a read, 50 ms between requests
// and ignores requests in the first 300 ms of a connection. Its 40 registers become three reads
// (16, 16, 8: the simulator refuses 17 with 03), the link waits the gap (gapMs 50) and the warm-up
// (warmUpMs 300), and polled against the simulator serving the same limits every poll of the three
// is answered: none refused with 03 as too large or 06 as too soon, none unanswered in the warm-up
// (before, one read of 40 was refused every time, reads back to back were refused as too soon,
// and the first request after connecting timed out).
void TestWorkspaceWindow::profileLimitsHonoured()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("narrow.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"name": "narrow", "limits": {"maxQuantity": {"0x03": 16}, "minGapMs": 50, "warmUpMs": 300},
                   "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 40}]}}]})");
    file.close();
    const ProfileLoadResult loaded = ProfileLoader::loadFile(path);
    QVERIFY2(loaded.ok, qPrintable(loaded.errorText()));
    SimulatorHost host;
    QString error;
    QVERIFY2(host.load(loaded.profile, &error), qPrintable(error));
    const std::optional<LinkUrl> listening = host.listen(QStringLiteral("tcp://127.0.0.1:0"), &error);
    QVERIFY2(listening, qPrintable(error));
    host.start();
    const QString url = listening->toString();
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.showTab(QStringLiteral("watches"));
    WatchWorkspace *workspace = window.watchWorkspace();
    QCOMPARE(workspace->addFromProfile(path, 1, url, 100, &error), 3);
    QList<std::pair<int, int>> reads;
    for (const WatchDefinition &watch : workspace->watches().watches)
        reads.append({watch.address, watch.quantity});
    QCOMPARE(reads, (QList<std::pair<int, int>>{{0, 16}, {16, 16}, {32, 8}}));
    QCOMPARE(workspace->watches().links.size(), 1);
    QCOMPARE(workspace->watches().links.constFirst().target, url);
    QCOMPARE(workspace->watches().links.constFirst().gapMs, 51); // with some to spare: DeviceLimits::clientGap
    QCOMPARE(workspace->watches().links.constFirst().warmUpMs, 330);
    workspace->startAll();
    for (int i = 0; i < 3; ++i)
        QTRY_VERIFY_WITH_TIMEOUT(workspace->window(i)->counters().ok >= 3, kWaitMs);
    workspace->stopAll();
    for (int i = 0; i < 3; ++i) {
        const WatchCounters c = workspace->window(i)->counters();
        QVERIFY2(c.exceptions == 0 && c.timeouts == 0 && c.otherErrors == 0, qPrintable(c.lastError));
    }
}

QTEST_MAIN(TestWorkspaceWindow)
#include "tst_workspacewindow.moc"
