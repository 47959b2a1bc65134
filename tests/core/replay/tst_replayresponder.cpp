// ReplayResponder: the simulator answering with recorded answers, through its fault hook and
// Simulator::handleFrame as an endpoint calls it (a recording over RTU served on Modbus TCP and
// on RTU over TCP; frames built by AduBuilder).

#include "capture/captureexchange.h"
#include "protocol/adubuilder.h"
#include "replay/replayresponder.h"
#include "replay/replayscript.h"
#include "sim/simendpoint.h"
#include "sim/simulator.h"

#include <QtCore/QJsonObject>
#include <QtTest/QTest>

using namespace mbscope;

namespace {

CaptureExchange recorded(quint8 unit, const char *request, const char *answer, qint64 sentMs)
{
    CaptureExchange e;
    e.framing = Framing::Rtu;
    e.transaction.request = AduBuilder::rtu(QByteArray::fromHex(request), unit);
    const QByteArray pdu = QByteArray::fromHex(answer);
    e.transaction.sentNs = sentMs * 1'000'000;
    if (pdu.isEmpty()) {
        e.transaction.status = TransactionStatus::Timeout;
    } else {
        e.transaction.response = AduBuilder::rtu(pdu, unit);
        e.transaction.status = (quint8(pdu.at(0)) & 0x80) ? TransactionStatus::Exception : TransactionStatus::Ok;
        e.transaction.doneNs = e.transaction.sentNs + 4'000'000;
    }
    return e;
}

// The script: unit 1's read recorded three times with two values, a silence on unit 3.
ReplayScript script()
{
    ReplayScript s;
    // From 1 ms: a request sent at monotonic 0 reads as never written (Transaction::latencyNs).
    s.add(recorded(1, "0300790001", "0302041a", 1));
    s.add(recorded(1, "0300790001", "0302041b", 11));
    s.add(recorded(3, "0300790001", "", 21));
    s.add(recorded(1, "0300790001", "0302041c", 31));
    s.add(recorded(1, "0302000001", "8302", 41));
    return s;
}

} // namespace

class TestReplayResponder : public QObject
{
    Q_OBJECT

private slots:
    void script();
    void answers_data();
    void answers();
    void recordedLatencyBySpeed();
    void writesOfTheScript();
    void changingDiagnosticsOfTheScript_data();
    void changingDiagnosticsOfTheScript();
    void diagnosticsPlaces();
    void unansweredAtEndLeftOut();
};

void TestReplayResponder::script()
{
    const ReplayScript s = ::script();
    QCOMPARE(s.size(), 5);
    QCOMPARE(s.unitIds(), (QList<quint8>{1, 3}));
    QCOMPARE(s.exchanges().at(3).offsetNs, 30'000'000);
    QCOMPARE(s.exchanges().at(2).requestPdu, QByteArray::fromHex("0300790001"));
    QCOMPARE(s.recordedStatistics().count(), 5u);
    QCOMPARE(s.recordedStatistics().timeouts(), 1u);
}

void TestReplayResponder::answers_data()
{
    QTest::addColumn<QString>("listen");
    QTest::addColumn<int>("policy");
    QTest::addColumn<quint8>("unit");
    QTest::addColumn<QByteArray>("request");
    // Answer PDUs in turn for the same request sent again and again ("" for silence).
    QTest::addColumn<QList<QByteArray>>("answers");

    const auto x = [](const char *hex) { return QByteArray::fromHex(hex); };
    const int exception = int(ReplayResponder::Unrecorded::Exception0B);
    const int ignore = int(ReplayResponder::Unrecorded::Ignore);
    QTest::newRow("tcp: recorded answers in turn, cycling")
        << QStringLiteral("tcp://127.0.0.1:0") << exception << quint8(1) << x("0300790001")
        << QList<QByteArray>{x("0302041a"), x("0302041b"), x("0302041c"), x("0302041a")};
    QTest::newRow("rtu-tcp: recorded answers in turn")
        << QStringLiteral("rtu-tcp://127.0.0.1:0") << exception << quint8(1) << x("0300790001")
        << QList<QByteArray>{x("0302041a"), x("0302041b")};
    QTest::newRow("recorded exception") << QStringLiteral("tcp://127.0.0.1:0") << exception << quint8(1) << x("0302000001")
                                        << QList<QByteArray>{x("8302"), x("8302")};
    QTest::newRow("recorded silence") << QStringLiteral("tcp://127.0.0.1:0") << exception << quint8(3) << x("0300790001")
                                      << QList<QByteArray>{QByteArray(), QByteArray()};
    QTest::newRow("never recorded: 0B") << QStringLiteral("tcp://127.0.0.1:0") << exception << quint8(1) << x("0300790002")
                                        << QList<QByteArray>{x("830b")};
    QTest::newRow("never recorded: ignored") << QStringLiteral("rtu-tcp://127.0.0.1:0") << ignore << quint8(1) << x("0300790002")
                                             << QList<QByteArray>{QByteArray()};
    QTest::newRow("unit never recorded: 0B") << QStringLiteral("tcp://127.0.0.1:0") << exception << quint8(9) << x("0300790001")
                                             << QList<QByteArray>{x("830b")};
    QTest::newRow("unit never recorded: ignored") << QStringLiteral("tcp://127.0.0.1:0") << ignore << quint8(9) << x("0300790001")
                                                  << QList<QByteArray>{QByteArray()};
}

void TestReplayResponder::answers()
{
    QFETCH(QString, listen);
    QFETCH(int, policy);
    QFETCH(quint8, unit);
    QFETCH(QByteArray, request);
    QFETCH(QList<QByteArray>, answers);

    const ReplayScript s = ::script();
    ReplayResponder responder(s, ReplayResponder::Unrecorded(policy), 0);
    Simulator sim;
    responder.install(sim);
    QString error;
    SimEndpoint *endpoint = sim.listen(listen, responder.endpointOptions(), &error);
    QVERIFY2(endpoint, qPrintable(error));
    const Framing framing = endpoint->framing();
    quint16 transactionId = 0x1200;
    for (const QByteArray &expected : answers) {
        AduOptions options;
        options.framing = framing;
        options.unitId = unit;
        options.transactionId = ++transactionId;
        const QByteArray adu = AduBuilder::complete(request, options);
        const FaultPlan plan = sim.handleFrame(endpoint, adu, FrameStatus::Valid, QStringLiteral("test"), 0);
        if (expected.isEmpty()) {
            QVERIFY(plan.drop);
            continue;
        }
        QVERIFY(!plan.drop);
        QCOMPARE(plan.chunks.size(), 1);
        // Framed for this endpoint, with the request's unit and transaction id; speed 0: at once.
        QCOMPARE(plan.chunks.constFirst().bytes.toHex(' '), AduBuilder::complete(expected, options).toHex(' '));
        QCOMPARE(plan.chunks.constFirst().delayNs, 0);
    }
}

void TestReplayResponder::recordedLatencyBySpeed()
{
    // Recorded 4 ms; --speed 2 answers after 2 ms, --speed 1 after 4 ms.
    const ReplayScript s = ::script();
    for (const double speed : {1.0, 2.0}) {
        ReplayResponder responder(s, ReplayResponder::Unrecorded::Exception0B, speed);
        SimExchange exchange;
        exchange.framing = Framing::Rtu;
        exchange.unitId = 1;
        exchange.requestPdu = QByteArray::fromHex("0300790001");
        const FaultPlan plan = responder.answer(exchange);
        QCOMPARE(plan.chunks.size(), 1);
        QCOMPARE(plan.chunks.constFirst().delayNs, qint64(4'000'000 / speed));
        QCOMPARE(plan.chunks.constFirst().bytes, AduBuilder::rtu(QByteArray::fromHex("0302041a"), 1));
        QCOMPARE(responder.counters().served, 1u);
    }
}

// Issue 26 item 1: the requests that write, with where they write (what replay lists as not sent).
void TestReplayResponder::writesOfTheScript()
{
    ReplayScript s;
    s.add(recorded(1, "0300790001", "0302041a", 1));
    s.add(recorded(1, "05001fff00", "05001fff00", 2));                 // coil 0x001F on
    s.add(recorded(1, "06007d00fa", "06007d00fa", 3));                 // register 0x007D
    s.add(recorded(2, "0f0010000a020f03", "0f0010000a", 4));           // 10 coils from 0x0010
    s.add(recorded(2, "10010000020400010002", "1001000002", 5));       // 2 registers from 0x0100
    s.add(recorded(1, "16007d00f20025", "16007d00f20025", 6));         // mask write 0x007D
    s.add(recorded(3, "17000000020020000102000a", "170400000000", 7)); // write 1 at 0x0020
    s.add(recorded(1, "150d06000400070003000100020003", "150d06000400070003000100020003", 8)); // file 4 record 7, 3 registers
    s.add(recorded(1, "06", "8603", 9));                               // too short to say where
    s.add(recorded(1, "0800000000", "0800000000", 10));                // Return Query Data: only echoes
    const QList<RecordedWrite> writes = s.writes();
    QCOMPARE(writes.size(), 8);
    QStringList texts;
    for (const RecordedWrite &w : writes)
        texts.append(w.text());
    QCOMPARE(texts, (QStringList{
                        QStringLiteral("#2 unit 1 Write Single Coil (0x05) address 0x001F quantity 1"),
                        QStringLiteral("#3 unit 1 Write Single Register (0x06) address 0x007D quantity 1"),
                        QStringLiteral("#4 unit 2 Write Multiple Coils (0x0F) address 0x0010 quantity 10"),
                        QStringLiteral("#5 unit 2 Write Multiple Registers (0x10) address 0x0100 quantity 2"),
                        QStringLiteral("#6 unit 1 Mask Write Register (0x16) address 0x007D quantity 1"),
                        QStringLiteral("#7 unit 3 Read/Write Multiple Registers (0x17) address 0x0020 quantity 1"),
                        QStringLiteral("#8 unit 1 Write File Record (0x15) record 0x0007 quantity 3"),
                        QStringLiteral("#9 unit 1 Write Single Register (0x06), too short to say where it writes"),
                    }));
    QCOMPARE(RecordedWrite::placesText(writes),
             QStringLiteral("unit 1 at an unknown address, 0x0007-0x0009, 0x001F, 0x007D (2 times); unit 2 at 0x0010-0x0019, "
                            "0x0100-0x0101; unit 3 at 0x0020"));
    const QJsonObject json = writes.at(3).toJson();
    QCOMPARE(json.value(QStringLiteral("address")).toInt(), 0x100);
    QCOMPARE(json.value(QStringLiteral("quantity")).toInt(), 2);
    QCOMPARE(json.value(QStringLiteral("function")).toString(), QStringLiteral("0x10"));
    QVERIFY(writes.at(7).toJson().value(QStringLiteral("address")).isNull());
}

// Issue 26 item 1: Diagnostics sub-functions that change the device (restart, listen only,
// clear counters, change the ASCII delimiter, clear overrun) are held back like writes; those that
// only read are not.
void TestReplayResponder::changingDiagnosticsOfTheScript_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<bool>("heldBack");
    QTest::addColumn<QString>("text");
    QTest::newRow("00 return query data") << QByteArray("080000a537") << false << QString();
    QTest::newRow("01 restart") << QByteArray("080001ff00") << true
                                << QStringLiteral("#1 unit 1 Diagnostics (0x08) sub-function 0x0001 Restart Communications Option");
    QTest::newRow("02 diagnostic register") << QByteArray("0800020000") << false << QString();
    QTest::newRow("03 ASCII delimiter") << QByteArray("0800030a00") << true
                                        << QStringLiteral("#1 unit 1 Diagnostics (0x08) sub-function 0x0003 Change ASCII Input Delimiter");
    QTest::newRow("04 listen only") << QByteArray("0800040000") << true
                                    << QStringLiteral("#1 unit 1 Diagnostics (0x08) sub-function 0x0004 Force Listen Only Mode");
    QTest::newRow("0A clear counters") << QByteArray("08000a0000") << true
                                       << QStringLiteral("#1 unit 1 Diagnostics (0x08) sub-function 0x000A Clear Counters and Diagnostic Register");
    QTest::newRow("0B bus message count") << QByteArray("08000b0000") << false << QString();
    QTest::newRow("14 clear overrun") << QByteArray("0800140000") << true
                                      << QStringLiteral("#1 unit 1 Diagnostics (0x08) sub-function 0x0014 Clear Overrun Counter and Flag");
    QTest::newRow("too short") << QByteArray("0800") << true
                               << QStringLiteral("#1 unit 1 Diagnostics (0x08), too short to say which sub-function");
}

void TestReplayResponder::changingDiagnosticsOfTheScript()
{
    QFETCH(QByteArray, request);
    QFETCH(bool, heldBack);
    QFETCH(QString, text);
    const std::optional<RecordedWrite> w = RecordedWrite::of(0, 1, QByteArray::fromHex(request));
    QCOMPARE(w.has_value(), heldBack);
    if (w)
        QCOMPARE(w->text(), text);
}

void TestReplayResponder::diagnosticsPlaces()
{
    QList<RecordedWrite> writes;
    for (const char *request : {"06007d00fa", "0800010000", "0800010000", "0800040000"})
        writes.append(*RecordedWrite::of(writes.size(), 1, QByteArray::fromHex(request)));
    writes.append(*RecordedWrite::of(writes.size(), 2, QByteArray::fromHex("08000a0000")));
    QCOMPARE(RecordedWrite::placesText(writes),
             QStringLiteral("unit 1 at 0x007D and Restart Communications Option (2 times), Force Listen Only Mode; "
                            "unit 2: Clear Counters and Diagnostic Register"));
    QCOMPARE(writes.at(1).toJson().value(QStringLiteral("subFunctionName")).toString(), QStringLiteral("Restart Communications Option"));
}

// Issue 26 item 7: a request the recording ends before the outcome of is not replayed.
void TestReplayResponder::unansweredAtEndLeftOut()
{
    ReplayScript s;
    s.add(recorded(1, "0300790001", "0302041a", 1));
    CaptureExchange cut = recorded(1, "0300790001", "", 2);
    cut.kind = CaptureExchange::Kind::Unanswered;
    s.add(cut);
    QCOMPARE(s.size(), 1);
    QCOMPARE(s.recordedStatistics().timeouts(), 0u);
}

QTEST_GUILESS_MAIN(TestReplayResponder)
#include "tst_replayresponder.moc"
