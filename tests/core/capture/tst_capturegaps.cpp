// Captures with holes: packets the capture lost (a request, an answer, half of a frame), a
// capture that began mid-stream, for Modbus TCP and RTU over TCP. The packets are built here with
// the sequence and acknowledgement numbers a real connection has, then some are left out of the
// file. Framing must resume at the next frame, and only the exchanges whose packets were lost may
// count as timeouts or unmatched answers; the gaps and the bytes lost are counted.
#include "capture/captureanalysis.h"
#include "capture/capturefilewriter.h"
#include "capture/exchangesource.h"
#include "capture/packetsynthesizer.h"
#include "protocol/adubuilder.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtTest/QTest>

using namespace mbscope;

namespace {

constexpr qint64 kStart = 1'700'000'000'000'000'000LL;
constexpr qint64 kMs = 1'000'000;
constexpr int kTransactions = 20;

struct Segment {
    bool toServer = true;
    QByteArray payload;
    qint64 timeNs = 0;
};

// Which segment of transaction i (0-based): the request, or a part of the answer.
int requestSegment(int i, int answerParts)
{
    return i * (1 + answerParts);
}

int answerSegment(int i, int answerParts, int part = 0)
{
    return i * (1 + answerParts) + 1 + part;
}

// kTransactions reads, one every 100 ms, each answered 5 ms later; an answer split at splitAt
// (0: not split) goes as two segments 10 us apart.
std::vector<Segment> transactions(Framing framing, const QByteArray &answerPdu, int splitAt)
{
    std::vector<Segment> segments;
    for (int i = 0; i < kTransactions; ++i) {
        const qint64 t = kStart + i * 100 * kMs;
        // As many registers as the answer carries.
        const QByteArray read = QByteArray::fromHex("03000000") + char(quint8(answerPdu.at(1)) / 2);
        const QByteArray request = framing == Framing::Rtu ? AduBuilder::rtu(read, 1) : AduBuilder::mbap(read, 1, quint16(i));
        const QByteArray answer = framing == Framing::Rtu ? AduBuilder::rtu(answerPdu, 1) : AduBuilder::mbap(answerPdu, 1, quint16(i));
        segments.push_back({true, request, t});
        if (splitAt > 0) {
            segments.push_back({false, answer.left(splitAt), t + 5 * kMs});
            segments.push_back({false, answer.mid(splitAt), t + 5 * kMs + 10'000});
        } else {
            segments.push_back({false, answer, t + 5 * kMs});
        }
    }
    return segments;
}

// The segments as one TCP connection in a pcapng, without the dropped ones (their sequence
// numbers are used all the same) and, when handshake is false, without SYNs.
QByteArray capture(const std::vector<Segment> &segments, const QList<int> &dropped, bool handshake, quint16 serverPort)
{
    using P = PacketSynthesizer;
    P::Endpoints endpoints;
    endpoints.client.bytes = {192, 168, 1, 5};
    endpoints.server.bytes = {192, 168, 1, 10};
    endpoints.clientPort = 40000;
    endpoints.serverPort = serverPort;
    CaptureFileWriter writer;
    writer.openInMemory(TrafficFormat::Pcapng);
    quint32 clientNext = 1000;
    quint32 serverNext = 5000;
    if (handshake) {
        const qint64 t = segments.front().timeNs - kMs;
        writer.write(t, P::tcp(endpoints, true, clientNext - 1, 0, P::kSyn, {}));
        writer.write(t, P::tcp(endpoints, false, serverNext - 1, clientNext, P::kSyn | P::kAck, {}));
        writer.write(t, P::tcp(endpoints, true, clientNext, serverNext, P::kAck, {}));
    }
    for (int i = 0; i < int(segments.size()); ++i) {
        const Segment &s = segments[std::size_t(i)];
        quint32 &sequence = s.toServer ? clientNext : serverNext;
        const quint32 acknowledgement = s.toServer ? serverNext : clientNext;
        if (!dropped.contains(i))
            writer.write(s.timeNs, P::tcp(endpoints, s.toServer, sequence, acknowledgement, P::kPsh | P::kAck, s.payload));
        sequence += quint32(s.payload.size());
    }
    QString error;
    if (!writer.close(&error))
        qWarning("%s", qPrintable(error));
    return writer.bytes();
}

QList<int> range(int from, int to)
{
    QList<int> list;
    for (int i = from; i < to; ++i)
        list.append(i);
    return list;
}

} // namespace

class TestCaptureGaps : public QObject
{
    Q_OBJECT

private slots:
    void gaps_data();
    void gaps();
};

void TestCaptureGaps::gaps_data()
{
    QTest::addColumn<bool>("rtuOverTcp");
    QTest::addColumn<QByteArray>("answerPdu");
    QTest::addColumn<int>("splitAt");
    QTest::addColumn<QList<int>>("dropped");
    QTest::addColumn<bool>("handshake");
    QTest::addColumn<int>("ok");
    QTest::addColumn<int>("timeouts");
    QTest::addColumn<int>("unmatched");
    QTest::addColumn<int>("gaps");
    QTest::addColumn<qint64>("lostBytes");
    QTest::addColumn<qint64>("cutByGapBytes");
    QTest::addColumn<int>("joinedMidStream");
    QTest::addColumn<QList<int>>("requestGaps"); // per direction: to the server, to the client

    const bool tcp = false;
    const bool rtu = true;
    const QByteArray read = QByteArray::fromHex("030400010002");
    // Sixteen register bytes that hold something like an MBAP header (protocol 0, length 6,
    // unit 1, function 03), followed by bytes no header can start with.
    const QByteArray lookalike = QByteArray::fromHex("0310" "000000000006" "0103" "ffffffffffffffff");

    // MBAP request: 12 bytes, answer: 13.
    QTest::newRow("mbap: lost request packet")
        << tcp << read << 0 << QList<int>{requestSegment(7, 1)} << true << 19 << 0 << 1 << 1 << 12LL << 0LL << 0 << QList<int>{1, 0};
    QTest::newRow("mbap: lost answer packet")
        << tcp << read << 0 << QList<int>{answerSegment(7, 1)} << true << 19 << 1 << 0 << 1 << 13LL << 0LL << 0 << QList<int>{0, 1};
    QTest::newRow("mbap: lost request and answer, three apart")
        << tcp << read << 0 << QList<int>{requestSegment(3, 1), answerSegment(6, 1)} << true << 18 << 1 << 1 << 2 << 25LL << 0LL << 0
        << QList<int>{1, 1};
    QTest::newRow("mbap: capture started mid-stream (at an answer)")
        << tcp << read << 0 << range(0, answerSegment(4, 1)) << false << 15 << 0 << 1 << 0 << 0LL << 0LL << 2 << QList<int>{0, 0};
    QTest::newRow("mbap: gap in the middle of an answer (its head lost)")
        << tcp << read << 4 << QList<int>{answerSegment(7, 2, 0)} << true << 19 << 1 << 0 << 1 << 4LL << 9LL << 0 << QList<int>{0, 1};
    QTest::newRow("mbap: gap in the middle of an answer (its tail lost)")
        << tcp << read << 4 << QList<int>{answerSegment(7, 2, 1)} << true << 19 << 1 << 0 << 1 << 9LL << 4LL << 0 << QList<int>{0, 1};
    QTest::newRow("mbap: gap before register values that look like a header")
        << tcp << lookalike << 9 << QList<int>{answerSegment(7, 2, 0)} << true << 19 << 1 << 0 << 1 << 9LL << 16LL << 0
        << QList<int>{0, 1};
    QTest::newRow("mbap: capture started in the middle of an answer")
        << tcp << lookalike << 9 << range(0, answerSegment(4, 2, 1)) << false << 15 << 0 << 0 << 0 << 0LL << 16LL << 2
        << QList<int>{0, 0};

    // RTU request: 8 bytes, answer: 9.
    QTest::newRow("rtu over tcp: lost request packet")
        << rtu << read << 0 << QList<int>{requestSegment(7, 1)} << true << 19 << 0 << 1 << 1 << 8LL << 0LL << 0 << QList<int>{1, 0};
    QTest::newRow("rtu over tcp: lost answer packet")
        << rtu << read << 0 << QList<int>{answerSegment(7, 1)} << true << 19 << 1 << 0 << 1 << 9LL << 0LL << 0 << QList<int>{0, 1};
    QTest::newRow("rtu over tcp: gap in the middle of an answer (its head lost)")
        << rtu << read << 3 << QList<int>{answerSegment(7, 2, 0)} << true << 19 << 1 << 0 << 1 << 3LL << 6LL << 0 << QList<int>{0, 1};
    QTest::newRow("rtu over tcp: capture started mid-stream (at a request)")
        << rtu << read << 0 << range(0, requestSegment(5, 1)) << false << 15 << 0 << 0 << 0 << 0LL << 0LL << 2 << QList<int>{0, 0};
}

void TestCaptureGaps::gaps()
{
    QFETCH(bool, rtuOverTcp);
    const Framing framing = rtuOverTcp ? Framing::Rtu : Framing::Tcp;
    QFETCH(QByteArray, answerPdu);
    QFETCH(int, splitAt);
    QFETCH(QList<int>, dropped);
    QFETCH(bool, handshake);

    const QByteArray file = capture(transactions(framing, answerPdu, splitAt), dropped, handshake, framing == Framing::Rtu ? 4001 : 502);
    CaptureOptions options;
    options.rtuPorts = {4001};
    CaptureAnalysis analysis;
    QStringList failures;
    const ExchangeSourceReport report = ExchangeSource::readCapture(file, options, [&](const CaptureExchange &e) {
        analysis.add(e);
        const Transaction &t = e.transaction;
        if (t.status != TransactionStatus::Ok)
            failures.append(QStringLiteral("%1 %2 -> %3: %4")
                                .arg(transactionStatusName(t.status), QString::fromLatin1(t.request.toHex(' ')),
                                     QString::fromLatin1(t.response.toHex(' ')), t.problem));
        else if (t.doneNs - t.sentNs != 5 * kMs && t.doneNs - t.sentNs != 5 * kMs + 10'000)
            failures.append(QStringLiteral("ok but %1 ns: paired with another transaction's answer").arg(t.doneNs - t.sentNs));
    });
    QVERIFY2(report.isComplete(), qPrintable(report.error));
    const QString context = failures.join(QLatin1Char('\n')) + QLatin1Char('\n') + report.problems.join(QLatin1Char('\n'));

    QFETCH(int, ok);
    QFETCH(int, timeouts);
    QFETCH(int, unmatched);
    QFETCH(int, gaps);
    QFETCH(qint64, lostBytes);
    QFETCH(qint64, cutByGapBytes);
    QFETCH(int, joinedMidStream);
    QFETCH(QList<int>, requestGaps);
    QVERIFY2(analysis.statistics().ok() == quint64(ok), qPrintable(QStringLiteral("ok %1\n").arg(analysis.statistics().ok()) + context));
    QVERIFY2(analysis.statistics().timeouts() == quint64(timeouts),
             qPrintable(QStringLiteral("timeouts %1\n").arg(analysis.statistics().timeouts()) + context));
    QVERIFY2(analysis.statistics().failed() == quint64(timeouts), qPrintable(context));
    QVERIFY2(analysis.unmatchedResponses() == quint64(unmatched),
             qPrintable(QStringLiteral("unmatched %1\n").arg(analysis.unmatchedResponses()) + context));
    QCOMPARE(report.frames.gaps, quint64(gaps));
    QCOMPARE(report.frames.lostBytes, lostBytes);
    QCOMPARE(report.frames.cutByGapBytes, cutByGapBytes);
    QCOMPARE(report.frames.joinedMidStream, quint64(joinedMidStream));
    QCOMPARE(report.conversations.size(), std::size_t(1));
    const CaptureConversation &c = report.conversations.front();
    QCOMPARE(c.requestGaps, quint64(requestGaps.at(0)));
    QCOMPARE(c.responseGaps, quint64(requestGaps.at(1)));
    QCOMPARE(c.requestBytesLost + c.responseBytesLost, lostBytes);
    QCOMPARE(c.joinedMidStream, joinedMidStream > 0);

    // The report says where the bytes went.
    const QJsonObject json = analysis.toJson(report);
    const QJsonObject source = json.value(QStringLiteral("source")).toObject();
    QCOMPARE(source.value(QStringLiteral("gaps")).toInteger(), qint64(gaps));
    QCOMPARE(source.value(QStringLiteral("lost_bytes")).toInteger(), lostBytes);
    const QJsonObject conversation = json.value(QStringLiteral("conversations")).toArray().at(0).toObject();
    QCOMPARE(conversation.value(QStringLiteral("request_gaps")).toInteger(), qint64(requestGaps.at(0)));
    QCOMPARE(conversation.value(QStringLiteral("response_gaps")).toInteger(), qint64(requestGaps.at(1)));
    if (gaps > 0)
        QVERIFY2(analysis.summary(report).contains(QStringLiteral("byte(s) never captured")), qPrintable(analysis.summary(report)));
}

QTEST_GUILESS_MAIN(TestCaptureGaps)
#include "tst_capturegaps.moc"
