// The status of a matched answer, from the Dissector reading it as the response to its request.

#include "../engine/enginetesting.h"

#include "exchange/responseverdict.h"
#include "protocol/delimitedframer.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::test;

Q_DECLARE_METATYPE(mbscope::TransactionStatus)

class tst_ResponseVerdict : public QObject
{
    Q_OBJECT

private slots:
    void modbus_data();
    void modbus();
    void delimited_data();
    void delimited();
    void registerCheckAgrees_data();
    void registerCheckAgrees();
};

void tst_ResponseVerdict::modbus_data()
{
    QTest::addColumn<QString>("framing");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<TransactionStatus>("status");
    QTest::addColumn<int>("exceptionCode");
    QTest::addColumn<QString>("problem"); // a part of the problem text

    using S = TransactionStatus;
    auto row = [](const char *framing, const QByteArray &request, const QByteArray &response, S status, int code,
                  const char *problem) {
        QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(QLatin1String(framing), QString::fromLatin1(response.toHex(' ')))))
            << QString::fromLatin1(framing) << request << response << status << code << QString::fromLatin1(problem);
    };
    const QByteArray tcpRead = mbap("0300000002", 1, 1);
    row("tcp", tcpRead, mbap("0304000a000b", 1, 1), S::Ok, 0, "");
    row("tcp", tcpRead, mbap("8302", 1, 1), S::Exception, 2, "Illegal Data Address");
    row("tcp", tcpRead, mbap("8304", 1, 1), S::Exception, 4, "Server Device Failure");
    // Byte count 4 announces 4 data bytes, 2 are present (V1.1b3, 6.3).
    row("tcp", tcpRead, mbap("0304000a", 1, 1), S::Malformed, 0, "byte count");
    // Two registers asked, three answered.
    row("tcp", tcpRead, mbap("0306000a000b000c", 1, 1), S::Malformed, 0, "");
    // The MBAP length field says 9 bytes follow, 7 do.
    row("tcp", tcpRead, hex("000100000009010304000a000b"), S::Malformed, 0, "mbap.length");
    // An exception without its code.
    row("tcp", tcpRead, mbap("83", 1, 1), S::Malformed, 0, "");

    const QByteArray rtuRead = rtu("0300790016", 1);
    // 22 registers: byte count 0x2C and 44 data bytes (the RosRao module's answer layout).
    const QByteArray registers = hex("032C") + QByteArray(44, '\x01');
    row("rtu", rtuRead, AduBuilder::rtu(registers, 1), S::Ok, 0, "");
    row("rtu", rtuRead, rtu("8302", 1), S::Exception, 2, "");
    QByteArray badCrc = AduBuilder::rtu(registers, 1);
    badCrc[badCrc.size() - 1] = char(badCrc.at(badCrc.size() - 1) ^ 0x55);
    row("rtu", rtuRead, badCrc, S::CrcError, 0, "CRC");
    // A wrong CRC wins over every other problem: the rest of a damaged frame is not trusted.
    QByteArray shortAndBad = rtu("0304000a", 1);
    shortAndBad[shortAndBad.size() - 2] = char(shortAndBad.at(shortAndBad.size() - 2) ^ 0x01);
    row("rtu", rtu("0300000002", 1), shortAndBad, S::CrcError, 0, "CRC");
    row("rtu", rtu("0300000002", 1), rtu("0304000a", 1), S::Malformed, 0, "");
    row("rtu", rtu("0600010003", 1), rtu("0600010003", 1), S::Ok, 0, "");
    // The echo of a write must repeat the request (V1.1b3, 6.6).
    row("rtu", rtu("1000010002040001000200", 1), rtu("1000010002", 1), S::Ok, 0, "");

    const QByteArray asciiRead = ascii("0300000001", 0x11);
    row("ascii", asciiRead, ascii("03020123", 0x11), S::Ok, 0, "");
    row("ascii", asciiRead, ascii("8301", 0x11), S::Exception, 1, "Illegal Function");
    QByteArray badLrc = ascii("03020123", 0x11);
    badLrc[badLrc.size() - 3] = badLrc.at(badLrc.size() - 3) == '0' ? '1' : '0';
    row("ascii", asciiRead, badLrc, S::CrcError, 0, "LRC");
}

void tst_ResponseVerdict::modbus()
{
    QFETCH(QString, framing);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(TransactionStatus, status);
    QFETCH(int, exceptionCode);
    QFETCH(QString, problem);

    ResponseVerdict verdict(*framingFromName(framing), false);
    const ResponseVerdict::Result r = verdict.judge(response, request);
    QVERIFY2(r.status == status, qPrintable(transactionStatusName(r.status) + QStringLiteral(": ") + r.problem));
    QCOMPARE(int(r.exceptionCode), exceptionCode);
    QVERIFY2(r.problem.contains(problem, Qt::CaseInsensitive), qPrintable(r.problem));
    if (status == TransactionStatus::Ok)
        QVERIFY(r.problem.isEmpty());
    else
        QVERIFY(!r.problem.isEmpty());
    // The same through the StreamFrame overload.
    StreamFrame frame;
    frame.bytes = response;
    QCOMPARE(int(verdict.judge(frame, request).status), int(status));
}

void tst_ResponseVerdict::delimited_data()
{
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<TransactionStatus>("status");

    DelimitedFraming f;
    f.enabled = true;
    f.startBytes = QByteArray("\x05");
    f.endBytes = QByteArray("\x04");
    f.checksum = DelimitedChecksum::Sum;
    const QByteArray good = DelimitedFramer::complete(f, QByteArray("\x05" "00RSS\x04"));
    QByteArray bad = good;
    bad[bad.size() - 1] = char(bad.at(bad.size() - 1) + 1);
    QTest::newRow(qPrintable(QString::fromLatin1(good.toHex(' ')))) << good << TransactionStatus::Ok;
    QTest::newRow(qPrintable(QString::fromLatin1(bad.toHex(' ')))) << bad << TransactionStatus::CrcError;
}

void tst_ResponseVerdict::delimited()
{
    QFETCH(QByteArray, frame);
    QFETCH(TransactionStatus, status);
    DelimitedFraming f;
    f.enabled = true;
    f.startBytes = QByteArray("\x05");
    f.endBytes = QByteArray("\x04");
    f.checksum = DelimitedChecksum::Sum;
    DelimitedFramer framer(f);
    framer.feed(frame);
    const QList<StreamFrame> frames = framer.takeFrames();
    QCOMPARE(frames.size(), 1);
    ResponseVerdict verdict(Framing::Tcp, true);
    const ResponseVerdict::Result r = verdict.judge(frames.first(), QByteArray("\x05" "00RSS\x04"));
    QCOMPARE(int(r.status), int(status));
}

void tst_ResponseVerdict::registerCheckAgrees_data()
{
    QTest::addColumn<QString>("framing");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    auto row = [](const char *framing, const QByteArray &request, const QByteArray &response) {
        QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(QLatin1String(framing), QString::fromLatin1(request.toHex(' ')))))
            << QString::fromLatin1(framing) << request << response;
    };
    row("tcp", mbap("0300000002", 0x2A2A, 1), mbap("030403e803eb", 0x2A2A, 1));
    row("tcp", mbap("0400070001", 7, 0), mbap("040201f4", 7, 0));
    row("udp", mbap("040000000a", 1, 255), mbap(QByteArray("0414" + QByteArray(40, '7')).constData(), 1, 255));
    // 125 registers, the most one request may ask for, ending at the last address (V1.1b3, 6.3).
    row("tcp", mbap("03ff83007d", 0xFFFF, 1), mbap(QByteArray("03fa" + QByteArray(500, 'a')).constData(), 0xFFFF, 1));
}

// The register check says Ok without the dissector; wherever it does, the dissector must agree.
// Every byte of request and answer is changed in turn (one bit, the top bit, all bits), and the
// answer is cut and lengthened: each variant the check accepts must be Ok for the dissector too,
// and the unchanged answer must be accepted (else the check would never be used).
void tst_ResponseVerdict::registerCheckAgrees()
{
    QFETCH(QString, framing);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    ResponseVerdict verdict(*framingFromName(framing), false);
    QVERIFY(verdict.isExpectedRegisterAnswer(response, request));
    QCOMPARE(int(verdict.judgeByDissection(response, request).status), int(TransactionStatus::Ok));

    int accepted = 0;
    auto check = [&](const QByteArray &answer, const QByteArray &asked, const QString &what) {
        if (!verdict.isExpectedRegisterAnswer(answer, asked))
            return true;
        ++accepted;
        const ResponseVerdict::Result full = verdict.judgeByDissection(answer, asked);
        if (full.status == TransactionStatus::Ok)
            return true;
        qWarning("%s: the register check accepts %s for %s; the dissector says %s: %s", qPrintable(what),
                 answer.toHex(' ').constData(), asked.toHex(' ').constData(), qPrintable(transactionStatusName(full.status)),
                 qPrintable(full.problem));
        return false;
    };
    for (const char mask : {char(0x01), char(0x80), char(0xFF)}) {
        for (qsizetype i = 0; i < response.size(); ++i) {
            QByteArray changed = response;
            changed[i] = char(changed.at(i) ^ mask);
            QVERIFY(check(changed, request, QStringLiteral("answer byte %1 ^ %2").arg(i).arg(quint8(mask))));
        }
        for (qsizetype i = 0; i < request.size(); ++i) {
            QByteArray changed = request;
            changed[i] = char(changed.at(i) ^ mask);
            QVERIFY(check(response, changed, QStringLiteral("request byte %1 ^ %2").arg(i).arg(quint8(mask))));
        }
    }
    for (qsizetype n = 0; n < response.size(); ++n)
        QVERIFY(check(response.first(n), request, QStringLiteral("answer cut to %1 bytes").arg(n)));
    QVERIFY(check(response + '\0', request, QStringLiteral("answer with a byte more")));
    // Register values are free: changing them keeps the answer accepted.
    QVERIFY(accepted >= 3 * (response.size() - 9));
}

QTEST_GUILESS_MAIN(tst_ResponseVerdict)
#include "tst_responseverdict.moc"
