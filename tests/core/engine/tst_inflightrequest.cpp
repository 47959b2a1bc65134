// InFlightRequest's judgement of a serial answer's timing (issue 19, item 3): an answer cannot
// begin before its request left the line, nor end sooner after it than its own characters take.
// The cases are in characters of 9600 baud 8E1 (11 bits, 1.146 ms): an 8-byte request, a 7-byte
// answer (8.02 ms on the line).
#include "engine/inflightrequest.h"

#include <QtTest/QtTest>

using namespace mbscope;

namespace {

constexpr qint64 kCharacterNs = 11 * 1'000'000'000LL / 9600;
constexpr qint64 kWriteNs = 1'000'000'000;
constexpr qint64 kLineEndNs = kWriteNs + 8 * kCharacterNs;
constexpr qsizetype kAnswerBytes = 7;

InFlightRequest serialRequest()
{
    InFlightRequest p;
    p.sent = QByteArray(8, '\0');
    p.writeStartNs = kWriteNs;
    p.predictedSentNs = kLineEndNs;
    p.characterNs = kCharacterNs;
    return p;
}

} // namespace

class TestInFlightRequest : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void outranLine_data();
    void outranLine();
    void neverWrittenHasNoLatency();
};

void TestInFlightRequest::outranLine_data()
{
    QTest::addColumn<qint64>("firstNs");
    QTest::addColumn<qint64>("lastNs");
    QTest::addColumn<bool>("outran");
    const qint64 answerNs = kAnswerBytes * kCharacterNs;
    QTest::newRow("first byte before the request left") << kLineEndNs - kCharacterNs << kLineEndNs + answerNs << true;
    QTest::newRow("at once after the line end, whole") << kLineEndNs << kLineEndNs + answerNs << false;
    QTest::newRow("3.5 characters of silence, then whole")
        << kLineEndNs + 4 * kCharacterNs << kLineEndNs + 4 * kCharacterNs + answerNs << false;
    // The try-out's pty case: 6.893 ms after the computed line end, with 8.02 ms of answer to
    // carry. Within one character of it, so it passed as a line-end latency of 6.9 ms.
    QTest::newRow("whole 6.893 ms after the line end") << kLineEndNs + 6'000'000 << kLineEndNs + 6'893'000 << true;
    QTest::newRow("one character short of the answer") << kLineEndNs << kLineEndNs + answerNs - kCharacterNs << true;
    // A UART's clock may run a little fast: 2 % short of the answer's time is still a real line.
    QTest::newRow("2 % short of the answer") << kLineEndNs << kLineEndNs + answerNs * 98 / 100 << false;
}

void TestInFlightRequest::outranLine()
{
    QFETCH(qint64, firstNs);
    QFETCH(qint64, lastNs);
    QFETCH(bool, outran);
    const InFlightRequest p = serialRequest();
    QCOMPARE(p.outranLine(firstNs, lastNs, kAnswerBytes), outran);
    const Transaction t = p.toTransaction(TransactionStatus::Ok, {}, QByteArray(kAnswerBytes, '\0'), firstNs, lastNs);
    QCOMPARE(t.outranLine, outran);
    QCOMPARE(t.sentNs, outran ? kWriteNs : kLineEndNs);
    QCOMPARE(t.measuredFromLineEnd(), !outran);
    // Never shorter than the line allows, from wherever it is measured.
    QVERIFY(t.latencyNs() >= kAnswerBytes * kCharacterNs * 98 / 100 || outran);
}

// A request that failed before it was written (the link was refused) has the moment it failed
// as its time in the traffic list, and no latency: the try-out's `send` to a closed port said
// "answered in 43648.517 s", the host's uptime.
void TestInFlightRequest::neverWrittenHasNoLatency()
{
    OutgoingRequest out;
    out.item.bytes = QByteArray::fromHex("010300790016" "15DD");
    const Transaction t = InFlightRequest::unsent(out).toTransaction(TransactionStatus::LinkError, QStringLiteral("refused"), {}, 0,
                                                                     kWriteNs);
    QCOMPARE(t.sentNs, qint64(0));
    QCOMPARE(t.doneNs, kWriteNs);
    QCOMPARE(t.latencyNs(), qint64(-1));
}

QTEST_GUILESS_MAIN(TestInFlightRequest)
#include "tst_inflightrequest.moc"
