// Exchanges -> ExchangePcapExporter (packets with synthesized Ethernet/IP/TCP or UDP) -> an
// in-memory pcapng or pcap -> ExchangeSource (reader, decoder, TCP reassembly, framers, pairer)
// gives back the same exchanges: the same bytes, times to the nanosecond, the same verdicts,
// in request order. Each row is one situation the pairer must get right.
#include "capture/captureanalysis.h"
#include "capture/capturefilewriter.h"
#include "capture/exchangepcapexporter.h"
#include "capture/exchangesource.h"
#include "exchange/responsematcher.h"
#include "protocol/adubuilder.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>

#include <QtTest/QTest>

#include <map>
#include <vector>

using namespace mbscope;

Q_DECLARE_METATYPE(std::vector<mbscope::CaptureExchange>)
Q_DECLARE_METATYPE(std::vector<mbscope::CaptureConversation>)

namespace {

constexpr qint64 kStart = 1'700'000'000'000'000'000LL;
constexpr qint64 kMs = 1'000'000;

QByteArray mbap(quint16 tid, quint8 unit, const char *pduHex)
{
    return AduBuilder::mbap(QByteArray::fromHex(pduHex), unit, tid);
}

QByteArray rtu(quint8 unit, const QByteArray &pduHex)
{
    return AduBuilder::rtu(QByteArray::fromHex(pduHex), unit);
}

CaptureConversation conversation(quint32 id, Framing framing, quint16 serverPort, bool v6 = false)
{
    CaptureConversation c;
    c.id = id;
    c.framing = framing;
    c.udp = framing == Framing::Udp;
    c.clientPort = quint16(40000 + id);
    c.serverPort = serverPort;
    if (v6) {
        c.client.v6 = c.server.v6 = true;
        c.client.bytes = {0x20, 0x01, 0x0d, 0xb8, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
        c.server.bytes = {0x20, 0x01, 0x0d, 0xb8, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2};
    } else {
        c.client.bytes = {192, 168, 1, 5};
        c.server.bytes = {192, 168, 1, quint8(10 + id)};
    }
    return c;
}

CaptureExchange exchange(quint32 conv, Framing framing, const QByteArray &request, qint64 sentNs, const QByteArray &response,
                         qint64 doneNs, TransactionStatus status, quint8 exceptionCode = 0)
{
    CaptureExchange e;
    e.conversation = conv;
    e.framing = framing;
    e.transaction.request = request;
    e.transaction.response = response;
    e.transaction.sentNs = sentNs;
    e.transaction.firstByteNs = e.transaction.doneNs = doneNs;
    e.transaction.status = status;
    e.transaction.exceptionCode = exceptionCode;
    if (request.isEmpty())
        e.kind = CaptureExchange::Kind::UnmatchedResponse;
    return e;
}

QString describe(const CaptureExchange &e)
{
    return QStringLiteral("%1 %2 -> %3 at %4..%5 %6 (%7)")
        .arg(transactionStatusName(e.transaction.status), QString::fromLatin1(e.transaction.request.toHex(' ')),
             QString::fromLatin1(e.transaction.response.toHex(' ')))
        .arg(e.transaction.sentNs - kStart)
        .arg(e.transaction.doneNs == 0 ? 0 : e.transaction.doneNs - kStart)
        .arg(e.kind == CaptureExchange::Kind::UnmatchedResponse ? QStringLiteral("unmatched") : QStringLiteral("transaction"))
        .arg(e.transaction.problem);
}

} // namespace

class TestCaptureRoundTrip : public QObject
{
    Q_OBJECT

private slots:
    void roundTrip_data();
    void roundTrip();
    void malformedRequests_data();
    void malformedRequests();
};

void TestCaptureRoundTrip::roundTrip_data()
{
    QTest::addColumn<std::vector<CaptureConversation>>("conversations");
    QTest::addColumn<std::vector<CaptureExchange>>("exchanges");
    QTest::addColumn<bool>("classicPcap");

    const Framing tcp = Framing::Tcp;
    const auto ok = TransactionStatus::Ok;
    {
        std::vector<CaptureExchange> e;
        for (int i = 0; i < 20; ++i) {
            const qint64 t = kStart + i * 100 * kMs;
            e.push_back(exchange(0, tcp, mbap(quint16(i), 1, "0300000002"), t, mbap(quint16(i), 1, "030400010002"), t + 3 * kMs + i * 1000, ok));
        }
        QTest::newRow("mbap: 20 sequential reads") << std::vector{conversation(0, tcp, 502)} << e << false;
        QTest::newRow("mbap: the same in classic pcap") << std::vector{conversation(0, tcp, 502)} << e << true;
    }
    {
        // Four requests in flight, answered last first: the transaction id pairs them.
        std::vector<CaptureExchange> e;
        for (int i = 0; i < 4; ++i)
            e.push_back(exchange(0, tcp, mbap(quint16(100 + i), 1, "0300100001"), kStart + i * 1000,
                                 mbap(quint16(100 + i), 1, "030200aa"), kStart + 10 * kMs - i * 1000, ok));
        QTest::newRow("mbap: pipelined, answers in reverse") << std::vector{conversation(0, tcp, 502)} << e << false;
    }
    QTest::newRow("mbap: exception 02")
        << std::vector{conversation(0, tcp, 502)}
        << std::vector{exchange(0, tcp, mbap(1, 1, "0300640001"), kStart, mbap(1, 1, "8302"), kStart + kMs, TransactionStatus::Exception, 2)}
        << false;
    QTest::newRow("mbap: timeout, then the late answer")
        << std::vector{conversation(0, tcp, 502)}
        << std::vector{exchange(0, tcp, mbap(7, 1, "0300000001"), kStart, {}, 0, TransactionStatus::Timeout),
                       exchange(0, tcp, mbap(8, 1, "0300000001"), kStart + 1200 * kMs, mbap(8, 1, "03020001"), kStart + 1201 * kMs, ok),
                       exchange(0, tcp, mbap(7, 1, "0300000001"), kStart, mbap(7, 1, "03020001"), kStart + 1500 * kMs,
                                TransactionStatus::Late)}
        << false;
    QTest::newRow("mbap: an answer with no request")
        << std::vector{conversation(0, tcp, 502)}
        << std::vector{exchange(0, tcp, mbap(1, 1, "0600010003"), kStart, mbap(1, 1, "0600010003"), kStart + kMs, ok),
                       exchange(0, tcp, {}, 0, mbap(99, 1, "03020001"), kStart + 2 * kMs, TransactionStatus::Unexpected)}
        << false;
    QTest::newRow("mbap: answered by the wrong unit")
        << std::vector{conversation(0, tcp, 502)}
        << std::vector{exchange(0, tcp, mbap(5, 1, "0300000001"), kStart, mbap(5, 2, "03020001"), kStart + kMs, TransactionStatus::Unexpected)}
        << false;
    QTest::newRow("mbap: malformed answer (byte count)")
        << std::vector{conversation(0, tcp, 502)}
        << std::vector{exchange(0, tcp, mbap(5, 1, "0300000002"), kStart, mbap(5, 1, "0302000100"), kStart + kMs, TransactionStatus::Malformed)}
        << false;
    QTest::newRow("modbus udp")
        << std::vector{conversation(0, Framing::Udp, 502)}
        << std::vector{exchange(0, Framing::Udp, mbap(1, 1, "0400000001"), kStart, mbap(1, 1, "04020007"), kStart + 2 * kMs, ok),
                       exchange(0, Framing::Udp, mbap(2, 1, "0400000001"), kStart + 5 * kMs, {}, 0, TransactionStatus::Timeout),
                       // The capture goes on past the timeout (1 s): it shows the one before time out.
                       exchange(0, Framing::Udp, mbap(3, 1, "0400000001"), kStart + 1200 * kMs, mbap(3, 1, "04020007"), kStart + 1202 * kMs, ok)}
        << false;
    {
        // A request the recording ends before the timeout of: unanswered at its end, in the
        // exported capture as in the journal (the capture's last packet is that request).
        CaptureExchange cut = exchange(0, tcp, mbap(9, 1, "0300000001"), kStart + 10 * kMs, {}, 0, TransactionStatus::Timeout);
        cut.kind = CaptureExchange::Kind::Unanswered;
        QTest::newRow("mbap: the recording ends before the last request's timeout")
            << std::vector{conversation(0, tcp, 502)}
            << std::vector{exchange(0, tcp, mbap(8, 1, "0300000001"), kStart, mbap(8, 1, "03020001"), kStart + kMs, ok), cut}
            << false;
    }
    {
        // One function code and unit for ten reads, then others: the per-function and per-unit
        // tables, the overall figures while they are alike, are kept apart from the first that differs.
        std::vector<CaptureExchange> e;
        for (int i = 0; i < 10; ++i) {
            const qint64 t = kStart + i * 10 * kMs;
            e.push_back(exchange(0, tcp, mbap(quint16(i), 1, "0300000001"), t, mbap(quint16(i), 1, "03020001"), t + kMs + i * 7000, ok));
        }
        e.push_back(exchange(0, tcp, mbap(10, 2, "0300000001"), kStart + 200 * kMs, mbap(10, 2, "03020001"), kStart + 203 * kMs, ok));
        e.push_back(exchange(0, tcp, mbap(11, 2, "0600010003"), kStart + 300 * kMs, mbap(11, 2, "8602"), kStart + 302 * kMs,
                             TransactionStatus::Exception, 2));
        e.push_back(exchange(0, tcp, mbap(12, 1, "0300000001"), kStart + 400 * kMs, mbap(12, 1, "03020001"), kStart + 409 * kMs, ok));
        QTest::newRow("mbap: one function and unit, then others") << std::vector{conversation(0, tcp, 502)} << e << false;
    }
    QTest::newRow("mbap over ipv6, two conversations")
        << std::vector{conversation(0, tcp, 502, true), conversation(1, tcp, 1502)}
        << std::vector{exchange(0, tcp, mbap(1, 1, "0100000010"), kStart, mbap(1, 1, "0102ff00"), kStart + kMs, ok),
                       exchange(1, tcp, mbap(1, 9, "0500050000"), kStart + 100, mbap(1, 9, "0500050000"), kStart + kMs + 100, ok)}
        << false;
    {
        const Framing r = Framing::Rtu;
        QTest::newRow("rtu over tcp: read, broadcast, passed-over request, exception")
            << std::vector{conversation(0, r, 4001)}
            << std::vector{exchange(0, r, rtu(1, "0300790016"), kStart, rtu(1, "032c" + QByteArray(88, '0')), kStart + 40 * kMs, ok),
                           exchange(0, r, rtu(0, "0600010005"), kStart + 100 * kMs, {}, 0, TransactionStatus::Broadcast),
                           exchange(0, r, rtu(1, "0300000001"), kStart + 200 * kMs, {}, 0, TransactionStatus::Timeout),
                           exchange(0, r, rtu(2, "0300000001"), kStart + 300 * kMs, rtu(2, "03020001"), kStart + 320 * kMs, ok),
                           exchange(0, r, rtu(2, "0300000001"), kStart + 400 * kMs, rtu(2, "8302"), kStart + 420 * kMs,
                                    TransactionStatus::Exception, 2),
                           // A wrong CRC: the framer skips the bytes; as in the engine they still
                           // answer the waiting request, as a CRC error.
                           exchange(0, r, rtu(3, "0300000001"), kStart + 500 * kMs, rtu(3, "03020001").left(5) + "\x12\x34",
                                    kStart + 520 * kMs, TransactionStatus::CrcError)}
            << false;
    }
}

void TestCaptureRoundTrip::roundTrip()
{
    QFETCH(std::vector<CaptureConversation>, conversations);
    QFETCH(std::vector<CaptureExchange>, exchanges);
    QFETCH(bool, classicPcap);

    CaptureFileWriter writer;
    writer.openInMemory(classicPcap ? TrafficFormat::Pcap : TrafficFormat::Pcapng);
    ExchangePcapExporter exporter(writer);
    for (const CaptureConversation &c : conversations)
        exporter.addConversation(c);
    for (const CaptureExchange &e : exchanges)
        exporter.add(e);
    exporter.finish();
    QString error;
    QVERIFY(writer.close(&error));

    CaptureOptions options;
    options.mbapPorts = {502, 1502};
    options.rtuPorts = {4001};
    std::vector<CaptureExchange> read;
    CaptureAnalysis analysis;
    std::vector<CaptureConversation> seenConversations;
    const ExchangeSourceReport report = ExchangeSource::readCapture(
        writer.bytes(), options,
        [&](const CaptureExchange &e) {
            read.push_back(e);
            analysis.add(e);
        },
        [&](const CaptureConversation &c) { seenConversations.push_back(c); });
    QVERIFY2(report.isComplete(), qPrintable(report.error));
    QCOMPARE(report.frames.lostBytes, qint64(0));
    qint64 undelimited = 0; // RTU answers with a wrong CRC are skipped by the framer, and only those
    for (const CaptureExchange &e : exchanges)
        undelimited += e.transaction.status == TransactionStatus::CrcError ? e.transaction.response.size() : 0;
    QCOMPARE(report.frames.skippedBytes, undelimited);
    QCOMPARE(seenConversations.size(), conversations.size());
    for (std::size_t i = 0; i < conversations.size(); ++i) {
        QCOMPARE(seenConversations[i].clientText(), conversations[i].clientText());
        QCOMPARE(seenConversations[i].serverText(), conversations[i].serverText());
        QCOMPARE(seenConversations[i].framing, conversations[i].framing);
    }

    QStringList got;
    QStringList want;
    for (const CaptureExchange &e : read)
        got.append(describe(e));
    for (const CaptureExchange &e : exchanges)
        want.append(describe(e));
    QCOMPARE(read.size(), exchanges.size());
    for (std::size_t i = 0; i < exchanges.size(); ++i) {
        const Transaction &a = read[i].transaction;
        const Transaction &b = exchanges[i].transaction;
        const QByteArray where = QStringLiteral("exchange %1: got %2, want %3").arg(i).arg(got.at(qsizetype(i)), want.at(qsizetype(i))).toUtf8();
        QVERIFY2(read[i].kind == exchanges[i].kind, where.constData());
        QVERIFY2(a.request == b.request, where.constData());
        QVERIFY2(a.response == b.response, where.constData());
        QVERIFY2(a.status == b.status, where.constData());
        QVERIFY2(a.exceptionCode == b.exceptionCode, where.constData());
        QVERIFY2(a.doneNs == b.doneNs, where.constData());
        if (read[i].kind == CaptureExchange::Kind::Transaction)
            QVERIFY2(a.sentNs == b.sentNs, where.constData());
        QVERIFY2(read[i].conversation == exchanges[i].conversation, where.constData());
    }

    // The analysis counts as the engine's Statistics does over the same transactions.
    Statistics truth;
    for (const CaptureExchange &e : exchanges) {
        if (e.kind == CaptureExchange::Kind::Transaction)
            truth.add(e.transaction);
    }
    QCOMPARE(analysis.statistics().count(), truth.count());
    QCOMPARE(analysis.statistics().ok(), truth.ok());
    QCOMPARE(analysis.statistics().failed(), truth.failed());
    QCOMPARE(analysis.statistics().late(), truth.late());
    QCOMPARE(analysis.statistics().latency().count(), truth.latency().count());
    QCOMPARE(analysis.statistics().latency().maxNs(), truth.latency().maxNs());
    QCOMPARE(analysis.statistics().latency().medianNs(), truth.latency().medianNs());

    // Per function code and per unit id: the figures of the transactions with that code or unit.
    std::map<quint8, Statistics> byFunction;
    std::map<quint8, Statistics> byUnit;
    for (const CaptureExchange &e : exchanges) {
        const FrameKeys keys = ResponseMatcher::keysOf(e.transaction.request, e.framing);
        if (e.kind != CaptureExchange::Kind::Transaction || !keys.valid)
            continue;
        byFunction[quint8(keys.functionCode & 0x7f)].add(e.transaction);
        byUnit[keys.unit].add(e.transaction);
    }
    const QJsonObject json = analysis.toJson(report);
    const auto compareTable = [](const QJsonArray &table, const std::map<quint8, Statistics> &expected, const QString &key) {
        QCOMPARE(table.size(), qsizetype(expected.size()));
        qsizetype i = 0;
        for (const auto &[k, statistics] : expected) {
            QJsonObject row = table.at(i++).toObject();
            row.remove(QStringLiteral("function"));
            row.remove(QStringLiteral("name"));
            row.remove(QStringLiteral("unit"));
            QVERIFY2(row == statistics.toJson(), qPrintable(QStringLiteral("%1 %2: %3").arg(key).arg(int(k)).arg(
                                                     QString::fromUtf8(QJsonDocument(row).toJson(QJsonDocument::Compact)))));
        }
    };
    compareTable(json.value(QStringLiteral("functions")).toArray(), byFunction, QStringLiteral("function"));
    compareTable(json.value(QStringLiteral("units")).toArray(), byUnit, QStringLiteral("unit"));
}

// Every malformed request is counted, however often well-formed ones with nearly the same bytes
// came before it (the pairer dissects a request again only when its bytes differ from the last
// well-formed one's, the MBAP transaction id apart).
void TestCaptureRoundTrip::malformedRequests_data()
{
    QTest::addColumn<bool>("rtuFraming");
    QTest::addColumn<QList<QByteArray>>("pdus"); // hex, one request each, unit 1
    QTest::addColumn<int>("malformed");
    const QByteArray good = "0300000002";
    const QByteArray zero = "0300000000"; // quantity 0: outside 1-125
    const QByteArray over = "030000007e"; // 126 registers
    QTest::newRow("mbap: one request repeated") << false << QList<QByteArray>{good, good, good, good} << 0;
    QTest::newRow("mbap: good, bad of the same size, good") << false << QList<QByteArray>{good, zero, good} << 1;
    QTest::newRow("mbap: the same bad request twice") << false << QList<QByteArray>{zero, zero} << 2;
    QTest::newRow("mbap: good, two bad ones, good, bad") << false << QList<QByteArray>{good, zero, over, good, over} << 3;
    QTest::newRow("rtu: good, bad, good, bad") << true << QList<QByteArray>{good, zero, good, zero} << 2;
    QTest::newRow("rtu: one request repeated") << true << QList<QByteArray>{good, good, good} << 0;
}

void TestCaptureRoundTrip::malformedRequests()
{
    QFETCH(bool, rtuFraming);
    QFETCH(QList<QByteArray>, pdus);
    QFETCH(int, malformed);
    const Framing framing = rtuFraming ? Framing::Rtu : Framing::Tcp;
    CaptureFileWriter writer;
    writer.openInMemory(TrafficFormat::Pcapng);
    ExchangePcapExporter exporter(writer);
    exporter.addConversation(conversation(0, framing, rtuFraming ? 4001 : 502));
    for (qsizetype i = 0; i < pdus.size(); ++i) {
        const QByteArray request = rtuFraming ? rtu(1, pdus.at(i)) : mbap(quint16(i), 1, pdus.at(i).constData());
        exporter.add(exchange(0, framing, request, kStart + i * 2000 * kMs, {}, 0, TransactionStatus::Timeout));
    }
    exporter.finish();
    QString error;
    QVERIFY(writer.close(&error));
    CaptureOptions options;
    options.mbapPorts = {502};
    options.rtuPorts = {4001};
    const ExchangeSourceReport report = ExchangeSource::readCapture(writer.bytes(), options, [](const CaptureExchange &) {});
    QCOMPARE(report.pairs.requests, quint64(pdus.size()));
    QCOMPARE(report.pairs.malformedRequests, quint64(malformed));
}

QTEST_GUILESS_MAIN(TestCaptureRoundTrip)
#include "tst_captureroundtrip.moc"
