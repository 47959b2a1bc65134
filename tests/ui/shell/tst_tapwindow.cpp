// The inline tap in the window, driven as a user does (issue 27: "a Tap mode in the window's
// connection bar", "shown live in the window's traffic and decode views, recorded to a journal,
// analysable and exportable like any other traffic"): the first run's built-in simulator is the
// device (RTU over TCP), the user disconnects, ticks Tap, says where masters connect and presses
// Connect; a master (a QTcpSocket speaking Modbus/TCP) reads the RosRao registers through the
// tap. Both legs are listed, each decodes in the Answer tab in its own framing, the composer says
// why it does not send, the banner says where masters go, and Save Traffic As keeps both legs.
#include "guitestsupport.h"

#include "capture/journalexchangereader.h"
#include "compose/requestcomposer.h"
#include "decode/decodeview.h"
#include "decode/transactionview.h"
#include "link/connectionbar.h"
#include "link/linkcontroller.h"
#include "link/tapfields.h"
#include "link/taprunner.h"
#include "common/noticebanner.h"
#include "shell/mainwindow.h"
#include "shell/linkstatuswidget.h"
#include "sim/embeddedsimulator.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableView>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 10000;
const QString kAnyPort = QStringLiteral("rtu-tcp://127.0.0.1:0");

QByteArray ask(const QString &endpoint, const QByteArray &request)
{
    const LinkUrl url = *LinkUrl::parse(endpoint).url;
    QTcpSocket master;
    master.connectToHost(url.host, url.port);
    if (!master.waitForConnected(kWaitMs))
        return {};
    master.write(request);
    QByteArray answer;
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 3000 && (answer.size() < 6 || answer.size() < 6 + ((quint8(answer[4]) << 8) | quint8(answer[5])))) {
        QTest::qWait(5);
        answer += master.readAll();
    }
    return answer;
}

// The list's row of the frame on link in direction dir (-1: none).
int rowOf(const TrafficModel *model, const QString &link, TrafficDirection dir)
{
    for (int row = 0; row < model->rowCount(); ++row) {
        const FrameExchange e = model->exchangeAt(row);
        if (e.link == link && e.selected == dir)
            return row;
    }
    return -1;
}

} // namespace

class TestTapWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void tapInTheWindow_data();
    void tapInTheWindow();
};

void TestTapWindow::tapInTheWindow_data()
{
    QTest::addColumn<bool>("readOnly");
    QTest::addColumn<QByteArray>("request"); // Modbus/TCP, from the master
    QTest::addColumn<int>("rows");           // in the traffic list
    QTest::addColumn<QString>("summary");    // the master's answer, decoded in the Answer tab
    QTest::addColumn<QByteArray>("faults");  // the Tap row's fault rules file ("": none)

    // The RosRao read of the first run, 22 registers from 0x79, through the tap.
    QTest::newRow("read") << false << QByteArray::fromHex("002a00000006010300790016") << 4
                          << QStringLiteral("Read Holding Registers") << QByteArray();
    // A write on a read-only tap: refused with 01, the device never sees it.
    QTest::newRow("read-only write") << true << QByteArray::fromHex("002b0000000601060079002a") << 2
                                     << QStringLiteral("exception") << QByteArray();
    // Faults on the way back: the device answers, the master gets exception 06 instead (the
    // simulator's rules, from the file in the Tap row's Faults field).
    QTest::newRow("faults") << false << QByteArray::fromHex("002c00000006010300790016") << 4 << QStringLiteral("exception")
                            << QByteArray(R"({"rules": [{"kind": "exception", "code": 6, "name": "busy"}]})");
}

void TestTapWindow::tapInTheWindow()
{
    QFETCH(bool, readOnly);
    QFETCH(QByteArray, request);
    QFETCH(int, rows);
    QFETCH(QString, summary);
    QFETCH(QByteArray, faults);
    QTemporaryDir faultsDir;
    QString faultsFile;
    if (!faults.isEmpty()) {
        faultsFile = faultsDir.filePath(QStringLiteral("busy.json"));
        QFile f(faultsFile);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(faults);
    }

    MainWindow window;
    QVERIFY(window.startWithSimulator(kAnyPort));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    LinkController *link = window.controller();
    QTRY_COMPARE_WITH_TIMEOUT(link->state(), LinkController::State::Connected, kWaitMs);
    ConnectionBar *bar = window.connectionBar();

    // Disconnect, tick Tap, say where masters connect, Connect.
    bar->connectButton()->click();
    QCOMPARE(link->state(), LinkController::State::Disconnected);
    window.trafficMonitor()->clear();
    auto *tap = bar->findChild<QCheckBox *>(QStringLiteral("tapCheck"));
    QVERIFY(tap && tap->isEnabled());
    tap->click();
    QVERIFY(bar->tapFields()->isVisible());
    QVERIFY2(guitest::mnemonicClashes(&window).isEmpty(), qPrintable(guitest::mnemonicClashes(&window).join(QLatin1Char('\n'))));
    bar->tapFields()->listenEdit()->setText(QStringLiteral("tcp://127.0.0.1:0"));
    bar->tapFields()->readOnlyCheck()->setChecked(readOnly);
    bar->tapFields()->faultsEdit()->setText(faultsFile);
    bar->connectButton()->click();
    QVERIFY2(link->isTapping(), qPrintable(bar->errorText()));
    QCOMPARE(link->state(), LinkController::State::Connected);
    const QString endpoint = link->tap()->endpoints().value(0);
    const QString device = window.simulator()->started().url.toString();
    QVERIFY(!bar->tapFields()->listenEdit()->isEnabled()); // locked while the tap runs
    QVERIFY(!bar->tapFields()->faultsEdit()->isEnabled());
    QVERIFY(!window.composer()->findChild<QPushButton *>(QStringLiteral("sendButton"))->isEnabled());
    QVERIFY2(window.banner()->text().contains(endpoint), qPrintable(window.banner()->text()));

    // A master reads (or writes) through the tap.
    const QByteArray answer = ask(endpoint, request);
    QVERIFY(!answer.isEmpty());
    TrafficModel *model = window.trafficMonitor()->model();
    QTRY_COMPARE_WITH_TIMEOUT(model->rowCount(), rows, kWaitMs);
    QTRY_VERIFY(bar->tapFields()->countersText().contains(QStringLiteral("1 requests from masters")));

    // The master's answer, picked in the list, decodes in the Answer tab as Modbus/TCP.
    const int masterAnswer = rowOf(model, endpoint, TrafficDirection::In);
    QVERIFY(masterAnswer >= 0);
    window.trafficMonitor()->selectRow(masterAnswer);
    DecodeView *decode = window.answerView()->decodeView();
    QTRY_COMPARE(decode->exchange().link, endpoint);
    QCOMPARE(decode->exchange().response, answer);
    QCOMPARE(decode->responseDissection().framing, Framing::Tcp);
    QVERIFY2(decode->responseDissection().summary().contains(summary, Qt::CaseInsensitive),
             qPrintable(decode->responseDissection().summary()));
    QVERIFY(decode->exchange().latencyNs >= 0);

    const int deviceAnswer = rowOf(model, device, TrafficDirection::In);
    if (rows == 4) {
        // The device's leg: RTU over TCP, the same registers, its own latency.
        QVERIFY(deviceAnswer >= 0);
        window.trafficMonitor()->selectRow(deviceAnswer);
        QTRY_COMPARE(decode->exchange().link, device);
        QCOMPARE(decode->responseDissection().framing, Framing::Rtu);
        QVERIFY(decode->responseDissection().isValid());
        if (faults.isEmpty())
            QCOMPARE(decode->exchange().response.mid(1, decode->exchange().response.size() - 3), answer.mid(7));
        else // the device answered normally; the master got the fault's exception
            QCOMPARE(answer.mid(7), QByteArray::fromHex("8306"));
        QVERIFY(decode->exchange().latencyNs >= 0);
        QVERIFY(window.linkStatus()->countersText().contains(QStringLiteral("1 request")));
    } else {
        QCOMPARE(deviceAnswer, -1); // read-only: nothing reached the device
    }
    // The guide's picture (scripts/screenshots.sh asks for it): the master's answer picked.
    window.trafficMonitor()->selectRow(masterAnswer);
    QTRY_COMPARE(decode->exchange().link, endpoint);
    const QString shot = qEnvironmentVariable("MBSCOPE_TAP_SCREENSHOT");
    if (!shot.isEmpty() && rows == 4) {
        QCoreApplication::sendPostedEvents();
        QVERIFY(window.grab().save(shot, "PNG"));
    }
    QVERIFY(guitest::saveShot(&window, QStringLiteral("tap-window-%1.png").arg(QString::fromLatin1(QTest::currentDataTag()).replace(u' ', u'-'))));

    // Save Traffic As keeps both legs, the master's as the master saw it.
    QTemporaryDir folder;
    const QString saved = folder.filePath(QStringLiteral("tap.mbscope.journal"));
    QVERIFY(window.trafficMonitor()->saveTo(saved, TrafficFormat::Journal, false).ok);
    QList<CaptureExchange> exchanges;
    const JournalExchangeReader::Result read = JournalExchangeReader::read(saved, [&](const CaptureExchange &e) { exchanges.append(e); });
    QVERIFY2(read.recovery.frames == quint64(rows), qPrintable(read.recovery.message));
    QCOMPARE(exchanges.size(), rows / 2);

    // Disconnect stops the tap: the masters' port closes, the composer sends again.
    bar->connectButton()->click();
    QVERIFY(!link->isTapping());
    QVERIFY(bar->tapFields()->listenEdit()->isEnabled());
    QTcpSocket late;
    const LinkUrl url = *LinkUrl::parse(endpoint).url;
    late.connectToHost(url.host, url.port);
    QVERIFY(!late.waitForConnected(2000)); // refused: nobody listens there any more
}

QTEST_MAIN(TestTapWindow)
#include "tst_tapwindow.moc"
