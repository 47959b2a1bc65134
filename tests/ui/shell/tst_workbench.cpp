// The window as a whole against its built-in simulator: first run, type and send a request, the
// decoded answer (request + matched response, latency), Ctrl+Return, a taken port, a link error in
// place, a poll and its counters, screenshots.
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

#include <QtNetwork/QTcpServer>
#include <QtTest/QAbstractItemModelTester>
#include <QtWidgets/QDockWidget>
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

QTEST_MAIN(TestWorkbench)
#include "tst_workbench.moc"
