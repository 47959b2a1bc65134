// Which framed answer matches which request: MBAP by transaction id, unit and function code;
// RTU and ASCII by unit and function code; delimited framing and keyless requests by order.

#include "../engine/enginetesting.h"

#include "exchange/requestitem.h"
#include "exchange/responsematcher.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::test;

Q_DECLARE_METATYPE(mbscope::ResponseMatcher::Outcome)

namespace {

RequestItem itemFor(const QString &framing, const QByteArray &request)
{
    if (framing == QLatin1String("delimited"))
        return RequestItem::fromBytes(request, Framing::Tcp, true);
    return RequestItem::fromBytes(request, *framingFromName(framing));
}

QString rowName(const char *what, const QByteArray &request, const QByteArray &response)
{
    return QStringLiteral("%1: %2 -> %3").arg(QLatin1String(what), QString::fromLatin1(request.toHex(' ')),
                                             QString::fromLatin1(response.toHex(' ')));
}

} // namespace

class tst_Matcher : public QObject
{
    Q_OBJECT

private slots:
    void keys_data();
    void keys();
    void match_data();
    void match();
    void exceptionAnswersOnlyItsFunction();
    void itemForLink();
};

void tst_Matcher::keys_data()
{
    QTest::addColumn<QString>("framing");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<int>("rule");
    QTest::addColumn<int>("unit");
    QTest::addColumn<int>("function");
    QTest::addColumn<int>("transactionId");
    QTest::addColumn<bool>("broadcast");

    auto row = [](const char *framing, const QByteArray &request, MatchRule rule, int unit, int function, int tid, bool broadcast) {
        QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(QLatin1String(framing), QString::fromLatin1(request.toHex(' ')))))
            << QString::fromLatin1(framing) << request << int(rule) << unit << function << tid << broadcast;
    };
    row("tcp", mbap("030000000a", 0x1234, 17), MatchRule::Mbap, 17, 3, 0x1234, false);
    row("udp", mbap("0400000001", 7, 1), MatchRule::Mbap, 1, 4, 7, false);
    // Unit 0 over MBAP addresses the server itself, not every server (Messaging on TCP/IP V1.0b, 4.4.2).
    row("tcp", mbap("0600010003", 1, 0), MatchRule::Mbap, 0, 6, 1, false);
    row("rtu", rtu("0300790016", 1), MatchRule::UnitFunction, 1, 3, 0, false);
    row("rtu", rtu("0600010003", 0), MatchRule::UnitFunction, 0, 6, 0, true);
    row("ascii", ascii("0300000001", 0x11), MatchRule::UnitFunction, 0x11, 3, 0, false);
    row("ascii", ascii("0F000000030105", 0), MatchRule::UnitFunction, 0, 0x0F, 0, true);
    // Only a well-formed frame to unit 0 is a broadcast: one byte too many, or MBAP bytes read as
    // RTU (transaction id 0x0001: "unit 0", no valid CRC), wait for an answer like any request.
    row("ascii", ascii("0F00000003010500", 0), MatchRule::UnitFunction, 0, 0x0F, 0, false);
    row("rtu", mbap("0300790001", 1, 1), MatchRule::UnitFunction, 0, 1, 0, false);
    // Too short for keys: the next frame answers it.
    row("tcp", hex("0001000000"), MatchRule::NextFrame, 0, 0, 0, false);
    row("rtu", hex("01"), MatchRule::NextFrame, 0, 0, 0, false);
    row("delimited", QByteArray("$01R#"), MatchRule::NextFrame, 0, 0, 0, false);
}

void tst_Matcher::keys()
{
    QFETCH(QString, framing);
    QFETCH(QByteArray, request);
    QFETCH(int, rule);
    QFETCH(int, unit);
    QFETCH(int, function);
    QFETCH(int, transactionId);
    QFETCH(bool, broadcast);
    const RequestItem item = itemFor(framing, request);
    QCOMPARE(int(item.rule), rule);
    QCOMPARE(item.bytes, request);
    if (item.rule != MatchRule::NextFrame) {
        QCOMPARE(int(item.unit), unit);
        QCOMPARE(int(item.functionCode), function);
        QCOMPARE(int(item.transactionId), transactionId);
    }
    QCOMPARE(item.broadcast, broadcast);
}

void tst_Matcher::match_data()
{
    QTest::addColumn<QString>("framing");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<ResponseMatcher::Outcome>("outcome");

    using O = ResponseMatcher::Outcome;
    auto row = [](const char *what, const char *framing, const QByteArray &request, const QByteArray &response, O outcome) {
        QTest::newRow(qPrintable(rowName(what, request, response))) << QString::fromLatin1(framing) << request << response << outcome;
    };
    const QByteArray tcpReq = mbap("0300000002", 0x0102, 1);
    row("tcp answer", "tcp", tcpReq, mbap("0304000a000b", 0x0102, 1), O::Match);
    row("tcp exception", "tcp", tcpReq, mbap("8302", 0x0102, 1), O::Match);
    row("tcp wrong transaction id", "tcp", tcpReq, mbap("0304000a000b", 0x0103, 1), O::WrongTransactionId);
    row("tcp wrong unit", "tcp", tcpReq, mbap("0304000a000b", 0x0102, 2), O::WrongUnit);
    row("tcp wrong function", "tcp", tcpReq, mbap("0404000a000b", 0x0102, 1), O::WrongFunction);
    row("tcp other exception", "tcp", tcpReq, mbap("8402", 0x0102, 1), O::WrongFunction);
    row("tcp too short", "tcp", tcpReq, hex("01020000000201"), O::NoKeys);
    // The transaction id decides first: a wrong id with a wrong unit is a wrong id.
    row("tcp wrong id and unit", "tcp", tcpReq, mbap("0304000a000b", 9, 9), O::WrongTransactionId);
    row("udp answer", "udp", mbap("0100000008", 5, 3), mbap("010155", 5, 3), O::Match);

    const QByteArray rtuReq = rtu("0300790016", 1);
    row("rtu answer", "rtu", rtuReq, rtu("0304000a000b", 1), O::Match);
    row("rtu exception", "rtu", rtuReq, rtu("8302", 1), O::Match);
    row("rtu wrong unit", "rtu", rtuReq, rtu("0304000a000b", 2), O::WrongUnit);
    row("rtu wrong function", "rtu", rtuReq, rtu("0404000a000b", 1), O::WrongFunction);
    // A damaged CRC does not prevent the match: the verdict says CRC error.
    row("rtu bad crc", "rtu", rtuReq, hex("010304000a000b0000"), O::Match);
    row("rtu one byte", "rtu", rtuReq, hex("01"), O::NoKeys);

    const QByteArray asciiReq = ascii("0300000001", 0x11);
    row("ascii answer", "ascii", asciiReq, ascii("03020123", 0x11), O::Match);
    row("ascii exception", "ascii", asciiReq, ascii("8301", 0x11), O::Match);
    row("ascii wrong unit", "ascii", asciiReq, ascii("03020123", 0x12), O::WrongUnit);
    row("ascii wrong function", "ascii", asciiReq, ascii("06020123", 0x11), O::WrongFunction);
    row("ascii no digits", "ascii", asciiReq, QByteArray(":1\r\n"), O::NoKeys);
    row("ascii bad digit", "ascii", asciiReq, QByteArray(":11G3\r\n"), O::NoKeys);

    row("delimited next frame", "delimited", QByteArray("$01R#"), QByteArray("$01 293 295 #"), O::Match);
    row("delimited anything", "delimited", QByteArray("$01R#"), QByteArray("x"), O::Match);
    row("keyless tcp request", "tcp", hex("0001"), mbap("0304000a000b", 0x0102, 1), O::Match);
}

void tst_Matcher::match()
{
    QFETCH(QString, framing);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(ResponseMatcher::Outcome, outcome);
    const RequestItem item = itemFor(framing, request);
    const ResponseMatcher::Result result = ResponseMatcher::match(item, response);
    QCOMPARE(int(result.outcome), int(outcome));
    QCOMPARE(result.matched(), outcome == ResponseMatcher::Outcome::Match);
    QCOMPARE(result.problem.isEmpty(), result.matched());
    if (outcome == ResponseMatcher::Outcome::WrongTransactionId)
        QVERIFY2(result.problem.contains(QLatin1String("transaction id")), qPrintable(result.problem));
    if (outcome == ResponseMatcher::Outcome::WrongUnit)
        QVERIFY2(result.problem.contains(QLatin1String("unit")), qPrintable(result.problem));
    if (outcome == ResponseMatcher::Outcome::WrongFunction)
        QVERIFY2(result.problem.contains(QLatin1String("function code")), qPrintable(result.problem));
}

void tst_Matcher::exceptionAnswersOnlyItsFunction()
{
    for (int request = 1; request < 0x80; ++request) {
        for (int response = 0; response < 256; ++response) {
            const bool expected = response == request || response == (request | 0x80);
            QCOMPARE(ResponseMatcher::answersFunction(quint8(request), quint8(response)), expected);
        }
    }
    // A request with bit 7 set (sent on purpose) is answered only by the same code.
    QVERIFY(ResponseMatcher::answersFunction(0x83, 0x83));
    QVERIFY(!ResponseMatcher::answersFunction(0x83, 0x03));
}

void tst_Matcher::itemForLink()
{
    const RequestItem tcp = RequestItem::forLink(mbap("0300000002", 3, 1), parseUrl(QStringLiteral("tcp://h:502?timeout=250ms")));
    QCOMPARE(tcp.timeoutMs, 250);
    QCOMPARE(int(tcp.rule), int(MatchRule::Mbap));
    QCOMPARE(int(tcp.transactionId), 3);
    const RequestItem rtuTcp = RequestItem::forLink(rtu("0600010003", 0), parseUrl(QStringLiteral("rtu-tcp://h:4001")), QStringLiteral("broadcast"));
    QCOMPARE(rtuTcp.timeoutMs, RequestItem{}.timeoutMs);
    QCOMPARE(rtuTcp.name, QStringLiteral("broadcast"));
    QCOMPARE(int(rtuTcp.framing), int(Framing::Rtu));
    QVERIFY(rtuTcp.broadcast);
    const RequestItem udp = RequestItem::forLink(mbap("0300000002", 3, 0), parseUrl(QStringLiteral("udp://h:502")));
    QCOMPARE(int(udp.framing), int(Framing::Udp));
    QVERIFY(!udp.broadcast);
    const RequestItem text = RequestItem::forLink(QByteArray("$01R#"), parseUrl(QStringLiteral("rtu:///dev/ttyS0?baud=9600&framing=delimited&start=24&end=23")));
    QCOMPARE(int(text.rule), int(MatchRule::NextFrame));
    QVERIFY(!text.broadcast);
}

QTEST_GUILESS_MAIN(tst_Matcher)
#include "tst_matcher.moc"
