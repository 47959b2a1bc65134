// LinkController and EmbeddedSimulator without the window: states, a send, a poll's summary, a
// profile that does not exist, a port that is taken.
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "link/linkcontroller.h"
#include "traffic/trafficmodel.h"

#include "exchange/statistics.h"

#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpServer>
#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;

class TestLinkController : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void states();
    void sendToTheSimulator();
    void pollSummary();
    void pollKeepsTheTargetsPace();
    void unknownProfileIsNamed();
    void takenPortIsSaid();
    void connectOpensTheLink();
    void closedPortFailsAtConnect();
    void unsentRequestHasATime();
};

namespace {

LinkUrl simulatorUrl(EmbeddedSimulator &sim)
{
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    if (!started.ok)
        qWarning("%s", qPrintable(started.error));
    return started.url;
}

} // namespace

void TestLinkController::states()
{
    LinkController controller;
    QSignalSpy states(&controller, &LinkController::stateChanged);
    QCOMPARE(controller.state(), LinkController::State::Disconnected);
    QCOMPARE(controller.send(QByteArray::fromHex("01030079001615DD")), quint64(0)); // nowhere to send
    LinkUrl url;
    url.kind = LinkKind::RtuTcp;
    url.host = QStringLiteral("127.0.0.1");
    url.port = 4001;
    controller.connectTo(url);
    QCOMPARE(controller.state(), LinkController::State::Ready);
    QVERIFY(controller.isConnected());
    controller.disconnectLink();
    QCOMPARE(controller.state(), LinkController::State::Disconnected);
    QCOMPARE(states.count(), 2);
}

void TestLinkController::sendToTheSimulator()
{
    EmbeddedSimulator sim;
    const LinkUrl url = simulatorUrl(sim);
    QVERIFY(sim.isRunning());
    LinkController controller;
    QSignalSpy latest(&controller, &LinkController::latestTransaction);
    controller.connectTo(url);
    QVERIFY(controller.send(QByteArray::fromHex("01030079001615DD")) > 0);
    QVERIFY(latest.wait(5000));
    const Transaction t = latest.first().first().value<Transaction>();
    QVERIFY2(t.isOk(), qPrintable(t.problem));
    QCOMPARE(t.response.size(), 49);
    QCOMPARE(controller.state(), LinkController::State::Connected);
    QTRY_COMPARE_WITH_TIMEOUT(controller.counters().bytesOut, quint64(8), 5000);
    QTRY_COMPARE_WITH_TIMEOUT(controller.counters().bytesIn, quint64(49), 5000);
    // A new connection counts from zero (issue 26 item 16: they went on from the connection before).
    controller.connectTo(url);
    QCOMPARE(controller.counters().bytesOut, quint64(0));
    QCOMPARE(controller.counters().bytesIn, quint64(0));
}

void TestLinkController::pollSummary()
{
    EmbeddedSimulator sim;
    const LinkUrl url = simulatorUrl(sim);
    LinkController controller;
    QSignalSpy finished(&controller, &LinkController::pollFinished);
    QSignalSpy polling(&controller, &LinkController::pollingChanged);
    controller.connectTo(url);
    QVERIFY(controller.startPoll(QByteArray::fromHex("01030079001615DD"), 0, 5));
    QVERIFY(controller.isPolling());
    QVERIFY(finished.wait(10000));
    QVERIFY(!controller.isPolling());
    QCOMPARE(polling.count(), 2);
    const PollReport report = finished.first().first().value<PollReport>();
    const QString text = LinkController::describe(report);
    QVERIFY2(text.startsWith(QLatin1String("Poll finished: 5 transactions, 5 ok, 0 failed; latency min ")), qPrintable(text));
}

// Issue 28: the window's own poll keeps the device's pace when the target carries it (gap=, as
// the bar's Pace… sets it): a device that answers 06 to a request sooner than 40 ms after the one
// before gets every request of a back-to-back poll right; the same poll without it does not.
void TestLinkController::pollKeepsTheTargetsPace()
{
    QTemporaryDir dir;
    const QString profile = dir.filePath(QStringLiteral("busy.json"));
    QFile file(profile);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"name": "busy", "limits": {"minGapMs": 40}, "units": [{"id": 1, "tables": {"holding": [{"address": 0, "count": 10}]}}]})");
    file.close();
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started = sim.start(profile, QStringLiteral("tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    const QByteArray read = QByteArray::fromHex("000100000006010300000002");
    for (const bool paced : {true, false}) { // the device counts its gap across connections: the paced poll first
        LinkUrl url = started.url;
        if (paced)
            url.gap = std::chrono::milliseconds(41);
        LinkController controller;
        QSignalSpy finished(&controller, &LinkController::pollFinished);
        controller.connectTo(url);
        QVERIFY(controller.startPoll(read, 0, 6));
        QVERIFY(finished.wait(10000));
        const PollReport report = finished.first().first().value<PollReport>();
        QCOMPARE(report.runs.size(), 1);
        const Statistics &stats = report.runs.first().statistics.overall();
        QCOMPARE(stats.count(), quint64(6));
        if (paced)
            QVERIFY2(stats.ok() == 6, qPrintable(LinkController::describe(report) + stats.summary()));
        else
            QVERIFY2(stats.ok() < 6, qPrintable(LinkController::describe(report)));
    }
}

void TestLinkController::unknownProfileIsNamed()
{
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started = sim.start(QStringLiteral("no-such-profile"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY(!started.ok);
    QVERIFY(!sim.isRunning());
    QVERIFY2(started.error.contains(QLatin1String("no-such-profile")), qPrintable(started.error));
    QVERIFY2(started.error.contains(QLatin1String("rosrao-gamma")), qPrintable(started.error)); // what exists
}

void TestLinkController::takenPortIsSaid()
{
    QTcpServer squatter;
    QVERIFY(squatter.listen(QHostAddress::LocalHost, 0));
    EmbeddedSimulator sim;
    const EmbeddedSimulator::Started started =
        sim.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(squatter.serverPort()));
    QVERIFY2(started.ok, qPrintable(started.error));
    QVERIFY(started.url.port != squatter.serverPort());
    QVERIFY2(started.note.contains(QString::number(squatter.serverPort())), qPrintable(started.note));
    QVERIFY(started.note.contains(QString::number(started.url.port)));
    sim.stop();
    QVERIFY(!sim.isRunning());
}

namespace {

// A loopback port nothing listens on: taken from the OS, then let go.
quint16 closedPort()
{
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost, 0))
        return 0;
    const quint16 port = server.serverPort();
    server.close();
    return port;
}

LinkUrl tcpUrl(quint16 port)
{
    LinkUrl url;
    url.kind = LinkKind::Tcp;
    url.host = QStringLiteral("127.0.0.1");
    url.port = port;
    return url;
}

} // namespace

// Connect opens the link: Connected before any request went out.
void TestLinkController::connectOpensTheLink()
{
    EmbeddedSimulator sim;
    const LinkUrl url = simulatorUrl(sim);
    LinkController controller;
    controller.connectTo(url);
    QTRY_COMPARE_WITH_TIMEOUT(controller.state(), LinkController::State::Connected, 5000);
    QCOMPARE(controller.counters().requestsSent, quint64(0));
}

// A closed port is reported at Connect, in the link's words, not "ready" until the first Send.
void TestLinkController::closedPortFailsAtConnect()
{
    const quint16 port = closedPort();
    QVERIFY(port != 0);
    LinkController controller;
    controller.connectTo(tcpUrl(port));
    QTRY_COMPARE_WITH_TIMEOUT(controller.state(), LinkController::State::Failed, 5000);
    QVERIFY2(!controller.message().isEmpty(), "the failure says why");
}

// A request the link never took (it would not open) still has a time: when it failed. The traffic
// list places it there, not thousands of seconds before the first row.
void TestLinkController::unsentRequestHasATime()
{
    const quint16 port = closedPort();
    LinkController controller;
    TrafficModel model;
    connect(&controller, &LinkController::transactionsFinished, &model, &TrafficModel::appendTransactions);
    EmbeddedSimulator sim;
    controller.connectTo(simulatorUrl(sim));
    QSignalSpy latest(&controller, &LinkController::latestTransaction);
    QVERIFY(controller.send(QByteArray::fromHex("01030079001615DD")) > 0);
    QVERIFY(latest.wait(5000));
    controller.connectTo(tcpUrl(port));
    QTRY_COMPARE_WITH_TIMEOUT(controller.state(), LinkController::State::Failed, 5000);
    latest.clear();
    QVERIFY(controller.send(QByteArray::fromHex("000100000006010300790016")) > 0);
    QVERIFY(latest.wait(5000));
    const Transaction t = latest.first().first().value<Transaction>();
    QCOMPARE(transactionStatusName(t.status), transactionStatusName(TransactionStatus::LinkError));
    QVERIFY(t.doneNs > 0);
    QTRY_VERIFY(model.rowCount() >= 4);
    for (int row = 0; row < model.rowCount(); ++row) {
        const QString time = model.index(row, TrafficModel::TimeColumn).data().toString();
        QVERIFY2(!time.startsWith(QLatin1Char('-')) && !time.startsWith(QChar(0x2212)), qPrintable(time));
    }
}

QTEST_MAIN(TestLinkController)
#include "tst_linkcontroller.moc"
