// The window as a whole against its built-in simulator: first run, type and send a request, the
// decoded answer (request + matched response, latency), Ctrl+Return, a taken port, a link error in
// place, a poll and its counters, screenshots.
#include "analysis/latencyanalysis.h"
#include "analysis/latencysource.h"
#include "analysis/latencytimepanel.h"
#include "analysis/trendpanels.h"
#include "link/connectionbar.h"
#include "decode/decodeview.h"
#include "decode/frameinspector.h"
#include "decode/fieldtreemodel.h"
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "shell/linkstatuswidget.h"
#include "shell/mainwindow.h"
#include "common/noticebanner.h"
#include "compose/rawrequesteditor.h"
#include "registers/registertable.h"
#include "registers/registertablemodel.h"
#include "compose/requestcomposer.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"
#include "decode/transactionview.h"
#include "watch/watchworkspace.h"

#include "profile/profileloader.h"
#include "sim/simulatorhost.h"

#include <QtNetwork/QTcpServer>
#include <QtTest/QAbstractItemModelTester>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QStatusBar>
#include <QtWidgets/QTabWidget>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// The simulator on a port the OS chooses: tests never depend on 4001 being free.
const QString kAnyPort = QStringLiteral("rtu-tcp://127.0.0.1:0");
constexpr int kAnswerWaitMs = 5000;

} // namespace

class TestWorkbench : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void firstRunIsReadyToSend();
    void bannerFollowsTheLink();
    void typedRequestIsAnsweredAndDecoded();
    void ctrlReturnSends();
    void takenPortFallsBackToAFreeOne();
    void linkErrorIsShownInPlace();
    void pollCountsAndStops();
    void pickedFrameStaysWhilePolling();
    void registersProfileFollowsTheTarget();
    void eachConnectionCountsAlone();
};

void TestWorkbench::initTestCase()
{
    guitest::isolateSettings();
}

void TestWorkbench::firstRunIsReadyToSend()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.simulator()->isRunning());
    QCOMPARE(window.composer()->rawEditor()->text(), QStringLiteral("01 03 00 79 00 16 15 DD"));
    QVERIFY(window.controller()->isConnected());
    QCOMPARE(window.controller()->url().port, window.simulator()->started().url.port);
    QVERIFY(window.banner()->isVisible());
    QVERIFY(window.banner()->text().contains(QLatin1String("simulator")));
    QVERIFY(window.banner()->text().contains(QLatin1String("real device")));
    QVERIFY(window.composer()->sendAction()->isEnabled());
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-first-run.png")));
    // Disconnecting keeps the banner truthful: the simulator still runs, the window is not on it.
    window.connectionBar()->connectButton()->click();
    QVERIFY(!window.controller()->isConnected());
    QVERIFY2(window.banner()->text().startsWith(QLatin1String("Disconnected")), qPrintable(window.banner()->text()));
    QVERIFY(!window.composer()->sendAction()->isEnabled());
}

// Try-out 8, item 4: disconnected from the first-run simulator, Listen ticked, Connect: the status
// bar said "listening only" while the banner still said "Disconnected ... press Connect".
void TestWorkbench::bannerFollowsTheLink()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    const QString connected = window.banner()->text();
    // first-run.md (item 12): the target is greyed while connected, the unit (per request) is not.
    auto *unit = window.connectionBar()->findChild<QSpinBox *>(QStringLiteral("unitSpin"));
    QVERIFY(unit && unit->isEnabled());
    QVERIFY(!window.connectionBar()->findChild<QSpinBox *>(QStringLiteral("portSpin"))->isEnabled());
    window.connectionBar()->connectButton()->click();
    QVERIFY2(window.banner()->text().startsWith(QLatin1String("Disconnected")), qPrintable(window.banner()->text()));

    window.connectionBar()->setListenOnly(true);
    window.connectionBar()->connectButton()->click();
    QVERIFY(window.controller()->isListening());
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    QVERIFY(window.banner()->isVisible());
    QVERIFY2(!window.banner()->text().contains(QLatin1String("Disconnected")), qPrintable(window.banner()->text()));
    QVERIFY2(window.banner()->text().contains(QLatin1String("Listening only")), qPrintable(window.banner()->text()));
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-listen-simulator.png")));

    // Back to sending: the first run's words again, not "Disconnected".
    window.connectionBar()->connectButton()->click();
    QVERIFY(window.banner()->text().startsWith(QLatin1String("Disconnected")));
    window.connectionBar()->setListenOnly(false);
    window.connectionBar()->connectButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    QCOMPARE(window.banner()->text(), connected);
}

void TestWorkbench::typedRequestIsAnsweredAndDecoded()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    DecodeView *decode = window.answerView()->decodeView();
    FieldTreeModel *model = decode->responseInspector()->model();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);

    QPlainTextEdit *raw = window.composer()->rawEditor()->editor();
    raw->clear();
    raw->setFocus();
    QTest::keyClicks(raw, QStringLiteral("01 03 00 79 00 16 15 DD"));
    auto *send = window.composer()->findChild<QPushButton *>(QStringLiteral("sendButton"));
    QVERIFY(send && send->isEnabled());
    QTest::mouseClick(send, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(window.answerView()->shown().has_value(), kAnswerWaitMs);

    const Transaction t = *window.answerView()->shown();
    QCOMPARE(transactionStatusName(t.status), transactionStatusName(TransactionStatus::Ok));
    QCOMPARE(t.request.toHex(' '), QByteArray("01 03 00 79 00 16 15 dd"));
    QCOMPARE(t.response.size(), 3 + 44 + 2);
    QVERIFY(t.latencyNs() > 0);
    QCOMPARE(window.viewTabs()->currentWidget(), window.answerView());
    QVERIFY(window.answerView()->problemText().isEmpty());
    QCOMPARE(decode->exchange().latencyNs, t.latencyNs());
    QVERIFY2(decode->copyText(DecodeView::CopyFormat::Text).contains(QLatin1String("ms")),
             qPrintable(decode->copyText(DecodeView::CopyFormat::Text)));

    // The trees: the request, and the response read against it.
    QCOMPARE(decode->exchange().request, t.request);
    QCOMPARE(decode->requestDissection().direction, Direction::Request);
    const Dissection &d = decode->responseDissection();
    QVERIFY2(d.isValid(), qPrintable(d.summary()));
    QCOMPARE(d.direction, Direction::Response);
    const QModelIndex unit = model->indexOfKey("rtu.unit_id", FieldTreeModel::ValueColumn);
    QVERIFY(unit.isValid());
    QCOMPARE(unit.data().toString(), QStringLiteral("1"));
    const QModelIndex function = model->indexOfKey("modbus.function_code", FieldTreeModel::ValueColumn);
    QVERIFY(function.isValid());
    QVERIFY2(function.data().toString().contains(QLatin1String("03")), qPrintable(function.data().toString()));
    const QList<int> registers = d.fields.indexesOf("modbus.register_value");
    QCOMPARE(registers.size(), 22);
    QCOMPARE(d.fields.at(registers.first()).value, quint64(1050));
    const QModelIndex first = model->indexOfField(registers.first(), FieldTreeModel::ValueColumn);
    QVERIFY2(first.data().toString().contains(QLatin1String("1050")), qPrintable(first.data().toString()));

    // The status bar counted the bytes.
    QTRY_VERIFY_WITH_TIMEOUT(window.linkStatus()->countersText().contains(QLatin1String("TX 8 B")), kAnswerWaitMs);
    QTRY_VERIFY2_WITH_TIMEOUT(window.linkStatus()->countersText().contains(QLatin1String("RX 49 B")),
                              qPrintable(window.linkStatus()->countersText()), kAnswerWaitMs);
    QVERIFY(window.linkStatus()->stateText().contains(QLatin1String("Connected")));

    // The traffic list has the exchange; the register table shows the 22 values with the profile's names.
    QTRY_VERIFY_WITH_TIMEOUT(window.trafficMonitor()->model()->rowCount() >= 2, kAnswerWaitMs);
    QCOMPARE(window.registerTable()->model()->rowCount(), 22);

    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-answer.png")));
    QVERIFY(guitest::saveShot(window.answerView(), QStringLiteral("answer-view.png")));
    QVERIFY(guitest::saveShot(window.composer(), QStringLiteral("composer-raw.png")));
    QVERIFY(guitest::saveShot(window.connectionBar(), QStringLiteral("connectionbar-connected.png")));
    QVERIFY(guitest::saveShot(window.trafficMonitor(), QStringLiteral("traffic-dock.png")));
    auto *registersDock = window.findChild<QDockWidget *>(QStringLiteral("registersDock"));
    QVERIFY(registersDock);
    registersDock->raise();
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-registers.png")));
}

void TestWorkbench::ctrlReturnSends()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QPlainTextEdit *raw = window.composer()->rawEditor()->editor();
    raw->setFocus();
    QTest::keyClick(raw, Qt::Key_Return, Qt::ControlModifier);
    QTRY_VERIFY_WITH_TIMEOUT(window.answerView()->shown().has_value(), kAnswerWaitMs);
    // The shortcut sent the request; it did not type a newline into the bytes.
    QCOMPARE(raw->toPlainText(), QStringLiteral("01 03 00 79 00 16 15 DD"));
}

void TestWorkbench::takenPortFallsBackToAFreeOne()
{
    QTcpServer squatter;
    QVERIFY(squatter.listen(QHostAddress::LocalHost, 0));
    const quint16 taken = squatter.serverPort();
    MainWindow window;
    QVERIFY(window.startWithSimulator(QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(taken)));
    const quint16 used = window.simulator()->started().url.port;
    QVERIFY(used != taken && used != 0);
    QVERIFY2(window.banner()->text().contains(QLatin1String("in use")), qPrintable(window.banner()->text()));
    QVERIFY(window.banner()->text().contains(QString::number(used)));
    QCOMPARE(window.controller()->url().port, used);
    window.composer()->send();
    QTRY_VERIFY_WITH_TIMEOUT(window.answerView()->shown().has_value(), kAnswerWaitMs);
    QVERIFY(window.answerView()->shown()->isOk());
}

void TestWorkbench::linkErrorIsShownInPlace()
{
    quint16 closedPort = 0;
    {
        QTcpServer probe;
        QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
        closedPort = probe.serverPort();
    }
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const LinkUrl::Result url = LinkUrl::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(closedPort));
    QVERIFY(url.url);
    window.connectionBar()->setUrl(*url.url);
    window.connectionBar()->connectButton()->click();
    QVERIFY(window.controller()->isConnected());
    window.composer()->setRequestText(QStringLiteral("00 01 00 00 00 06 01 03 00 00 00 01"));
    window.composer()->send();
    QTRY_VERIFY_WITH_TIMEOUT(!window.connectionBar()->errorText().isEmpty(), kAnswerWaitMs);
    QVERIFY2(window.connectionBar()->errorText().contains(QLatin1String("refused")), qPrintable(window.connectionBar()->errorText()));
    QVERIFY(window.connectionBar()->errorText().contains(QLatin1String("Disconnect")));
    QTRY_VERIFY_WITH_TIMEOUT(window.answerView()->problemText().contains(QLatin1String("refused")), kAnswerWaitMs);
    QVERIFY(window.linkStatus()->stateText().contains(QLatin1String("Link failed")));
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-link-error.png")));
}

void TestWorkbench::pollCountsAndStops()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy finished(window.controller(), &LinkController::pollFinished);
    window.composer()->intervalSpin()->setValue(0);
    window.composer()->countSpin()->setValue(20);
    window.composer()->togglePoll();
    QVERIFY(window.controller()->isPolling());
    QVERIFY(!window.composer()->sendAction()->isEnabled()); // one thing at a time on the link
    QVERIFY(finished.wait(20000));
    QVERIFY(!window.controller()->isPolling());
    QTRY_VERIFY_WITH_TIMEOUT(window.controller()->counters().requestsSent >= 20, kAnswerWaitMs);
    QVERIFY(window.answerView()->shown().has_value());
    QVERIFY(window.answerView()->shown()->isOk());
    QVERIFY(window.composer()->sendAction()->isEnabled());
    const QString summary = window.statusBar()->currentMessage();
    QVERIFY2(summary.contains(QLatin1String("Poll finished: 20 transactions, 20 ok")), qPrintable(summary));
    QVERIFY2(summary.contains(QLatin1String("latency min")), qPrintable(summary));
}

// Issue 26 item 13: Find in the traffic list picked a frame while a poll ran, and the Answer tab
// showed it only until the next poll's answer replaced it. A picked frame now stays shown, the
// poll's answers held back, until "Back to live" (or a new Send or Poll).
void TestWorkbench::pickedFrameStaysWhilePolling()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    window.composer()->intervalSpin()->setValue(20);
    window.composer()->countSpin()->setValue(0); // until stopped
    window.composer()->togglePoll();
    QVERIFY(window.controller()->isPolling());
    TrafficMonitor *traffic = window.trafficMonitor();
    QTRY_VERIFY_WITH_TIMEOUT(traffic->model()->rowCount() >= 6, kAnswerWaitMs);
    TransactionView *answer = window.answerView();

    // Find the answer's bytes (the function and byte count of the read): the first row found.
    auto *search = traffic->findChild<QLineEdit *>(QStringLiteral("searchEdit"));
    QVERIFY(search);
    search->setText(QStringLiteral("01 03 2C"));
    traffic->findNext();
    QVERIFY(traffic->currentRow() >= 0);
    const quint64 picked = answer->decodeView()->exchange().transactionId;
    QVERIFY(picked != 0);
    // More answers come: the picked one stays.
    const quint64 sent = window.controller()->counters().requestsSent;
    QTRY_VERIFY_WITH_TIMEOUT(window.controller()->counters().requestsSent >= sent + 5, kAnswerWaitMs);
    QTest::qWait(2 * TransactionView::kMinRefreshMs);
    QCOMPARE(answer->decodeView()->exchange().transactionId, picked);
    auto *live = answer->findChild<QPushButton *>(QStringLiteral("answerBackToLive"));
    QVERIFY(live);
    QVERIFY(live->isVisible());
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-picked-frame.png")));

    // Back to live: the newest answer, and the ones after it.
    QTest::mouseClick(live, Qt::LeftButton);
    QVERIFY(!live->isVisible());
    QVERIFY(answer->decodeView()->exchange().transactionId > picked);
    QCOMPARE(traffic->currentRow(), -1);
    const quint64 newest = answer->decodeView()->exchange().transactionId;
    QTRY_VERIFY_WITH_TIMEOUT(answer->decodeView()->exchange().transactionId > newest, kAnswerWaitMs);

    // A picked frame, then a new poll: live again.
    traffic->findNext();
    QVERIFY(live->isVisible());
    window.composer()->togglePoll();
    QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isPolling(), kAnswerWaitMs);
    window.composer()->togglePoll();
    QVERIFY(!live->isVisible());
    window.composer()->togglePoll();
}

// Issue 26 item 15: the Registers dock kept "Profile: rosrao-gamma" (and the simulator's names)
// after connecting to another device. The profile is the simulator's: off it, none; back on it, again.
void TestWorkbench::registersProfileFollowsTheTarget()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto *profile = window.registerTable()->findChild<QLabel *>(QStringLiteral("registerTableProfile"));
    QVERIFY(profile);
    QCOMPARE(profile->text(), QStringLiteral("Profile: rosrao-gamma"));

    // Another device: an M221 PLC simulated over Modbus TCP.
    const ProfileLoadResult plcProfile = ProfileLoader::load(QStringLiteral("m221-plc"));
    QVERIFY2(plcProfile.ok, qPrintable(plcProfile.errorText()));
    SimulatorHost plc;
    QString error;
    QVERIFY2(plc.load(plcProfile.profile, &error), qPrintable(error));
    const std::optional<LinkUrl> plcUrl = plc.listen(QStringLiteral("tcp://127.0.0.1:0"), &error);
    QVERIFY2(plcUrl, qPrintable(error));
    plc.start();
    window.connectionBar()->connectButton()->click();
    QVERIFY(!window.controller()->isConnected());
    window.connectionBar()->setUrl(*plcUrl);
    window.connectionBar()->connectButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    QCOMPARE(profile->text(), QStringLiteral("Profile: none"));

    // Back on the built-in simulator: its profile again.
    window.connectionBar()->connectButton()->click();
    window.connectionBar()->setUrl(window.simulator()->started().url);
    window.connectionBar()->connectButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    QCOMPARE(profile->text(), QStringLiteral("Profile: rosrao-gamma"));
}

// Issue 26 item 16: the status bar's TX/RX went on from one connection to the next; the latency
// over time, shown again (another source chosen and back), started at the first request the window
// ever made; the Answer tab's latency and the traffic list's disagreed without saying why.
void TestWorkbench::eachConnectionCountsAlone()
{
    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    for (quint64 sent = 1; sent <= 2; ++sent) {
        window.composer()->send();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller()->counters().requestsSent, sent, kAnswerWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(window.answerView()->shown().has_value(), kAnswerWaitMs);
    }
    QTRY_VERIFY_WITH_TIMEOUT(window.linkStatus()->countersText().contains(QStringLiteral("2 requests")), kAnswerWaitMs);

    // Connected again: nothing counted yet.
    window.connectionBar()->connectButton()->click();
    window.connectionBar()->connectButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->state(), LinkController::State::Connected, kAnswerWaitMs);
    QCOMPARE(window.controller()->counters().requestsSent, quint64(0));
    QCOMPARE(window.controller()->counters().bytesOut, quint64(0));
    QVERIFY2(window.linkStatus()->countersText().startsWith(QStringLiteral("TX 0 B  RX 0 B")), qPrintable(window.linkStatus()->countersText()));
    window.composer()->send();
    QTRY_COMPARE_WITH_TIMEOUT(window.controller()->counters().requestsSent, quint64(1), kAnswerWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(window.linkStatus()->countersText().contains(QStringLiteral("1 request")), kAnswerWaitMs);

    // Latency over time shown again (a watch's source chosen, then the bench's): this connection's
    // one request, not the three since the window opened.
    WatchDefinition watch;
    watch.name = QStringLiteral("elsewhere");
    watch.target = QStringLiteral("tcp://127.0.0.1:1");
    window.watchWorkspace()->addWatch(watch);
    LatencyTimePanel *time = window.trendPanels()->latency();
    QTRY_VERIFY2_WITH_TIMEOUT(time->summary().startsWith(QStringLiteral("1 transactions")), qPrintable(time->summary()), kAnswerWaitMs);
    LatencySource *source = window.latencyAnalysis()->source();
    QVERIFY(source->choiceCount() > 1);
    source->setChoice(source->choiceCount() - 1);
    source->setChoice(0);
    QVERIFY2(time->summary().startsWith(QStringLiteral("1 transactions")), qPrintable(time->summary()));

    // The Answer tab says which latency it shows: the transaction's, to the answer's last byte;
    // a frame picked in the traffic list, to its first byte, as the list's column.
    auto *header = window.answerView()->decodeView()->findChild<QLabel *>(QStringLiteral("exchangeHeader"));
    QVERIFY(header);
    QTRY_VERIFY_WITH_TIMEOUT(header->text().contains(QStringLiteral("to the answer's last byte")), kAnswerWaitMs);
    QVERIFY(header->toolTip().contains(QStringLiteral("first byte")));
    // The shown transaction's answer in the traffic list (the newest row of that id).
    const quint64 id = window.answerView()->shown()->id;
    TrafficModel *list = window.trafficMonitor()->model();
    const auto answerRow = [list, id] {
        for (int row = list->rowCount() - 1; row >= 0; --row) {
            const FrameExchange e = list->exchangeAt(row);
            if (e.transactionId == id && e.selected == TrafficDirection::In)
                return row;
        }
        return -1;
    };
    QTRY_VERIFY_WITH_TIMEOUT(answerRow() >= 0, kAnswerWaitMs);
    window.trafficMonitor()->selectRow(answerRow());
    QVERIFY2(header->text().contains(QStringLiteral("to the answer's first byte")), qPrintable(header->text()));
    QVERIFY(guitest::saveShot(&window, QStringLiteral("workbench-latency-named.png")));
}

QTEST_MAIN(TestWorkbench)
#include "tst_workbench.moc"
