// UnitClassifier: the engine's verdict on one probe named for a unit scan, one row per kind,
// named by the answer's hex (RTU unless said).

#include "discovery/unitclassifier.h"

#include "protocol/adubuilder.h"

#include <QtTest/QTest>

using namespace mbscope;

namespace {

const QByteArray kRequest = AduBuilder::rtu(QByteArray::fromHex("0300000001"), 5);

Transaction transaction(TransactionStatus status, const QByteArray &response, quint8 exceptionCode = 0)
{
    Transaction t;
    t.request = kRequest;
    t.response = response;
    t.status = status;
    t.exceptionCode = exceptionCode;
    t.sentNs = 1000;
    t.doneNs = response.isEmpty() ? 0 : 2000;
    return t;
}

} // namespace

class TestUnitClassifier : public QObject
{
    Q_OBJECT

private slots:
    void classify_data();
    void classify();
    void echoOfAnMbapRequest();
};

void TestUnitClassifier::classify_data()
{
    QTest::addColumn<Transaction>("t");
    QTest::addColumn<QByteArray>("bytesRead");
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("exceptionCode");
    QTest::addColumn<int>("answeredUnit");

    const QByteArray ok = AduBuilder::rtu(QByteArray::fromHex("030203E8"), 5);
    QTest::newRow(ok.toHex(' ').constData()) << transaction(TransactionStatus::Ok, ok) << ok
                                             << int(UnitProbeKind::Answers) << 0 << 0;
    const QByteArray e02 = AduBuilder::rtu(QByteArray::fromHex("8302"), 5);
    QTest::newRow(e02.toHex(' ').constData()) << transaction(TransactionStatus::Exception, e02, 2) << e02
                                              << int(UnitProbeKind::Exception) << 2 << 0;
    const QByteArray e0a = AduBuilder::rtu(QByteArray::fromHex("830A"), 5);
    QTest::newRow(e0a.toHex(' ').constData()) << transaction(TransactionStatus::Exception, e0a, 0x0A) << e0a
                                              << int(UnitProbeKind::GatewayPathUnavailable) << 0x0A << 0;
    const QByteArray e0b = AduBuilder::rtu(QByteArray::fromHex("830B"), 5);
    QTest::newRow(e0b.toHex(' ').constData()) << transaction(TransactionStatus::Exception, e0b, 0x0B) << e0b
                                              << int(UnitProbeKind::GatewayTargetFailed) << 0x0B << 0;
    const QByteArray other = AduBuilder::rtu(QByteArray::fromHex("030203E8"), 9);
    QTest::newRow(other.toHex(' ').constData()) << transaction(TransactionStatus::Unexpected, other) << other
                                                << int(UnitProbeKind::WrongUnit) << 0 << 9;
    QByteArray badCrc = ok;
    badCrc[badCrc.size() - 1] = char(badCrc.at(badCrc.size() - 1) ^ 0xFF);
    QTest::newRow(badCrc.toHex(' ').constData()) << transaction(TransactionStatus::CrcError, badCrc) << badCrc
                                                 << int(UnitProbeKind::Garbage) << 0 << 0;
    const QByteArray wrongFunction = AduBuilder::rtu(QByteArray::fromHex("040203E8"), 5);
    QTest::newRow(wrongFunction.toHex(' ').constData()) << transaction(TransactionStatus::Unexpected, wrongFunction) << wrongFunction
                                                        << int(UnitProbeKind::Garbage) << 0 << 0;
    QTest::newRow("timeout, nothing read") << transaction(TransactionStatus::Timeout, {}) << QByteArray()
                                           << int(UnitProbeKind::Silent) << 0 << 0;
    QTest::newRow("timeout, DE AD read") << transaction(TransactionStatus::Timeout, {}) << QByteArray::fromHex("DEAD")
                                         << int(UnitProbeKind::Garbage) << 0 << 0;
    QTest::newRow("echo framed as garbage") << transaction(TransactionStatus::Timeout, {}) << kRequest
                                            << int(UnitProbeKind::Echo) << 0 << 0;
    QTest::newRow("link error") << transaction(TransactionStatus::LinkError, {}) << QByteArray()
                                << int(UnitProbeKind::LinkError) << 0 << 0;
}

void TestUnitClassifier::classify()
{
    QFETCH(Transaction, t);
    QFETCH(QByteArray, bytesRead);
    QFETCH(int, kind);
    QFETCH(int, exceptionCode);
    QFETCH(int, answeredUnit);
    const UnitProbe probe = UnitClassifier::classify(5, t, Framing::Rtu, bytesRead);
    QCOMPARE(unitProbeKindName(probe.kind), unitProbeKindName(UnitProbeKind(kind)));
    QCOMPARE(int(probe.exceptionCode), exceptionCode);
    QCOMPARE(int(probe.answeredUnit), answeredUnit);
    QCOMPARE(probe.unit, quint8(5));
    QCOMPARE(probe.isPresent(), probe.kind == UnitProbeKind::Answers || probe.kind == UnitProbeKind::Exception);
    QVERIFY(!probe.summary().isEmpty());
}

void TestUnitClassifier::echoOfAnMbapRequest()
{
    // The echo carries the request's keys, so the engine matched it and found it malformed.
    const QByteArray request = AduBuilder::mbap(QByteArray::fromHex("0300000001"), 1, 7);
    Transaction t;
    t.request = request;
    t.response = request;
    t.status = TransactionStatus::Malformed;
    const UnitProbe probe = UnitClassifier::classify(1, t, Framing::Tcp, request);
    QCOMPARE(unitProbeKindName(probe.kind), "echo");
    QCOMPARE(probe.response, request);
}

QTEST_GUILESS_MAIN(TestUnitClassifier)
#include "tst_unitclassifier.moc"
