// The transaction engine against a scripted peer in the same process: verdicts per framing,
// answers in pieces, timeouts and late answers, retries, unexpected answers, garbage before an
// answer, a peer that answers twice. Link events, pipelining and broadcasts: tst_engineflow.

#include "enginetesting.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::test;

Q_DECLARE_METATYPE(mbscope::TransactionStatus)

namespace {

PeerScript answerWith(const QByteArray &reply, int delayMs = 1)
{
    return [reply, delayMs](const QByteArray &, int) { return QList<Reply>{Reply{delayMs, reply, false}}; };
}

void checkTimes(const Transaction &t)
{
    QVERIFY2(t.sentNs > 0, "sentNs set");
    QVERIFY2(t.sentNs <= t.firstByteNs, "the answer began after the request was written");
    QVERIFY2(t.firstByteNs <= t.doneNs, "the answer's first byte came before its last");
    QVERIFY(t.latencyNs() > 0);
}

} // namespace

class tst_TransactionEngine : public QObject
{
    Q_OBJECT

private slots:
    void verdict_data();
    void verdict();
    void answerInPieces();
    void timeoutThenLate_data();
    void timeoutThenLate();
    void lateWhileNextIsPending();
    void retries();
    void retriesExhausted();
    void unexpected_data();
    void unexpected();
    void garbageBeforeAnswer_data();
    void garbageBeforeAnswer();
    void answersTwice_data();
    void answersTwice();
};

void tst_TransactionEngine::verdict_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("reply");
    QTest::addColumn<TransactionStatus>("status");
    QTest::addColumn<int>("exceptionCode");

    using S = TransactionStatus;
    auto row = [](const char *url, const QByteArray &request, const QByteArray &reply, S status, int code = 0) {
        QTest::newRow(qPrintable(QStringLiteral("%1 %2 -> %3")
                                     .arg(QLatin1String(url), QString::fromLatin1(request.toHex(' ')),
                                          QString::fromLatin1(reply.toHex(' ')))))
            << QString::fromLatin1(url) << request << reply << status << code;
    };
    const QByteArray tcpRead = mbap("0300000002", 1, 1);
    row("tcp://peer:502", tcpRead, mbap("0304000a000b", 1, 1), S::Ok);
    row("tcp://peer:502", tcpRead, mbap("8302", 1, 1), S::Exception, 2);
    row("tcp://peer:502", tcpRead, mbap("0304000a", 1, 1), S::Malformed);
    row("tls://peer:802", tcpRead, mbap("0304000a000b", 1, 1), S::Ok);
    row("udp://peer:502", tcpRead, mbap("0304000a000b", 1, 1), S::Ok);
    row("udp://peer:502", tcpRead, mbap("8303", 1, 1), S::Exception, 3);

    const QByteArray rtuRead = rtu("0300000002", 1);
    QByteArray badCrc = rtu("0304000a000b", 1);
    badCrc[badCrc.size() - 1] = char(badCrc.at(badCrc.size() - 1) ^ 0x5A);
    row("rtu-tcp://peer:4001", rtuRead, rtu("0304000a000b", 1), S::Ok);
    row("rtu-tcp://peer:4001", rtuRead, rtu("8302", 1), S::Exception, 2);
    row("rtu-tcp://peer:4001", rtuRead, badCrc, S::CrcError);
    // Cut short: the framer ends it at the silence, the dissector says what is missing.
    row("rtu-tcp://peer:4001", rtuRead, rtu("0304000a", 1), S::Malformed);
    row("rtu-udp://peer:4001", rtuRead, rtu("0304000a000b", 1), S::Ok);
    row("rtu-udp://peer:4001", rtuRead, badCrc, S::CrcError);
    // A serial line: t3.5 at 9600 baud ends the damaged frame.
    row("rtu:///dev/ttyTEST?baud=9600", rtuRead, rtu("0304000a000b", 1), S::Ok);
    row("rtu:///dev/ttyTEST?baud=9600", rtuRead, badCrc, S::CrcError);

    const QByteArray asciiRead = ascii("0300000001", 0x11);
    QByteArray badLrc = ascii("03020123", 0x11);
    badLrc[badLrc.size() - 3] = badLrc.at(badLrc.size() - 3) == '0' ? '1' : '0';
    row("ascii-tcp://peer:4002", asciiRead, ascii("03020123", 0x11), S::Ok);
    row("ascii-tcp://peer:4002", asciiRead, ascii("8301", 0x11), S::Exception, 1);
    row("ascii-tcp://peer:4002", asciiRead, badLrc, S::CrcError);
    row("ascii:///dev/ttyTEST?baud=19200&data=7", asciiRead, ascii("03020123", 0x11), S::Ok);

    row("tcp://peer:4003?framing=delimited&start=24&end=23", QByteArray("$01R#"), QByteArray("$01 293 295 #"), S::Ok);
    row("tcp://peer:4003?framing=delimited&start=05&end=04&checksum=xor", QByteArray("\x05" "00RSS\x04\x01"),
        QByteArray("\x05" "00ACK\x04") + char(0x05 ^ '0' ^ '0' ^ 'A' ^ 'C' ^ 'K' ^ 0x04), S::Ok);
    row("tcp://peer:4003?framing=delimited&start=05&end=04&checksum=xor", QByteArray("\x05" "00RSS\x04\x01"),
        QByteArray("\x05" "00ACK\x04\x00", 8), S::CrcError);
}

void tst_TransactionEngine::verdict()
{
    QFETCH(QString, url);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, reply);
    QFETCH(TransactionStatus, status);
    QFETCH(int, exceptionCode);

    EngineOptions options;
    options.streamSilenceMs = 20;
    EngineHarness h(url, answerWith(reply), options);
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(request));
    QVERIFY(t.has_value());
    QVERIFY2(t->status == status, qPrintable(transactionStatusName(t->status) + QStringLiteral(": ") + t->problem));
    QCOMPARE(int(t->exceptionCode), exceptionCode);
    QCOMPARE(t->request, request);
    QCOMPARE(t->response, reply);
    QCOMPARE(t->attempt, 0);
    QCOMPARE(t->item, -1);
    QVERIFY(!t->transactionIdRewritten);
    QCOMPARE(t->problem.isEmpty(), status == TransactionStatus::Ok);
    checkTimes(*t);
    QCOMPARE(h.peer->writes.load(), 1);
}

void tst_TransactionEngine::answerInPieces()
{
    // The answer trickles in three reads; the first and the last byte keep their own times.
    const QByteArray answer = rtu("0304000a000b", 1);
    EngineHarness h(QStringLiteral("rtu-tcp://peer:4001"), [answer](const QByteArray &, int) {
        return QList<Reply>{{2, answer.left(2), false}, {6, answer.mid(2, 3), false}, {10, answer.mid(5), false}};
    });
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(rtu("0300000002", 1)));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::Ok);
    QCOMPARE(t->response, answer);
    checkTimes(*t);
    QVERIFY(t->firstByteNs < t->doneNs);
}

void tst_TransactionEngine::timeoutThenLate_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("answer");
    QTest::newRow("tcp 00 01 00 00 00 06 01 03 00 00 00 02") << QStringLiteral("tcp://peer:502") << mbap("0300000002", 1, 1)
                                                              << mbap("0304000a000b", 1, 1);
    QTest::newRow("rtu-tcp 01 03 00 00 00 02 c4 0b") << QStringLiteral("rtu-tcp://peer:4001") << rtu("0300000002", 1)
                                                      << rtu("0304000a000b", 1);
}

void tst_TransactionEngine::timeoutThenLate()
{
    QFETCH(QString, url);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, answer);
    // The first answer comes long after its 100 ms timeout, the second at once.
    EngineHarness h(url, [answer](const QByteArray &, int index) {
        return QList<Reply>{Reply{index == 0 ? 600 : 1, answer, false}};
    });
    const quint64 id = h.engine.send(h.item(request, 100));
    QVERIFY(h.waitForRecords(2));
    QCOMPARE(h.records.at(0).id, id);
    QCOMPARE(h.records.at(0).status, TransactionStatus::Timeout);
    QVERIFY(h.records.at(0).response.isEmpty());
    QCOMPARE(h.records.at(0).latencyNs(), qint64(-1));
    QVERIFY(h.records.at(0).problem.contains(QLatin1String("100 ms")));
    // The late answer is a record of its own about the same request, not matched to another.
    const Transaction &late = h.records.at(1);
    QCOMPARE(late.id, id);
    QCOMPARE(late.status, TransactionStatus::Late);
    QCOMPARE(late.response, answer);
    QCOMPARE(late.request, request);
    QVERIFY(late.problem.contains(QLatin1String("after its 100 ms timeout")));
    checkTimes(late);
    QVERIFY(h.waitFor([&] { return h.progress.counters.late == 1; }));

    const std::optional<Transaction> next = h.engine.sendAndWait(h.item(request, 2000));
    QVERIFY(next.has_value());
    QCOMPARE(next->status, TransactionStatus::Ok);
    QCOMPARE(h.records.size(), 3);
}

void tst_TransactionEngine::lateWhileNextIsPending()
{
    // Transaction ids tell a late answer from the answer to the request now pending.
    const QByteArray first = mbap("0300000002", 1, 1);
    const QByteArray second = mbap("0300000002", 2, 1);
    EngineHarness h(QStringLiteral("tcp://peer:502"), [](const QByteArray &request, int index) {
        return QList<Reply>{Reply{index == 0 ? 400 : 800, mbapAnswer(request, "0304000a000b"), false}};
    });
    const quint64 a = h.engine.send(h.item(first, 100));
    QVERIFY(h.waitForRecords(1));
    QCOMPARE(h.records.at(0).status, TransactionStatus::Timeout);
    const quint64 b = h.engine.send(h.item(second, 5000));
    QVERIFY(h.waitForRecords(3));
    QCOMPARE(h.records.at(1).id, a);
    QCOMPARE(h.records.at(1).status, TransactionStatus::Late);
    QCOMPARE(h.records.at(2).id, b);
    QCOMPARE(h.records.at(2).status, TransactionStatus::Ok);
    QCOMPARE(h.records.at(2).response, mbapAnswer(second, "0304000a000b"));
}

void tst_TransactionEngine::retries()
{
    // The peer ignores the first two attempts.
    EngineHarness h(QStringLiteral("tcp://peer:502"), [](const QByteArray &request, int index) {
        return index < 2 ? QList<Reply>{} : QList<Reply>{Reply{1, mbapAnswer(request, "0304000a000b"), false}};
    });
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(mbap("0300000002"), 100, 2));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::Ok);
    QCOMPARE(t->attempt, 2);
    QCOMPARE(h.peer->writes.load(), 3);
    QVERIFY2(t->problem.contains(QLatin1String("attempt 1: timeout")), qPrintable(t->problem));
    QVERIFY2(t->problem.contains(QLatin1String("attempt 2: timeout")), qPrintable(t->problem));
    QVERIFY(h.waitFor([&] { return h.progress.counters.retries == 2 && h.progress.counters.requestsSent == 3; }));
    QCOMPARE(h.records.size(), 1);
}

void tst_TransactionEngine::retriesExhausted()
{
    EngineHarness h(QStringLiteral("rtu-tcp://peer:4001"), [](const QByteArray &, int) { return QList<Reply>{}; });
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(rtu("0300000002"), 80, 1));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::Timeout);
    QCOMPARE(t->attempt, 1);
    QCOMPARE(h.peer->writes.load(), 2);
    QCOMPARE(h.records.size(), 1);
}

void tst_TransactionEngine::unexpected_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("reply");
    QTest::addColumn<QByteArray>("goodReply");
    QTest::addColumn<QString>("problem");
    const QByteArray tcpRead = mbap("0300000002", 7, 1);
    const QByteArray tcpGood = mbap("0304000a000b", 7, 1);
    QTest::newRow("wrong transaction id 00 08 00 00 00 07 01 03 04 00 0a 00 0b")
        << QStringLiteral("tcp://peer:502") << tcpRead << mbap("0304000a000b", 8, 1) << tcpGood << QStringLiteral("transaction id 8");
    QTest::newRow("wrong unit 00 07 00 00 00 07 02 03 04 00 0a 00 0b")
        << QStringLiteral("tcp://peer:502") << tcpRead << mbap("0304000a000b", 7, 2) << tcpGood << QStringLiteral("unit 2");
    QTest::newRow("wrong function 00 07 00 00 00 07 01 04 04 00 0a 00 0b")
        << QStringLiteral("tcp://peer:502") << tcpRead << mbap("0404000a000b", 7, 1) << tcpGood << QStringLiteral("function code 0x04");
    QTest::newRow("rtu wrong unit 02 03 04 00 0a 00 0b")
        << QStringLiteral("rtu-tcp://peer:4001") << rtu("0300000002", 1) << rtu("0304000a000b", 2) << rtu("0304000a000b", 1)
        << QStringLiteral("unit 2");
}

void tst_TransactionEngine::unexpected()
{
    QFETCH(QString, url);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, reply);
    QFETCH(QByteArray, goodReply);
    QFETCH(QString, problem);
    EngineHarness h(url, [reply, goodReply](const QByteArray &, int index) {
        return QList<Reply>{Reply{1, index == 0 ? reply : goodReply, false}};
    });
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(request));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::Unexpected);
    QCOMPARE(t->response, reply);
    QVERIFY2(t->problem.contains(problem), qPrintable(t->problem));
    const std::optional<Transaction> next = h.engine.sendAndWait(h.item(request));
    QVERIFY(next.has_value());
    QCOMPARE(next->status, TransactionStatus::Ok);
}

void tst_TransactionEngine::garbageBeforeAnswer_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("garbage");
    QTest::addColumn<QByteArray>("answer");
    QTest::addColumn<bool>("sameRead");
    const QByteArray tcpRead = mbap("0300000002", 1, 1);
    const QByteArray rtuRead = rtu("0300000002", 1);
    QTest::newRow("tcp ff ff ff, same read") << QStringLiteral("tcp://peer:502") << tcpRead << hex("ffffff")
                                             << mbap("0304000a000b", 1, 1) << true;
    QTest::newRow("tcp ff ff ff, own read") << QStringLiteral("tcp://peer:502") << tcpRead << hex("ffffff")
                                            << mbap("0304000a000b", 1, 1) << false;
    QTest::newRow("rtu-tcp ff ff ff, same read") << QStringLiteral("rtu-tcp://peer:4001") << rtuRead << hex("ffffff")
                                                 << rtu("0304000a000b", 1) << true;
    QTest::newRow("ascii-tcp 'xyz', same read") << QStringLiteral("ascii-tcp://peer:4002") << ascii("0300000001", 1)
                                                << QByteArray("xyz") << ascii("03020123", 1) << true;
}

void tst_TransactionEngine::garbageBeforeAnswer()
{
    QFETCH(QString, url);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, garbage);
    QFETCH(QByteArray, answer);
    QFETCH(bool, sameRead);
    EngineHarness h(url, [=](const QByteArray &, int) {
        if (sameRead)
            return QList<Reply>{Reply{1, garbage + answer, false}};
        return QList<Reply>{Reply{1, garbage, false}, Reply{5, answer, false}};
    });
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(request));
    QVERIFY(t.has_value());
    QVERIFY2(t->status == TransactionStatus::Ok, qPrintable(t->problem));
    QCOMPARE(t->response, answer);
    checkTimes(*t);
    // Never silently dropped: counted (and logged, see trafficLog()).
    QVERIFY(h.waitFor([&] { return h.progress.counters.skippedBytes == quint64(garbage.size()); }));
    QCOMPARE(h.progress.counters.skippedRuns, quint64(1));
}

void tst_TransactionEngine::answersTwice_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("answer");
    QTest::newRow("tcp 00 01 00 00 00 07 01 03 04 00 0a 00 0b") << QStringLiteral("tcp://peer:502") << mbap("0300000002", 1, 1)
                                                                << mbap("0304000a000b", 1, 1);
    QTest::newRow("rtu-tcp 01 03 04 00 0a 00 0b") << QStringLiteral("rtu-tcp://peer:4001") << rtu("0300000002", 1)
                                                   << rtu("0304000a000b", 1);
}

void tst_TransactionEngine::answersTwice()
{
    QFETCH(QString, url);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, answer);
    EngineHarness h(url, [answer](const QByteArray &, int index) {
        if (index == 0)
            return QList<Reply>{Reply{1, answer, false}, Reply{30, answer, false}};
        return QList<Reply>{Reply{1, answer, false}};
    });
    const std::optional<Transaction> t = h.engine.sendAndWait(h.item(request));
    QVERIFY(t.has_value());
    QCOMPARE(t->status, TransactionStatus::Ok);
    QVERIFY(h.waitFor([&] { return h.progress.counters.duplicateFrames == 1; }));
    QCOMPARE(h.progress.counters.unsolicitedFrames, quint64(1));
    QCOMPARE(h.records.size(), 1);
    const std::optional<Transaction> next = h.engine.sendAndWait(h.item(request));
    QVERIFY(next.has_value());
    QCOMPARE(next->status, TransactionStatus::Ok);
}

QTEST_GUILESS_MAIN(tst_TransactionEngine)
#include "tst_transactionengine.moc"
