// AnswerComparison: a replayed answer against the recorded one, row by row from hand-made frames
// (unit 1, register and coil values of the RosRao example; Serial Line V1.02 CRCs computed by
// AduBuilder, MBAP headers by hand).

#include "protocol/adubuilder.h"
#include "replay/answercomparison.h"

#include <QtTest/QTest>

using namespace mbscope;

Q_DECLARE_METATYPE(mbscope::Framing)
Q_DECLARE_METATYPE(mbscope::AnswerComparison::Verdict)

namespace {

// An exchange in framing from request and answer PDUs in hex ("" for no answer).
Transaction exchange(Framing framing, const char *request, const char *answer)
{
    const auto frame = [framing](const QByteArray &pdu) {
        AduOptions options;
        options.framing = framing;
        options.unitId = 1;
        options.transactionId = 7;
        return AduBuilder::complete(pdu, options);
    };
    Transaction t;
    t.request = frame(QByteArray::fromHex(request));
    const QByteArray pdu = QByteArray::fromHex(answer);
    if (pdu.isEmpty()) {
        t.status = TransactionStatus::Timeout;
        return t;
    }
    t.response = frame(pdu);
    t.status = (quint8(pdu.at(0)) & 0x80) ? TransactionStatus::Exception : TransactionStatus::Ok;
    t.exceptionCode = t.status == TransactionStatus::Exception ? quint8(pdu.at(1)) : 0;
    t.sentNs = 1'000'000;
    t.doneNs = 5'000'000;
    return t;
}

} // namespace

class TestAnswerComparison : public QObject
{
    Q_OBJECT

private slots:
    void compare_data();
    void compare();
    void verdictNames();
    void ignoredFields_data();
    void ignoredFields();
};

void TestAnswerComparison::compare_data()
{
    QTest::addColumn<Framing>("recordedFraming");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("recorded");
    QTest::addColumn<Framing>("nowFraming");
    QTest::addColumn<QByteArray>("now");
    QTest::addColumn<AnswerComparison::Verdict>("verdict");
    QTest::addColumn<QStringList>("differences");

    using V = AnswerComparison::Verdict;
    const QByteArray read2("0300790002");
    QTest::newRow("03 same values") << Framing::Rtu << read2 << QByteArray("0304041a00fa") << Framing::Rtu << QByteArray("0304041a00fa")
                                    << V::Match << QStringList{};
    QTest::newRow("03 one register differs")
        << Framing::Rtu << read2 << QByteArray("0304041a00fa") << Framing::Rtu << QByteArray("0304041a00fb") << V::ValuesDiffer
        << QStringList{QStringLiteral("modbus.register_value@0x007A: recorded 250, now 251")};
    QTest::newRow("03 both registers differ")
        << Framing::Tcp << read2 << QByteArray("0304041a00fa") << Framing::Tcp << QByteArray("0304000000fb") << V::ValuesDiffer
        << QStringList{QStringLiteral("modbus.register_value@0x0079: recorded 1050, now 0"),
                       QStringLiteral("modbus.register_value@0x007A: recorded 250, now 251")};
    // The framing's own fields (CRC, MBAP header) are not the device's answer.
    QTest::newRow("recorded rtu, now tcp, same values")
        << Framing::Rtu << read2 << QByteArray("0304041a00fa") << Framing::Tcp << QByteArray("0304041a00fa") << V::Match << QStringList{};
    QTest::newRow("01 one coil differs")
        << Framing::Rtu << QByteArray("0100000004") << QByteArray("010105") << Framing::Rtu << QByteArray("010104") << V::ValuesDiffer
        << QStringList{QStringLiteral("modbus.coil_value@0x0000: recorded 1, now 0")};
    QTest::newRow("06 echo same") << Framing::Rtu << QByteArray("06007d00fa") << QByteArray("06007d00fa") << Framing::Rtu
                                  << QByteArray("06007d00fa") << V::Match << QStringList{};
    QTest::newRow("exception recorded, now normal")
        << Framing::Rtu << read2 << QByteArray("8302") << Framing::Rtu << QByteArray("0304041a00fa") << V::OutcomeDiffers
        << QStringList{QStringLiteral("recorded exception 0x02 (Illegal Data Address), now a normal answer")};
    QTest::newRow("normal recorded, now exception")
        << Framing::Rtu << read2 << QByteArray("0304041a00fa") << Framing::Rtu << QByteArray("8301") << V::OutcomeDiffers
        << QStringList{QStringLiteral("recorded a normal answer, now exception 0x01 (Illegal Function)")};
    QTest::newRow("another exception code")
        << Framing::Tcp << read2 << QByteArray("8302") << Framing::Tcp << QByteArray("830b") << V::OutcomeDiffers
        << QStringList{QStringLiteral("recorded exception 0x02 (Illegal Data Address), now exception 0x0B (Gateway Target Device Failed to Respond)")};
    QTest::newRow("same exception") << Framing::Rtu << read2 << QByteArray("8302") << Framing::Tcp << QByteArray("8302") << V::Match
                                    << QStringList{};
    QTest::newRow("answer recorded, none now")
        << Framing::Rtu << read2 << QByteArray("0304041a00fa") << Framing::Rtu << QByteArray() << V::MissingAnswer
        << QStringList{QStringLiteral("no answer now (recorded a normal answer)")};
    QTest::newRow("none recorded, answer now")
        << Framing::Rtu << read2 << QByteArray() << Framing::Rtu << QByteArray("8302") << V::OutcomeDiffers
        << QStringList{QStringLiteral("recorded no answer, now exception 0x02 (Illegal Data Address)")};
    QTest::newRow("none recorded, none now") << Framing::Rtu << read2 << QByteArray() << Framing::Rtu << QByteArray() << V::Match
                                             << QStringList{};
}

void TestAnswerComparison::compare()
{
    QFETCH(Framing, recordedFraming);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, recorded);
    QFETCH(Framing, nowFraming);
    QFETCH(QByteArray, now);
    QFETCH(AnswerComparison::Verdict, verdict);
    QFETCH(QStringList, differences);

    const AnswerComparison::Result r = AnswerComparison::compare(exchange(recordedFraming, request, recorded), recordedFraming,
                                                                 exchange(nowFraming, request, now), nowFraming);
    QCOMPARE(r.differences, differences);
    QCOMPARE(r.verdict, verdict);
    QCOMPARE(r.matched(), verdict == AnswerComparison::Verdict::Match);
}

void TestAnswerComparison::verdictNames()
{
    QCOMPARE(AnswerComparison::verdictName(AnswerComparison::Verdict::MissingAnswer), QStringLiteral("missing answer"));
    Transaction crc;
    crc.status = TransactionStatus::CrcError;
    crc.problem = QStringLiteral("CRC 0x1234, expected 0x4321");
    QCOMPARE(AnswerComparison::describeOutcome(crc), QStringLiteral("crc_error (CRC 0x1234, expected 0x4321)"));
}

void TestAnswerComparison::ignoredFields_data()
{
    // Register 0x007A changes (a live count); the selectors that cover it, and those that do not.
    QTest::addColumn<QStringList>("ignore");
    QTest::addColumn<bool>("matched");
    QTest::addColumn<int>("ignored");
    QTest::newRow("nothing ignored") << QStringList{} << false << 0;
    QTest::newRow("@0x007A") << QStringList{QStringLiteral("modbus.register_value@0x007A")} << true << 1;
    QTest::newRow("@122 decimal") << QStringList{QStringLiteral("modbus.register_value@122")} << true << 1;
    QTest::newRow("key alone, every address") << QStringList{QStringLiteral("modbus.register_value")} << true << 1;
    QTest::newRow("another address") << QStringList{QStringLiteral("modbus.register_value@0x0079")} << false << 0;
    QTest::newRow("another key") << QStringList{QStringLiteral("modbus.coil_value@0x007A")} << false << 0;
}

void TestAnswerComparison::ignoredFields()
{
    QFETCH(QStringList, ignore);
    QFETCH(bool, matched);
    QFETCH(int, ignored);
    IgnoredFields fields;
    for (const QString &selector : ignore) {
        QString error;
        QVERIFY2(fields.add(selector, &error), qPrintable(error));
    }
    const QByteArray read2("0300790002");
    // 0x0079 is 1050 both times, 0x007A 250 then 251: only a difference is reported ignored.
    const AnswerComparison::Result r = AnswerComparison::compare(exchange(Framing::Rtu, read2, "0304041a00fa"), Framing::Rtu,
                                                                 exchange(Framing::Rtu, read2, "0304041a00fb"), Framing::Rtu, fields);
    QCOMPARE(r.matched(), matched);
    QCOMPARE(r.ignored.size() > 0, ignored > 0);
    if (ignored > 0) {
        QCOMPARE(r.ignored.size(), 1);
        QCOMPARE(r.ignored.constFirst().difference, QStringLiteral("modbus.register_value@0x007A: recorded 250, now 251"));
        QCOMPARE(r.ignored.constFirst().selector, ignore.constFirst());
        QVERIFY(r.differences.isEmpty());
    } else {
        QCOMPARE(r.differences, QStringList{QStringLiteral("modbus.register_value@0x007A: recorded 250, now 251")});
    }
    // A selector that names no field is refused, saying why.
    IgnoredFields bad;
    QString error;
    QVERIFY(!bad.add(QStringLiteral("register@0x7A"), &error));
    QVERIFY2(error.contains(QLatin1String("is not a field selector")), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestAnswerComparison)
#include "tst_answercomparison.moc"
