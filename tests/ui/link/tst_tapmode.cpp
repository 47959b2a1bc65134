// The inline tap in the window (issue 27: "a Tap mode in the window's connection bar"): the bar's
// Tap row makes a TapSetup (or says which field is wrong), Connect with Tap ticked asks for a tap;
// the LinkController runs it (TapRunner: core/tap's forwarder on a thread of its own) and hands
// both legs of every request over as frames, the master's leg as the master saw it, and records
// them into the connection's journal as `mbscope tap --record` does (a server journal that
// analyze reads as the masters saw it). A real master (a QTcpSocket speaking Modbus/TCP) asks a
// real device (the core simulator on RTU over TCP) through the tap on loopback.
#include "guitestsupport.h"

#include "capture/journalexchangereader.h"
#include "link/connectionbar.h"
#include "link/linkcontroller.h"
#include "link/tapfields.h"
#include "link/taprunner.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"
#include "sim/simunit.h"
#include "traffic/capturedirectory.h"
#include "traffic/trafficmetadata.h"
#include "traffic/trafficjournal.h"
#include "traffic/trafficmodel.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QTemporaryDir>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>

using namespace mbscope;

namespace {

constexpr int kWaitMs = 10000;

// A device: unit 1 with holding registers 0-9 (100, 101, ...), on RTU over TCP.
struct Device {
    Simulator sim;
    LinkUrl url;
    Device()
    {
        SimRange range;
        range.count = 10;
        for (int i = 0; i < 10; ++i)
            range.values.append(quint16(100 + i));
        QString error;
        if (!sim.addUnit(1)->addRange(range, &error))
            qFatal("%s", qPrintable(error));
        SimEndpoint *endpoint = sim.listen(QStringLiteral("rtu-tcp://127.0.0.1:0"), {}, &error);
        if (!endpoint)
            qFatal("%s", qPrintable(error));
        url = endpoint->boundUrl();
    }
};

// One Modbus/TCP request from a master and its answer (empty when none came in time).
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
    // The header says how long the answer is (MBAP length: unit id and PDU).
    while (clock.elapsed() < 3000 && (answer.size() < 6 || answer.size() < 6 + ((quint8(answer[4]) << 8) | quint8(answer[5])))) {
        QTest::qWait(5); // the device (in this thread) answers meanwhile
        answer += master.readAll();
    }
    return answer;
}

struct Row {
    QString link;
    TrafficDirection direction;
    TrafficVerdict verdict;
    QByteArray bytes;
};

QList<Row> rowsOf(const QList<QList<QVariant>> &batches)
{
    QList<Row> rows;
    for (const QList<QVariant> &batch : batches) {
        const auto frames = batch.at(0).value<QList<TrafficFrame>>();
        const QStringList links = batch.at(1).toStringList();
        for (const TrafficFrame &f : frames)
            rows.append(Row{links.value(f.link), f.direction, f.verdict, f.bytes});
    }
    return rows;
}

} // namespace

class TestTapMode : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { guitest::isolateSettings(); }
    void barMakesTheSetup_data();
    void barMakesTheSetup();
    void barAsksForATapNotAConnection();
    void controllerTapsBothLegs_data();
    void controllerTapsBothLegs();
    void recordingHoldsBothLegs();
    void portInUseIsSaid();
};

void TestTapMode::barMakesTheSetup_data()
{
    QTest::addColumn<QString>("listen");
    QTest::addColumn<QString>("routes");
    QTest::addColumn<bool>("readOnly");
    QTest::addColumn<QString>("error");     // a part of the message, or empty: a setup is made
    QTest::addColumn<QStringList>("arguments"); // what mbscope tap would be given (the bar's target last)

    // The bar's target is rtu-tcp://127.0.0.1:4001 with its timeout field's 1000 ms.
    const auto args = [](const char *text) { return QString::fromLatin1(text).split(QLatin1Char(' ')); };
    QTest::newRow("one listen URL, every unit to the target")
        << "tcp://127.0.0.1:5020" << "" << false << ""
        << args("--listen tcp://127.0.0.1:5020 --target rtu-tcp://127.0.0.1:4001?timeout=1000ms --timeout 1000ms");
    QTest::newRow("two listen URLs, a renumbering route, read-only")
        << "tcp://127.0.0.1:0  udp://127.0.0.1:0" << "1:17=tcp://10.0.0.5:502" << true << ""
        << args("--listen tcp://127.0.0.1:0 --listen udp://127.0.0.1:0 --route 1:17=tcp://10.0.0.5:502 "
                "--target rtu-tcp://127.0.0.1:4001?timeout=1000ms --timeout 1000ms --read-only");
    QTest::newRow("no listen URL") << "  " << "" << false << "Masters connect to: type where" << QStringList{};
    QTest::newRow("a listen URL that is none") << "tcp://127.0.0.1:99999" << "" << false
                                               << "Masters connect to: 'tcp://127.0.0.1:99999'" << QStringList{};
    QTest::newRow("a route past unit 255") << "tcp://127.0.0.1:0" << "250-300=tcp://10.0.0.5:502" << false
                                           << "Routes: '250-300=tcp://10.0.0.5:502': unit 300" << QStringList{};
    QTest::newRow("a route without a URL") << "tcp://127.0.0.1:0" << "7" << false << "Routes: '7': expected UNITS" << QStringList{};
}

void TestTapMode::barMakesTheSetup()
{
    QFETCH(QString, listen);
    QFETCH(QString, routes);
    QFETCH(bool, readOnly);
    QFETCH(QString, error);
    QFETCH(QStringList, arguments);

    ConnectionBar bar;
    bar.setUrl(*LinkUrl::parse(u"rtu-tcp://127.0.0.1:4001").url);
    bar.setTap(true);
    bar.tapFields()->listenEdit()->setText(listen);
    bar.tapFields()->routesEdit()->setText(routes);
    bar.tapFields()->readOnlyCheck()->setChecked(readOnly);
    const std::optional<TapSetup> setup = bar.tapSetup();
    if (!error.isEmpty()) {
        QVERIFY(!setup);
        QVERIFY2(bar.errorText().contains(error), qPrintable(bar.errorText()));
        return;
    }
    QVERIFY2(setup, qPrintable(bar.errorText()));
    QCOMPARE(setup->arguments(), arguments);
    QCOMPARE(setup->settings.readOnly, readOnly);
    QCOMPARE(setup->settings.routes.constLast().target.kind, LinkKind::RtuTcp);
}

void TestTapMode::barAsksForATapNotAConnection()
{
    ConnectionBar bar;
    bar.show();
    bar.setUrl(*LinkUrl::parse(u"rtu-tcp://127.0.0.1:4001").url);
    auto *listen = bar.findChild<QCheckBox *>(QStringLiteral("listenOnlyCheck"));
    auto *tap = bar.findChild<QCheckBox *>(QStringLiteral("tapCheck"));
    QVERIFY(listen && tap);
    QVERIFY(!bar.tapFields()->isVisible());
    listen->setChecked(true);
    tap->setChecked(true); // one or the other
    QVERIFY(!listen->isChecked());
    QVERIFY(bar.tapFields()->isVisible());
    QVERIFY(!bar.isListenOnly());

    QSignalSpy tapSpy(&bar, &ConnectionBar::tapRequested);
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    QSignalSpy listenSpy(&bar, &ConnectionBar::listenRequested);
    bar.tapFields()->listenEdit()->setText(QStringLiteral("tcp://127.0.0.1:0"));
    bar.connectButton()->click();
    QCOMPARE(tapSpy.size(), 1);
    QCOMPARE(connectSpy.size(), 0);
    QCOMPARE(listenSpy.size(), 0);
    QCOMPARE(tapSpy.at(0).at(0).value<TapSetup>().listen.constFirst().toString(), QStringLiteral("tcp://127.0.0.1:0"));
    // The fields are kept for the next start.
    TapFields again;
    QCOMPARE(again.listenEdit()->text(), QStringLiteral("tcp://127.0.0.1:0"));
    // A running tap's fields are locked.
    bar.setConnected(true);
    QVERIFY(!tap->isEnabled());
    QVERIFY(!bar.tapFields()->listenEdit()->isEnabled());
    bar.setConnected(false);
    QVERIFY(bar.tapFields()->listenEdit()->isEnabled());
}

void TestTapMode::controllerTapsBothLegs_data()
{
    QTest::addColumn<bool>("readOnly");
    QTest::addColumn<QByteArray>("request"); // Modbus/TCP, from the master
    QTest::addColumn<QByteArray>("answer");  // what the master gets
    QTest::addColumn<int>("deviceFrames");   // frames of the device's leg (RTU over TCP)
    QTest::addColumn<int>("masterVerdict");  // of the master's answer in the list

    QTest::newRow("read: both legs") << false << QByteArray::fromHex("000700000006010300000002")
                                     << QByteArray::fromHex("00070000000701030400640065") << 2 << int(TrafficVerdict::Ok);
    QTest::newRow("the device's exception: both legs") << false << QByteArray::fromHex("000800000006010300640001")
                                                       << QByteArray::fromHex("000800000003018302") << 2
                                                       << int(TrafficVerdict::Exception);
    QTest::newRow("read-only refuses a write: the master's leg only")
        << true << QByteArray::fromHex("00090000000601060001002a") << QByteArray::fromHex("000900000003018601") << 0
        << int(TrafficVerdict::Exception);
}

void TestTapMode::controllerTapsBothLegs()
{
    QFETCH(bool, readOnly);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, answer);
    QFETCH(int, deviceFrames);
    QFETCH(int, masterVerdict);

    Device device;
    TapSetup setup;
    setup.listen = {*LinkUrl::parse(u"tcp://127.0.0.1:0", LinkUse::Listen).url};
    TapRoute every;
    every.target = device.url;
    setup.settings.routes = {every};
    setup.settings.readOnly = readOnly;

    LinkController controller;
    QSignalSpy frames(&controller, &LinkController::tapFramesLogged);
    QSignalSpy counters(&controller, &LinkController::tapCountersChanged);
    controller.tapTo(setup);
    QVERIFY(controller.isTapping());
    QCOMPARE(controller.state(), LinkController::State::Connected);
    const QString endpoint = controller.tap()->endpoints().value(0);
    QVERIFY2(controller.message().contains(endpoint), qPrintable(controller.message()));
    QCOMPARE(controller.send(request), quint64(0)); // the window does not send while tapping
    QVERIFY(!controller.startPoll(request, 100, 1));

    QCOMPARE(ask(endpoint, request), answer);
    const int expected = 2 + deviceFrames;
    QTRY_COMPARE_WITH_TIMEOUT(rowsOf(frames).size(), expected, kWaitMs);
    const QList<Row> rows = rowsOf(frames);
    // The master's leg as the master saw it: its request out, the tap's answer in.
    QCOMPARE(rows.first().link, endpoint);
    QCOMPARE(rows.first().direction, TrafficDirection::Out);
    QCOMPARE(rows.first().verdict, TrafficVerdict::Sent);
    QCOMPARE(rows.first().bytes, request);
    QCOMPARE(rows.last().link, endpoint);
    QCOMPARE(rows.last().direction, TrafficDirection::In);
    QCOMPARE(int(rows.last().verdict), masterVerdict);
    QCOMPARE(rows.last().bytes, answer);
    if (deviceFrames > 0) {
        // The device's leg in between, in its own framing: RTU, the same PDU.
        QCOMPARE(rows.at(1).link, device.url.toString());
        QCOMPARE(rows.at(1).direction, TrafficDirection::Out);
        QCOMPARE(rows.at(1).bytes.mid(1, rows.at(1).bytes.size() - 3), request.mid(7));
        QCOMPARE(rows.at(2).direction, TrafficDirection::In);
        QCOMPARE(rows.at(2).bytes.mid(1, rows.at(2).bytes.size() - 3), answer.mid(7));
    }
    QTRY_VERIFY(!counters.isEmpty());
    const auto last = counters.constLast().at(0).value<TapCounters>();
    QCOMPARE(last.requests, quint64(1));
    QCOMPARE(last.refusedWrites, quint64(readOnly ? 1 : 0));

    // The traffic list pairs both legs and times each.
    TrafficModel model;
    for (const QList<QVariant> &batch : std::as_const(frames))
        model.appendNamedFrames(batch.at(0).value<QList<TrafficFrame>>(), batch.at(1).toStringList());
    QCOMPARE(model.rowCount(), expected);
    for (int row = 0; row < expected; ++row) {
        const FrameExchange exchange = model.exchangeAt(row);
        QVERIFY2(!exchange.request.isEmpty() && !exchange.response.isEmpty(), qPrintable(QString::number(row)));
        QVERIFY(exchange.latencyNs >= 0);
    }
    QCOMPARE(model.exchangeAt(0).framing, Framing::Tcp);
    if (deviceFrames > 0) {
        QCOMPARE(model.exchangeAt(1).framing, Framing::Rtu);
        // The master waited for the device and for the tap: never less than the device's leg.
        QVERIFY(model.exchangeAt(expected - 1).latencyNs >= model.exchangeAt(2).latencyNs);
    }

    controller.disconnectLink();
    QVERIFY(!controller.isTapping());
    QCOMPARE(controller.state(), LinkController::State::Disconnected);
}

// The recording is the tap's journal: a server's, with where it listened, so that analyze reads
// the master's leg as the masters saw it and the device's as the tap's engine did.
void TestTapMode::recordingHoldsBothLegs()
{
    QTemporaryDir folder;
    Device device;
    TapSetup setup;
    setup.listen = {*LinkUrl::parse(u"tcp://127.0.0.1:0", LinkUse::Listen).url};
    TapRoute every;
    every.target = device.url;
    setup.settings.routes = {every};

    LinkController controller;
    controller.setRecording(true, CaptureDirectory(folder.path()), RollingCapture::Policy{});
    controller.tapTo(setup);
    const QString journal = controller.recordingPath();
    QVERIFY2(!journal.isEmpty(), qPrintable(controller.recordingProblem()));
    QVERIFY(controller.trafficLog() == nullptr); // nobody else writes into the tap's journal
    const QString endpoint = controller.tap()->endpoints().value(0);
    for (int i = 0; i < 3; ++i)
        QVERIFY(!ask(endpoint, QByteArray::fromHex("000100000006010300000002")).isEmpty());
    controller.disconnectLink();

    QList<CaptureExchange> exchanges;
    const JournalExchangeReader::Result read = JournalExchangeReader::read(journal, [&](const CaptureExchange &e) { exchanges.append(e); });
    QVERIFY2(read.recovery.isClean(), qPrintable(read.recovery.message));
    TrafficMetadata metadata;
    QString why;
    QVERIFY(TrafficMetadata::fromJson(read.recovery.metadata, &metadata, &why));
    QCOMPARE(metadata.role, TrafficMetadata::Role::Server);
    QCOMPARE(metadata.listen, QStringList{endpoint});
    QCOMPARE(metadata.target, device.url.toString());
    QCOMPARE(exchanges.size(), 6); // three requests, each on both legs
    int ok = 0;
    for (const CaptureExchange &e : std::as_const(exchanges))
        ok += e.transaction.status == TransactionStatus::Ok ? 1 : 0;
    QCOMPARE(ok, 6);
}

void TestTapMode::portInUseIsSaid()
{
    Device device;
    QTcpServer taken;
    QVERIFY(taken.listen(QHostAddress::LocalHost, 0));
    TapSetup setup;
    setup.listen = {*LinkUrl::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(taken.serverPort()), LinkUse::Listen).url};
    TapRoute every;
    every.target = device.url;
    setup.settings.routes = {every};
    LinkController controller;
    QSignalSpy failed(&controller, &LinkController::tapFailed);
    controller.tapTo(setup);
    QCOMPARE(failed.size(), 1);
    QVERIFY2(failed.at(0).at(0).toString().contains(QString::number(taken.serverPort())), qPrintable(failed.at(0).at(0).toString()));
    QVERIFY(!controller.isTapping());
    QCOMPARE(controller.state(), LinkController::State::Disconnected);
}

QTEST_MAIN(TestTapMode)
#include "tst_tapmode.moc"
