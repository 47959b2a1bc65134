// LinkController and EmbeddedSimulator without the window: states, a send, a poll's summary, a
// profile that does not exist, a port that is taken.
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "link/linkcontroller.h"

#include "exchange/statistics.h"

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
    void unknownProfileIsNamed();
    void takenPortIsSaid();
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
    // The counters go on across a new target (a new engine).
    controller.connectTo(url);
    QCOMPARE(controller.counters().bytesOut, quint64(8));
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

QTEST_MAIN(TestLinkController)
#include "tst_linkcontroller.moc"
