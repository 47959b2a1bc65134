// The traffic monitor fed as the window feeds it: TransactionEngine::framesLogged into
// appendLinkFrames, against the embedded simulator (rosrao-gamma on rtu-tcp, a port from the
// OS), then a device server that never answers. An answered read, an exception and a timeout
// become their rows, each on its link, with real timestamps and latencies; the rows are the
// engine's own traffic log frame for frame (one store: the same frames, verdicts and transaction
// ids), and selecting a row shows the exchange in a DecodeView.
#include "decode/decodeview.h"
#include "sim/embeddedsimulator.h"
#include "guitestsupport.h"
#include "traffic/trafficmodel.h"
#include "traffic/trafficmonitor.h"

#include "exchange/requestitem.h"
#include "engine/transactionengine.h"
#include "traffic/trafficlog.h"

#include <QtNetwork/QTcpServer>
#include <QtTest/QAbstractItemModelTester>
#include <QtTest/QtTest>

using namespace mbscope;

namespace {

// RosRao's read of 22 registers from 121 (tests/data/published-frames.json).
const QByteArray kRosRaoRead = QByteArray::fromHex("01 03 00 79 00 16 15 DD");
// An RTU frame: unit and PDU with its CRC-16/MODBUS, low byte first (Serial Line V1.02, 2.5.1.2).
QByteArray withCrc(QByteArray pdu)
{
    quint16 crc = 0xFFFF;
    for (const char c : std::as_const(pdu)) {
        crc ^= quint8(c);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1) ? (crc >> 1) ^ 0xA001 : crc >> 1;
    }
    pdu.append(char(crc & 0xFF));
    pdu.append(char(crc >> 8));
    return pdu;
}

} // namespace

class TestTrafficFeed : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void engineTransactionsBecomeRows();
};

void TestTrafficFeed::engineTransactionsBecomeRows()
{
    EmbeddedSimulator simulator;
    const EmbeddedSimulator::Started started = simulator.start(QStringLiteral("rosrao-gamma"), QStringLiteral("rtu-tcp://127.0.0.1:0"));
    QVERIFY2(started.ok, qPrintable(started.error));
    const LinkUrl url = started.url;

    TrafficMonitor monitor;
    QAbstractItemModelTester tester(monitor.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    DecodeView decode;
    QObject::connect(&monitor, &TrafficMonitor::frameSelected, &decode, &DecodeView::showExchange);

    TrafficLog log;
    TransactionEngine engine;
    engine.setTarget(url);
    engine.setTrafficLog(&log);
    engine.setFramesPublished(true);
    QObject::connect(&engine, &TransactionEngine::framesLogged, &monitor, &TrafficMonitor::appendLinkFrames);

    RequestItem read = RequestItem::forLink(kRosRaoRead, url);
    const std::optional<Transaction> answered = engine.sendAndWait(read);
    QVERIFY(answered);
    QCOMPARE(answered->status, TransactionStatus::Ok);
    // Register 0xFFF0 is outside the profile's table: an exception.
    RequestItem outside = RequestItem::forLink(withCrc(QByteArray::fromHex("0103FFF00001")), url);
    const std::optional<Transaction> exception = engine.sendAndWait(outside);
    QVERIFY(exception);
    QCOMPARE(exception->status, TransactionStatus::Exception);
    // A device server whose device never answers: it accepts and stays silent.
    QTcpServer silent;
    QVERIFY(silent.listen(QHostAddress::LocalHost, 0));
    const LinkUrl::Result quiet = LinkUrl::parse(QStringLiteral("rtu-tcp://127.0.0.1:%1").arg(silent.serverPort()));
    QVERIFY2(quiet.url, qPrintable(quiet.error));
    engine.setTarget(*quiet.url);
    RequestItem nobody = RequestItem::forLink(withCrc(QByteArray::fromHex("630300790001")), *quiet.url);
    nobody.timeoutMs = 200;
    const std::optional<Transaction> timeout = engine.sendAndWait(nobody);
    QVERIFY(timeout);
    QCOMPARE(timeout->status, TransactionStatus::Timeout);

    TrafficModel *model = monitor.model();
    QTRY_COMPARE(model->rowCount(), 6);
    const auto text = [model](int row, int column) { return model->data(model->index(row, column)).toString(); };
    const QStringList verdicts{QStringLiteral("sent"), QStringLiteral("ok"), QStringLiteral("sent"),
                               QStringLiteral("exception"), QStringLiteral("sent"), QStringLiteral("timeout")};
    for (int r = 0; r < 6; ++r) {
        QCOMPARE(text(r, TrafficModel::VerdictColumn), verdicts.at(r));
        QCOMPARE(text(r, TrafficModel::LinkColumn), r < 4 ? url.toString() : quiet.url->toString());
    }
    QCOMPARE(text(1, TrafficModel::LengthColumn), QStringLiteral("49"));
    QCOMPARE(text(1, TrafficModel::UnitColumn), QStringLiteral("1"));
    QCOMPARE(text(4, TrafficModel::UnitColumn), QStringLiteral("99"));
    QCOMPARE(text(5, TrafficModel::LengthColumn), QStringLiteral("0"));
    QCOMPARE(text(5, TrafficModel::UnitColumn), QStringLiteral("99")); // a timeout's unit is its request's

    // The rows are the engine's log, frame for frame.
    engine.setTrafficLog(nullptr);
    QCOMPARE(log.size(), quint64(6));
    for (int r = 0; r < 6; ++r) {
        const TrafficEntry logged = log.at(quint64(r));
        const TrafficEntry listed = model->frameAt(model->storeRow(r));
        QCOMPARE(listed.tNs, logged.tNs);
        QCOMPARE(listed.direction, logged.direction);
        QCOMPARE(listed.verdict, logged.verdict);
        QCOMPARE(listed.transactionId, logged.transactionId);
        QCOMPARE(listed.bytes.toByteArray(), logged.bytes.toByteArray());
        QCOMPARE(model->links().name(listed.link), log.linkName(logged.link));
    }
    // Latency as the log tells it: the request's write to the answer's first byte.
    QCOMPARE(model->data(model->index(1, 0), TrafficModel::LatencyNsRole).toLongLong(), log.at(1).tNs - log.at(0).tNs);
    QVERIFY(answered->latencyNs() > 0);

    monitor.selectRow(1);
    QCOMPARE(decode.requestDissection().fields.frame(), kRosRaoRead);
    QCOMPARE(decode.responseDissection().fields.frame(), answered->response);
    QVERIFY(decode.responseDissection().isValid());
    QCOMPARE(decode.responseDissection().fields.indexesOf("modbus.register_value").size(), 22);
    monitor.selectRow(3);
    QCOMPARE(decode.exchange().verdict, TrafficVerdict::Exception);
    monitor.selectRow(5);
    QCOMPARE(decode.exchange().verdict, TrafficVerdict::Timeout);
    QVERIFY(decode.responseDissection().fields.isEmpty());
    simulator.stop();
}

QTEST_MAIN(TestTrafficFeed)
#include "tst_trafficfeed.moc"
