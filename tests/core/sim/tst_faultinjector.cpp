#include "faultcases.h"
#include "json/jsonreader.h"
#include "profile/faultrulereader.h"
#include "protocol/adubuilder.h"
#include "sim/faultbytes.h"
#include "sim/faultinjector.h"
#include "sim/simexchange.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QThread>
#include <QtTest/QtTest>

#include <atomic>
#include <cmath>

using namespace mbscope;

class TestFaultInjector : public QObject
{
    Q_OBJECT
private slots:
    void context_data()
    {
        faultcases::addContextRows();
    }
    void context()
    {
        QFETCH(QByteArray, request);
        QFETCH(int, unit);
        QFETCH(int, function);
        QFETCH(int, first);
        QFETCH(int, last);
        const FaultContext c = FaultContext::forRequest(Framing::Rtu, request, QByteArray(), 5);
        QCOMPARE(int(c.unit), unit);
        QCOMPARE(int(c.function), function);
        QCOMPARE(c.firstAddress, first);
        QCOMPARE(c.lastAddress, last);
        QCOMPARE(c.responseDelayNs, qint64(5));
        QCOMPARE(c.request, request);
    }

    void noRules()
    {
        FaultInjector injector;
        const FaultPlan plan = injector.plan(rtuContext());
        verifySingle(plan, hex(kRtuResponse));
        QVERIFY(plan.faults.isEmpty());
    }

    // Every fault's exact bytes: only what the fault names is wrong.
    void exactBytes_data()
    {
        faultcases::addExactByteRows();
    }
    void exactBytes()
    {
        QFETCH(int, framing);
        QFETCH(FaultRule, faultRule);
        QFETCH(QByteArray, expected);
        FaultContext c;
        switch (Framing(framing)) {
        case Framing::Rtu:
            c = rtuContext();
            break;
        case Framing::Ascii:
            c = asciiContext();
            break;
        default:
            c = tcpContext();
            break;
        }
        const FaultPlan plan = planWith(faultRule, c);
        verifySingle(plan, expected);
        QCOMPARE(plan.faults, QStringList{FaultRule::kindName(faultRule.kind)});
    }

    // Faults that need what the answer does not have do not apply: the answer goes out unchanged
    // and nothing is listed as fired.
    void notApplicable_data()
    {
        QTest::addColumn<int>("framing");
        QTest::addColumn<FaultRule>("faultRule");
        QTest::newRow("wrong checksum on tcp") << int(Framing::Tcp) << rule(FaultRule::Kind::WrongChecksum);
        QTest::newRow("wrong tid on rtu") << int(Framing::Rtu) << rule(FaultRule::Kind::WrongTransactionId);
        QTest::newRow("wrong tid on ascii") << int(Framing::Ascii) << rule(FaultRule::Kind::WrongTransactionId);
    }
    void notApplicable()
    {
        QFETCH(int, framing);
        QFETCH(FaultRule, faultRule);
        const FaultContext c = Framing(framing) == Framing::Tcp ? tcpContext()
            : Framing(framing) == Framing::Rtu                  ? rtuContext()
                                                                : asciiContext();
        const FaultPlan plan = planWith(faultRule, c);
        verifySingle(plan, c.response);
        QVERIFY(plan.faults.isEmpty());
    }

    void fewerRegistersPdu_data()
    {
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<int>("fewer");
        QTest::addColumn<QByteArray>("expected");
        auto row = [](const char *pdu, int fewer, const char *expected) {
            QTest::addRow("%s fewer %d", pdu, fewer) << hex(pdu) << fewer << (expected ? hex(expected) : QByteArray());
        };
        row("01 02 CD 01", 1, "01 01 CD");                 // coils: one data byte fewer
        row("02 03 AC DB 35", 2, "02 01 AC");              // discrete inputs
        row("04 06 03 E8 01 F4 00 0A", 1, "04 04 03 E8 01 F4");
        row("17 06 00 FE 0A CD 00 01", 1, "17 04 00 FE 0A CD");
        row("18 00 06 00 02 01 B8 12 84", 1, "18 00 04 00 01 01 B8"); // FIFO: byte count and FIFO count
        row("18 00 06 00 02 01 B8 12 84", 9, "18 00 02 00 00");
        row("03 02 00 01", 1, "03 00");
        row("83 02", 1, nullptr);                           // an exception
        row("06 00 01 00 03", 1, nullptr);                  // not a read
        row("03 00", 1, nullptr);                           // nothing to take away
        row("03 04 00 01", 1, nullptr);                     // inconsistent already
    }
    void fewerRegistersPdu()
    {
        QFETCH(QByteArray, pdu);
        QFETCH(int, fewer);
        QFETCH(QByteArray, expected);
        QCOMPARE(hexText(FaultBytes::fewerRegistersPdu(pdu, fewer)), hexText(expected));
    }

    void drop()
    {
        const FaultPlan plan = planWith(rule(FaultRule::Kind::Drop), rtuContext());
        QVERIFY(plan.drop);
        QVERIFY(plan.chunks.isEmpty());
        QCOMPARE(plan.faults, QStringList{QStringLiteral("drop")});
    }

    void close_data()
    {
        QTest::addColumn<int>("when");
        QTest::addColumn<bool>("before");
        QTest::addColumn<bool>("after");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("before") << int(FaultRule::CloseWhen::Before) << true << false << QByteArray();
        QTest::newRow("after") << int(FaultRule::CloseWhen::After) << false << true << hex(kRtuResponse);
        QTest::newRow("midway: 01 03 04 04 of 9 bytes") << int(FaultRule::CloseWhen::Midway) << false << true << hex("01 03 04 04");
    }
    void close()
    {
        QFETCH(int, when);
        QFETCH(bool, before);
        QFETCH(bool, after);
        QFETCH(QByteArray, bytes);
        FaultRule r = rule(FaultRule::Kind::Close);
        r.closeWhen = FaultRule::CloseWhen(when);
        const FaultPlan plan = planWith(r, rtuContext());
        QCOMPARE(plan.closeBefore, before);
        QCOMPARE(plan.closeAfter, after);
        QVERIFY(!plan.drop);
        if (before) {
            QVERIFY(plan.chunks.isEmpty());
        } else {
            QCOMPARE(plan.chunks.size(), 1);
            QCOMPARE(hexText(plan.chunks.at(0).bytes), hexText(bytes));
            QCOMPARE(plan.chunks.at(0).delayNs, kUnitDelayNs);
        }
    }

    void chunks()
    {
        FaultRule r = rule(FaultRule::Kind::Chunks);
        r.chunkBytes = 4;
        r.gapMs = 2.5;
        const FaultPlan plan = planWith(r, rtuContext());
        QCOMPARE(plan.chunks.size(), 3);
        QCOMPARE(hexText(plan.chunks.at(0).bytes), QStringLiteral("01 03 04 04"));
        QCOMPARE(hexText(plan.chunks.at(1).bytes), QStringLiteral("1A 00 00 DA"));
        QCOMPARE(hexText(plan.chunks.at(2).bytes), QStringLiteral("C4"));
        QCOMPARE(plan.chunks.at(0).delayNs, kUnitDelayNs);
        QCOMPARE(plan.chunks.at(1).delayNs, qint64(2500000));
        QCOMPARE(plan.chunks.at(2).delayNs, qint64(2500000));
    }

    void trickle()
    {
        FaultRule r = rule(FaultRule::Kind::Trickle);
        r.gapMs = 20;
        const FaultPlan plan = planWith(r, tcpContext());
        const QByteArray response = hex(kTcpResponse);
        QCOMPARE(plan.chunks.size(), response.size());
        for (qsizetype i = 0; i < response.size(); ++i) {
            QCOMPARE(plan.chunks.at(i).bytes, response.mid(i, 1));
            QCOMPARE(plan.chunks.at(i).delayNs, i == 0 ? kUnitDelayNs : qint64(20000000));
        }
    }

    void junk()
    {
        FaultRule r = rule(FaultRule::Kind::Junk);
        r.junkBefore = hex("DE AD");
        r.junkAfterCount = 3;
        const FaultPlan a = planWith(r, rtuContext(), 7);
        QCOMPARE(a.chunks.size(), 1);
        const QByteArray bytes = a.chunks.at(0).bytes;
        QCOMPARE(bytes.size(), 2 + 9 + 3);
        QCOMPARE(hexText(bytes.left(11)), QStringLiteral("DE AD ") + QString::fromLatin1(kRtuResponse));
        // Random junk: the same seed gives the same bytes, another seed others.
        QCOMPARE(planWith(r, rtuContext(), 7).chunks.at(0).bytes, bytes);
        QVERIFY(planWith(r, rtuContext(), 8).chunks.at(0).bytes.right(3) != bytes.right(3));
    }

    void duplicate()
    {
        FaultRule r = rule(FaultRule::Kind::Duplicate);
        r.copies = 2;
        r.gapMs = 5;
        const FaultPlan plan = planWith(r, tcpContext());
        QCOMPARE(plan.chunks.size(), 3);
        for (const ResponseChunk &chunk : plan.chunks)
            QCOMPARE(chunk.bytes, hex(kTcpResponse));
        QCOMPARE(plan.chunks.at(0).delayNs, kUnitDelayNs);
        QCOMPARE(plan.chunks.at(1).delayNs, qint64(5000000));
        QCOMPARE(plan.chunks.at(2).delayNs, qint64(5000000));
    }

    void fixedDelay()
    {
        FaultRule r = rule(FaultRule::Kind::Delay);
        r.delay = DelaySpec::fixed(1500);
        verifySingle(planWith(r, rtuContext()), hex(kRtuResponse), qint64(1500) * 1000000);
    }

    void combined();
    void filters_data();
    void filters();
    void exactFilters_data();
    void exactFilters();
    void byInterval();
    void turnaround();
    void noise();
    void dropProportion();
    void delayDistributions_data();
    void delayDistributions();
    void unitResponseDelay();
    void planOfExchange_data();
    void planOfExchange();
    void reproducible();
    void setRulesWhileRunning();
    void setRulesFromAnotherThread();
};

// Several rules on one answer combine in the documented order, whatever their list order.
void TestFaultInjector::combined()
{
    FaultRule checksum = rule(FaultRule::Kind::WrongChecksum);
    FaultRule exception = rule(FaultRule::Kind::Exception);
    FaultRule junk = rule(FaultRule::Kind::Junk);
    junk.junkBefore = hex("FF");
    FaultRule chunks = rule(FaultRule::Kind::Chunks);
    chunks.chunkBytes = 2;
    chunks.gapMs = 1;
    FaultRule closeAfter = rule(FaultRule::Kind::Close);
    checksum.name = QStringLiteral("noisy line");
    FaultInjector injector;
    injector.setRules(FaultRuleSet{1, {checksum, chunks, exception, junk, closeAfter}});
    const FaultPlan plan = injector.plan(rtuContext());
    // Exception 01 83 04 40 F3, CRC inverted (BF 0C), junk FF before, in pieces of two.
    QCOMPARE(plan.chunks.size(), 3);
    QCOMPARE(hexText(plan.chunks.at(0).bytes), QStringLiteral("FF 01"));
    QCOMPARE(hexText(plan.chunks.at(1).bytes), QStringLiteral("83 04"));
    QCOMPARE(hexText(plan.chunks.at(2).bytes), QStringLiteral("BF 0C"));
    QVERIFY(plan.closeAfter);
    QCOMPARE(plan.faults, (QStringList{QStringLiteral("noisy line"), QStringLiteral("chunks"), QStringLiteral("exception"),
                                       QStringLiteral("junk"), QStringLiteral("close")}));
    // Drop wins over everything else.
    injector.setRules(FaultRuleSet{1, {exception, rule(FaultRule::Kind::Drop), junk}});
    const FaultPlan dropped = injector.plan(rtuContext());
    QVERIFY(dropped.drop);
    QVERIFY(dropped.chunks.isEmpty());
    // Wrong unit then wrong CRC: the CRC of the new unit's frame, inverted (E9 C4 -> 16 3B).
    injector.setRules(FaultRuleSet{1, {rule(FaultRule::Kind::WrongChecksum), rule(FaultRule::Kind::WrongUnit)}});
    QCOMPARE(hexText(injector.plan(rtuContext()).chunks.at(0).bytes), QStringLiteral("02 03 04 04 1A 00 00 16 3B"));
}

void TestFaultInjector::filters_data()
{
    QTest::addColumn<QList<quint8>>("units");
    QTest::addColumn<QList<quint8>>("functions");
    QTest::addColumn<int>("first");
    QTest::addColumn<int>("last");
    QTest::addColumn<bool>("fires");
    // The request: unit 1, 03, 0x79-0x7A (121-122).
    QTest::newRow("everything") << QList<quint8>{} << QList<quint8>{} << -1 << -1 << true;
    QTest::newRow("unit 1") << QList<quint8>{1} << QList<quint8>{} << -1 << -1 << true;
    QTest::newRow("unit 3") << QList<quint8>{3} << QList<quint8>{} << -1 << -1 << false;
    QTest::newRow("units 2, 1") << QList<quint8>{2, 1} << QList<quint8>{} << -1 << -1 << true;
    QTest::newRow("function 03") << QList<quint8>{} << QList<quint8>{0x03} << -1 << -1 << true;
    QTest::newRow("function 10") << QList<quint8>{} << QList<quint8>{0x10} << -1 << -1 << false;
    QTest::newRow("range ending at 121") << QList<quint8>{} << QList<quint8>{} << 100 << 121 << true;
    QTest::newRow("range starting at 122") << QList<quint8>{} << QList<quint8>{} << 122 << 200 << true;
    QTest::newRow("range before") << QList<quint8>{} << QList<quint8>{} << 0 << 120 << false;
    QTest::newRow("range after") << QList<quint8>{} << QList<quint8>{} << 123 << 65535 << false;
    QTest::newRow("unit 1, 03, range") << QList<quint8>{1} << QList<quint8>{3} << 121 << 121 << true;
}

void TestFaultInjector::filters()
{
    QFETCH(QList<quint8>, units);
    QFETCH(QList<quint8>, functions);
    QFETCH(int, first);
    QFETCH(int, last);
    QFETCH(bool, fires);
    FaultRule r = rule(FaultRule::Kind::Drop);
    r.units = units;
    r.functions = functions;
    r.firstAddress = first;
    r.lastAddress = last;
    QCOMPARE(planWith(r, rtuContext()).drop, fires);
    QCOMPARE(FaultInjector::matches(r, rtuContext()), fires);
}

// A drop probability observed over many answers, within five standard errors of a proportion.
// Exact matching (start, quantity, values) against "meets" (overlap), request by request, as the
// libmodbus unit-test server needs them: a rule for start 0x170 must not fire on a read of
// 0x160-0x17F, which meets it. Requests are RTU, unit 1 (CRCs computed by the builder).
void TestFaultInjector::exactFilters_data()
{
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<QString>("rule"); // the rule's matching keys, as a profile writes them
    QTest::addColumn<bool>("fires");
    const auto row = [](const char *name, const char *pdu, const char *rule, bool fires) {
        QTest::newRow(name) << hex(pdu) << QString::fromLatin1(rule) << fires;
    };
    row("start 0x170, read at 0x170", "03 01 70 00 01", R"("start": "0x0170")", true);
    row("start 0x170, read of 0x160-0x17F", "03 01 60 00 20", R"("start": "0x0170")", false);
    row("meets 0x170, read of 0x160-0x17F", "03 01 60 00 20", R"("meets": "0x0170")", true);
    row("meets 0x170, read of 0x171", "03 01 71 00 01", R"("meets": "0x0170")", false);
    row("addresses (older name of meets)", "03 01 60 00 20", R"("addresses": ["0x0170", "0x0171"])", true);
    row("quantity 2, read of 2", "03 01 60 00 02", R"("quantity": 2)", true);
    row("quantity 2, read of 3", "03 01 60 00 03", R"("quantity": 2)", false);
    row("quantity 2 or 3, read of 3", "03 01 60 00 03", R"("quantity": [2, 3])", true);
    row("start and quantity, both", "03 01 60 00 02", R"("start": 352, "quantity": 2)", true);
    row("start and quantity, start differs", "03 01 61 00 02", R"("start": 352, "quantity": 2)", false);
    row("06 value 0x1234", "06 00 10 12 34", R"("values": ["0x1234"])", true);
    row("06 value 0x1235", "06 00 10 12 35", R"("values": ["0x1234"])", false);
    row("05 coil on", "05 00 03 FF 00", R"("values": [1])", true);
    row("05 coil off", "05 00 03 00 00", R"("values": [1])", false);
    row("10 two registers", "10 00 00 00 02 04 00 01 00 02", R"("values": [1, 2])", true);
    row("10 one register differs", "10 00 00 00 02 04 00 01 00 03", R"("values": [1, 2])", false);
    row("10 fewer values than the rule", "10 00 00 00 01 02 00 01", R"("values": [1, 2])", false);
    row("0F bits 1 0 1", "0F 00 00 00 03 01 05", R"("values": [1, 0, 1])", true);
    row("0F bits 1 1 1", "0F 00 00 00 03 01 07", R"("values": [1, 0, 1])", false);
    row("values on a read never match", "03 00 00 00 01", R"("values": [1])", false);
    row("17 read start and quantity", "17 00 10 00 02 00 20 00 01 02 00 07", R"("start": 16, "quantity": 2, "values": [7])", true);
    row("16 masks", "16 00 04 00 F2 00 25", R"("values": ["0x00F2", "0x0025"])", true);
}

void TestFaultInjector::exactFilters()
{
    QFETCH(QByteArray, pdu);
    QFETCH(QString, rule);
    QFETCH(bool, fires);
    QList<ProfileProblem> problems;
    JsonReader reader(&problems, QStringLiteral("test"));
    const QJsonDocument doc = QJsonDocument::fromJson(QStringLiteral("{\"kind\": \"drop\", %1}").arg(rule).toUtf8());
    const auto r = FaultRuleReader::readRule(reader, doc.object(), QStringLiteral("rule"));
    QVERIFY2(r.has_value(), qPrintable(ProfileProblem::join(problems)));
    const QByteArray request = AduBuilder::rtu(pdu, 1);
    const FaultContext context = FaultContext::forRequest(Framing::Rtu, request, hex(kRtuResponse), kUnitDelayNs);
    QCOMPARE(FaultInjector::matches(*r, context), fires);
}

// Time-dependent firing: the chance by the interval since the previous request, interpolated.
void TestFaultInjector::byInterval()
{
    FaultRule r = rule(FaultRule::Kind::Drop);
    r.byIntervalMs = {{100, 1.0}, {200, 0.0}};
    QCOMPARE(r.probabilityAt(50), 1.0);
    QCOMPARE(r.probabilityAt(150), 0.5);
    QCOMPARE(r.probabilityAt(175), 0.25);
    QCOMPARE(r.probabilityAt(1000), 0.0);
    QCOMPARE(r.probabilityAt(-1), 0.0); // the first request: no interval, as after a long pause
    FaultInjector injector;
    injector.setRules(FaultRuleSet{11, {r}});
    FaultContext c = rtuContext();
    int fired = 0;
    constexpr int n = 2000;
    for (qint64 ms : {100, 90, 250, -1}) {
        c.intervalNs = ms < 0 ? -1 : ms * 1'000'000;
        const bool expected = ms >= 0 && ms <= 100;
        for (int i = 0; i < 20; ++i)
            QCOMPARE(injector.plan(c).drop, expected);
    }
    c.intervalNs = 150'000'000;
    for (int i = 0; i < n; ++i)
        fired += injector.plan(c).drop ? 1 : 0;
    const double sigma = std::sqrt(n * 0.25);
    QVERIFY2(std::abs(fired - n / 2) <= 4 * sigma, qPrintable(QStringLiteral("%1 of %2 at 150 ms").arg(fired).arg(n)));
}

// A turnaround time drawn per request: the rule fires when the interval is shorter.
void TestFaultInjector::turnaround()
{
    FaultRule r = rule(FaultRule::Kind::Drop);
    r.hasTurnaround = true;
    r.turnaround = DelaySpec::fixed(50);
    FaultInjector injector;
    injector.setRules(FaultRuleSet{5, {r}});
    FaultContext c = rtuContext();
    c.intervalNs = 40'000'000;
    QVERIFY(injector.plan(c).drop);
    c.intervalNs = 60'000'000;
    QVERIFY(!injector.plan(c).drop);
    c.intervalNs = -1;
    QVERIFY(!injector.plan(c).drop);
    // Exponential, mean 100 ms: at 100 ms the chance is e^-1.
    r.turnaround.kind = DelaySpec::Kind::Exponential;
    r.turnaround.meanMs = 100;
    r.turnaround.minMs = 0;
    r.turnaround.maxMs = -1;
    injector.setRules(FaultRuleSet{5, {r}});
    c.intervalNs = 100'000'000;
    constexpr int n = 4000;
    int fired = 0;
    for (int i = 0; i < n; ++i)
        fired += injector.plan(c).drop ? 1 : 0;
    const double p = std::exp(-1.0);
    QVERIFY2(std::abs(fired - n * p) <= 4 * std::sqrt(n * p * (1 - p)), qPrintable(QStringLiteral("%1 of %2").arg(fired).arg(n)));
    // Log-normal, mean 112 ms, standard deviation 132 ms, at most 330 ms (scada-rs485): at its
    // median, 112 / sqrt(1 + (132/112)^2) = 72.5 ms, half the requests are missed; from 330 ms on none.
    r.turnaround.kind = DelaySpec::Kind::LogNormal;
    r.turnaround.meanMs = 112;
    r.turnaround.stddevMs = 132;
    r.turnaround.maxMs = 330;
    injector.setRules(FaultRuleSet{5, {r}});
    c.intervalNs = std::llround(112e6 / std::sqrt(1 + (132.0 / 112) * (132.0 / 112)));
    fired = 0;
    for (int i = 0; i < n; ++i)
        fired += injector.plan(c).drop ? 1 : 0;
    QVERIFY2(std::abs(fired - n * 0.5) <= 4 * std::sqrt(n * 0.25), qPrintable(QStringLiteral("%1 of %2").arg(fired).arg(n)));
    c.intervalNs = 330'000'000;
    for (int i = 0; i < 1000; ++i)
        QVERIFY(!injector.plan(c).drop);
}

// Line noise: bits of the answer flipped as sent (an RTU CRC then fails), requests lost.
void TestFaultInjector::noise()
{
    FaultRule r = rule(FaultRule::Kind::Noise);
    r.name = QStringLiteral("hiss");
    r.noiseOn = FaultRule::NoiseOn::Answer;
    r.bitErrorRate = 0;
    FaultPlan plan = planWith(r, rtuContext());
    QCOMPARE(hexText(plan.chunks.at(0).bytes), QString::fromLatin1(kRtuResponse));
    QVERIFY(plan.faults.isEmpty()); // fired, changed nothing: not named
    r.bitErrorRate = 0.5;
    plan = planWith(r, rtuContext());
    const QByteArray sent = plan.chunks.at(0).bytes;
    QCOMPARE(sent.size(), hex(kRtuResponse).size());
    QVERIFY(sent != hex(kRtuResponse));
    QCOMPARE(plan.faults, QStringList{QStringLiteral("hiss")});
    const AduParts parts = AduBuilder::parse(sent, Framing::Rtu);
    QVERIFY(!parts.complete || !parts.checksumValid() || parts.pdu != AduBuilder::parse(hex(kRtuResponse), Framing::Rtu).pdu);
    // On requests: with half the bits flipped, every request is lost.
    r.noiseOn = FaultRule::NoiseOn::Request;
    for (int i = 0; i < 10; ++i)
        QVERIFY(planWith(r, rtuContext()).drop);
    // A rate of 1e-4 over the 64 bits of an 8-byte request loses about 0.64 % of them.
    r.bitErrorRate = 1e-4;
    FaultInjector injector;
    injector.setRules(FaultRuleSet{3, {r}});
    constexpr int n = 20000;
    int lost = 0;
    for (int i = 0; i < n; ++i)
        lost += injector.plan(rtuContext()).drop ? 1 : 0;
    const double p = 1 - std::pow(1 - 1e-4, 64);
    QVERIFY2(std::abs(lost - n * p) <= 4 * std::sqrt(n * p * (1 - p)), qPrintable(QStringLiteral("%1 of %2 lost").arg(lost).arg(n)));
}

void TestFaultInjector::dropProportion()
{
    for (const double p : {0.1, 0.5, 0.02}) {
        FaultRule r = rule(FaultRule::Kind::Drop);
        r.probability = p;
        FaultInjector injector;
        injector.setRules(FaultRuleSet{12345, {r}});
        const int n = 20000;
        int dropped = 0;
        for (int i = 0; i < n; ++i)
            dropped += injector.plan(tcpContext()).drop ? 1 : 0;
        const double observed = double(dropped) / n;
        QVERIFY2(std::fabs(observed - p) < 5 * std::sqrt(p * (1 - p) / n),
                 qPrintable(QStringLiteral("p %1, observed %2").arg(p).arg(observed)));
    }
}

void TestFaultInjector::delayDistributions_data()
{
    QTest::addColumn<DelaySpec>("spec");
    QTest::addColumn<double>("mean");   // expected mean, ms
    QTest::addColumn<double>("stddev"); // expected standard deviation, ms
    QTest::addColumn<double>("low");    // every sample within [low, high]
    QTest::addColumn<double>("high");
    DelaySpec fixed = DelaySpec::fixed(7.5);
    QTest::newRow("fixed 7.5") << fixed << 7.5 << 0.0 << 7.5 << 7.5;
    DelaySpec uniform;
    uniform.kind = DelaySpec::Kind::Uniform;
    uniform.minMs = 2;
    uniform.maxMs = 6;
    QTest::newRow("uniform 2-6") << uniform << 4.0 << 4 / std::sqrt(12.0) << 2.0 << 6.0;
    DelaySpec normal;
    normal.kind = DelaySpec::Kind::Normal;
    normal.meanMs = 50;
    normal.stddevMs = 5;
    QTest::newRow("normal 50, 5") << normal << 50.0 << 5.0 << 0.0 << 1e9;
    DelaySpec exponential;
    exponential.kind = DelaySpec::Kind::Exponential;
    exponential.meanMs = 20;
    QTest::newRow("exponential 20") << exponential << 20.0 << 20.0 << 0.0 << 1e9;
    DelaySpec logNormal;
    logNormal.kind = DelaySpec::Kind::LogNormal;
    logNormal.meanMs = 30;
    logNormal.stddevMs = 20;
    QTest::newRow("lognormal 30, 20") << logNormal << 30.0 << 20.0 << 0.0 << 1e9;
    logNormal.minMs = 10;
    logNormal.maxMs = 40;
    // Clamped to [10, 40]: ln X is normal with sigma^2 = ln(1 + (20/30)^2), mu = ln 30 - sigma^2 / 2;
    // the clamped moments from its partial moments (the mass below 10 at 10, above 40 at 40).
    QTest::newRow("lognormal 30, 20 clamped 10-40") << logNormal << 25.92 << 10.55 << 10.0 << 40.0;
}

// Delay rules observed as the plan's first chunk delay: mean and spread within bounds.
void TestFaultInjector::delayDistributions()
{
    QFETCH(DelaySpec, spec);
    QFETCH(double, mean);
    QFETCH(double, stddev);
    QFETCH(double, low);
    QFETCH(double, high);
    FaultRule r = rule(FaultRule::Kind::Delay);
    r.delay = spec;
    FaultInjector injector;
    injector.setRules(FaultRuleSet{99, {r}});
    const int n = 20000;
    double sum = 0;
    double sumSquares = 0;
    for (int i = 0; i < n; ++i) {
        const double ms = double(injector.plan(rtuContext()).chunks.at(0).delayNs) / 1e6;
        QVERIFY2(ms >= low - 1e-6 && ms <= high + 1e-6, qPrintable(QString::number(ms)));
        sum += ms;
        sumSquares += ms * ms;
    }
    const double m = sum / n;
    const double sd = std::sqrt(std::max(0.0, sumSquares / n - m * m));
    QVERIFY2(std::fabs(m - mean) <= 5 * stddev / std::sqrt(double(n)) + 1e-6,
             qPrintable(QStringLiteral("mean %1, expected %2").arg(m).arg(mean)));
    QVERIFY2(std::fabs(sd - stddev) <= 0.05 * stddev + 1e-6,
             qPrintable(QStringLiteral("stddev %1, expected %2").arg(sd).arg(stddev)));
}

// The unit's own response time (from the profile) when no delay rule fires; clamped to its bounds.
void TestFaultInjector::unitResponseDelay()
{
    DelaySpec normal;
    normal.kind = DelaySpec::Kind::Normal;
    normal.meanMs = 4;
    normal.stddevMs = 1.5;
    normal.minMs = 1;
    normal.maxMs = 12;
    FaultInjector injector;
    injector.setResponseDelay(1, normal);
    double sum = 0;
    const int n = 10000;
    for (int i = 0; i < n; ++i) {
        const FaultPlan plan = injector.plan(rtuContext());
        const double ms = double(plan.chunks.at(0).delayNs) / 1e6;
        QVERIFY(ms >= 1 && ms <= 12);
        sum += ms;
    }
    QVERIFY(std::fabs(sum / n - 4) < 5 * 1.5 / std::sqrt(double(n)) + 0.01);
    // Another unit keeps the context's fixed time.
    FaultContext other = rtuContext();
    other.unit = 2;
    QCOMPARE(injector.plan(other).chunks.at(0).delayNs, kUnitDelayNs);
    // A script's own delay stands over the unit's distribution, with rules and without (the
    // path without rules drew over it: {delay: 250} was answered at once).
    FaultContext scripted = rtuContext();
    scripted.responseDelayNs = 250'000'000;
    scripted.responseDelayFixed = true;
    QCOMPARE(injector.plan(scripted).chunks.at(0).delayNs, qint64(250'000'000));
    FaultRule never;
    never.kind = FaultRule::Kind::Drop;
    never.probability = 0.0;
    FaultRuleSet rules;
    rules.rules.append(never);
    injector.setRules(rules);
    QCOMPARE(injector.plan(scripted).chunks.at(0).delayNs, qint64(250'000'000));
    injector.setRules(FaultRuleSet());
    injector.clearResponseDelays();
    QCOMPARE(injector.plan(rtuContext()).chunks.at(0).delayNs, kUnitDelayNs);
}

// plan(SimExchange), which skips FaultContext when there is no rule, plans what
// plan(FaultContext::forExchange()) does: the same bytes, the same delays drawn from the same
// unit's stream, a script's delay kept; with a rule, the rule's plan.
void TestFaultInjector::planOfExchange_data()
{
    QTest::addColumn<int>("framing");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<int>("unitId");
    QTest::addColumn<int>("routedUnitId");
    QTest::addColumn<bool>("delimited");
    QTest::addColumn<bool>("delayFixed");
    QTest::addColumn<bool>("withRule");
    const QByteArray mbap1 = AduBuilder::mbap(QByteArray::fromHex("0300000001"), 1, 7);
    const QByteArray mbap0 = AduBuilder::mbap(QByteArray::fromHex("0300000001"), 0, 8);
    const QByteArray mbap2 = AduBuilder::mbap(QByteArray::fromHex("0300000001"), 2, 9);
    const QByteArray rtu1 = AduBuilder::rtu(QByteArray::fromHex("0300000001"), 1);
    QTest::newRow("mbap unit 1: its distribution") << int(Framing::Tcp) << mbap1 << 1 << 1 << false << false << false;
    QTest::newRow("mbap unit 2: no distribution") << int(Framing::Tcp) << mbap2 << 2 << 2 << false << false << false;
    QTest::newRow("mbap unit 0 routed to 1: unit 1's stream") << int(Framing::Tcp) << mbap0 << 0 << 1 << false << false << false;
    QTest::newRow("rtu unit 1") << int(Framing::Rtu) << rtu1 << 1 << 1 << false << false << false;
    QTest::newRow("a script's fixed delay") << int(Framing::Tcp) << mbap1 << 1 << 1 << false << true << false;
    QTest::newRow("delimited frame: the answering unit's") << int(Framing::Rtu) << QByteArray("PING\r") << 0 << 1 << true << false
                                                                 << false;
    QTest::newRow("with a rule") << int(Framing::Tcp) << mbap1 << 1 << 1 << false << false << true;
}

void TestFaultInjector::planOfExchange()
{
    QFETCH(int, framing);
    QFETCH(QByteArray, request);
    QFETCH(int, unitId);
    QFETCH(int, routedUnitId);
    QFETCH(bool, delimited);
    QFETCH(bool, delayFixed);
    QFETCH(bool, withRule);
    DelaySpec normal;
    normal.kind = DelaySpec::Kind::Normal;
    normal.meanMs = 4;
    normal.stddevMs = 1.5;
    FaultInjector byExchange;
    FaultInjector byContext;
    for (FaultInjector *injector : {&byExchange, &byContext}) {
        injector->setResponseDelay(1, normal);
        if (withRule) {
            FaultRule r = rule(FaultRule::Kind::Delay);
            r.probability = 0.5;
            r.delay = DelaySpec::fixed(30);
            FaultRuleSet rules;
            rules.rules.append(r);
            injector->setRules(rules);
        }
    }
    SimExchange exchange;
    exchange.framing = Framing(framing);
    exchange.unitId = quint8(unitId);
    exchange.routedUnitId = quint8(routedUnitId);
    exchange.delimited = delimited;
    exchange.requestAdu = request;
    exchange.responseAdu = request; // an echo: the bytes only have to come back unchanged
    exchange.responseDelayNs = 2'000'000;
    exchange.responseDelayFixed = delayFixed;
    for (int i = 0; i < 20; ++i) {
        const FaultPlan a = byExchange.plan(exchange);
        const FaultPlan b = byContext.plan(FaultContext::forExchange(exchange));
        QCOMPARE(a.chunks.size(), b.chunks.size());
        for (qsizetype c = 0; c < a.chunks.size(); ++c) {
            QCOMPARE(a.chunks.at(c).bytes, b.chunks.at(c).bytes);
            QCOMPARE(a.chunks.at(c).delayNs, b.chunks.at(c).delayNs);
        }
        QCOMPARE(a.faults, b.faults);
        QCOMPARE(a.drop, b.drop);
    }
}

// The same rules, seed and requests give the same plans; a rule that never matches does not
// shift the draws of the others; setRules restarts the streams.
void TestFaultInjector::reproducible()
{
    FaultRule drop = rule(FaultRule::Kind::Drop);
    drop.probability = 0.3;
    FaultRule delay = rule(FaultRule::Kind::Delay);
    delay.delay.kind = DelaySpec::Kind::Exponential;
    delay.delay.meanMs = 10;
    FaultRule never = rule(FaultRule::Kind::Drop);
    never.units = {99};
    never.probability = 0.5;
    auto trace = [](FaultInjector &injector) {
        QList<qint64> out;
        for (int i = 0; i < 500; ++i) {
            const FaultPlan plan = injector.plan(rtuContext());
            out.append(plan.drop ? -1 : plan.chunks.at(0).delayNs);
        }
        return out;
    };
    FaultInjector a;
    a.setRules(FaultRuleSet{2026, {drop, delay}});
    FaultInjector b;
    b.setRules(FaultRuleSet{2026, {drop, delay}});
    const QList<qint64> first = trace(a);
    QCOMPARE(trace(b), first);
    QVERIFY(first.contains(-1) && first.count(-1) < 500);
    FaultInjector c;
    c.setRules(FaultRuleSet{2026, {drop, delay, never}});
    QCOMPARE(trace(c), first);
    a.setRules(FaultRuleSet{2026, {drop, delay}});
    QCOMPARE(trace(a), first);
    FaultInjector d;
    d.setRules(FaultRuleSet{2027, {drop, delay}});
    QVERIFY(trace(d) != first);
}

void TestFaultInjector::setRulesWhileRunning()
{
    FaultInjector injector;
    verifySingle(injector.plan(tcpContext()), hex(kTcpResponse));
    injector.setRules(FaultRuleSet{1, {rule(FaultRule::Kind::Drop)}});
    QVERIFY(injector.plan(tcpContext()).drop);
    QCOMPARE(injector.rules().rules.size(), 1);
    injector.setRules(FaultRuleSet{});
    verifySingle(injector.plan(tcpContext()), hex(kTcpResponse));
}

// plan() in one thread while another replaces the rules: each plan sees one rule set whole.
void TestFaultInjector::setRulesFromAnotherThread()
{
    FaultInjector injector;
    const FaultRuleSet one{1, {rule(FaultRule::Kind::Drop)}};
    FaultRule duplicate = rule(FaultRule::Kind::Duplicate);
    const FaultRuleSet three{2, {rule(FaultRule::Kind::WrongUnit), duplicate, rule(FaultRule::Kind::WrongChecksum)}};
    std::atomic<bool> done = false;
    QThread *writer = QThread::create([&] {
        for (int i = 0; !done; ++i)
            injector.setRules(i % 2 ? one : three);
    });
    writer->start();
    for (int i = 0; i < 20000; ++i) {
        const FaultPlan plan = injector.plan(rtuContext());
        QVERIFY(plan.drop || plan.chunks.size() == 2 || plan.chunks.size() == 1);
    }
    done = true;
    writer->wait();
    delete writer;
}

QTEST_GUILESS_MAIN(TestFaultInjector)
#include "tst_faultinjector.moc"
