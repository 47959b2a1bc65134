#pragma once

// Frames, helpers and data rows for tst_faultinjector (CRC-16/MODBUS and LRC values computed by an
// independent script).

#include "protocol/hextext.h"
#include "sim/faultinjector.h"

#include <QtTest/QtTest>

Q_DECLARE_METATYPE(mbscope::FaultRule)
Q_DECLARE_METATYPE(mbscope::DelaySpec)

namespace mbscope {

namespace {

QByteArray hex(const char *text)
{
    const HexTextResult r = HexText::parse(QString::fromLatin1(text));
    if (!r.ok)
        qFatal("bad hex in test data: %s", text);
    return r.bytes;
}

QString hexText(const QByteArray &bytes)
{
    return HexText::format(bytes);
}

// The answers the rules work on (CRC-16/MODBUS and LRC computed by an independent script):
// RTU  01 03 00 79 00 02 15 D2 -> 01 03 04 04 1A 00 00 DA C4  (two registers from 0x0079)
// TCP  tid 5, unit 1, 03 from 0 x2 -> 00 0A 00 0B
// ASCII :010304000A000BE3 CR LF
const char kRtuRequest[] = "01 03 00 79 00 02 15 D2";
const char kRtuResponse[] = "01 03 04 04 1A 00 00 DA C4";
const char kTcpRequest[] = "00 05 00 00 00 06 01 03 00 00 00 02";
const char kTcpResponse[] = "00 05 00 00 00 07 01 03 04 00 0A 00 0B";
const QByteArray kAsciiRequest = QByteArrayLiteral(":010300000002FA\r\n");
const QByteArray kAsciiResponse = QByteArrayLiteral(":010304000A000BE3\r\n");

constexpr qint64 kUnitDelayNs = 3000000;

FaultContext rtuContext()
{
    return FaultContext::forRequest(Framing::Rtu, hex(kRtuRequest), hex(kRtuResponse), kUnitDelayNs);
}

FaultContext tcpContext()
{
    return FaultContext::forRequest(Framing::Tcp, hex(kTcpRequest), hex(kTcpResponse), kUnitDelayNs);
}

[[maybe_unused]] FaultContext asciiContext()
{
    return FaultContext::forRequest(Framing::Ascii, kAsciiRequest, kAsciiResponse, kUnitDelayNs);
}

FaultRule rule(FaultRule::Kind kind)
{
    FaultRule r;
    r.kind = kind;
    return r;
}

FaultPlan planWith(const FaultRule &r, const FaultContext &context, quint64 seed = 1)
{
    FaultInjector injector;
    injector.setRules(FaultRuleSet{seed, {r}});
    return injector.plan(context);
}

// One chunk with the whole answer after the unit's response time.
void verifySingle(const FaultPlan &plan, const QByteArray &bytes, qint64 delayNs = kUnitDelayNs)
{
    QVERIFY(!plan.drop);
    QVERIFY(!plan.closeBefore);
    QVERIFY(!plan.closeAfter);
    QCOMPARE(plan.chunks.size(), 1);
    QCOMPARE(hexText(plan.chunks.at(0).bytes), hexText(bytes));
    QCOMPARE(plan.chunks.at(0).delayNs, delayNs);
}

} // namespace

namespace faultcases {

// Requests and the context read from them: unit, function, addresses.
inline void addContextRows()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<int>("unit");
    QTest::addColumn<int>("function");
    QTest::addColumn<int>("first");
    QTest::addColumn<int>("last");
    auto row = [](const char *frame, int unit, int function, int first, int last) {
        QTest::newRow(frame) << hex(frame) << unit << function << first << last;
    };
    row("01 03 00 79 00 16 15 DD", 1, 0x03, 0x79, 0x79 + 21);
    row("07 04 01 2C 00 03 70 58", 7, 0x04, 300, 302);
    row("01 01 FF FF 00 10 00 00", 1, 0x01, 0xFFFF, 0xFFFF); // clamped at the last address
    row("02 06 00 0A 01 02 00 00", 2, 0x06, 10, 10);
    row("01 05 00 07 FF 00 00 00", 1, 0x05, 7, 7);
    row("01 0F 00 13 00 0A 02 CD 01 00 00", 1, 0x0F, 0x13, 0x13 + 9);
    row("01 10 00 01 00 02 04 00 0A 01 02 00 00", 1, 0x10, 1, 2);
    row("01 16 00 04 00 F2 00 25 00 00", 1, 0x16, 4, 4);
    // 17: read 3 from 4, write 3 from 14 -> 4..16
    row("01 17 00 04 00 03 00 0E 00 03 06 00 FF 00 FF 00 FF 00 00", 1, 0x17, 4, 16);
    row("01 18 04 DE 00 00", 1, 0x18, 0x04DE, 0x04DE);
    row("01 11 00 00", 1, 0x11, -1, -1);
    row("01 2B 0E 01 00 00 00", 1, 0x2B, -1, -1);
}

// Each fault's exact bytes per framing.
inline void addExactByteRows()
{
    QTest::addColumn<int>("framing");
    QTest::addColumn<FaultRule>("faultRule");
    QTest::addColumn<QByteArray>("expected");
    using K = FaultRule::Kind;
    auto row = [](const char *name, Framing framing, FaultRule r, const QByteArray &expected) {
        QTest::newRow(name) << int(framing) << r << expected;
    };
    FaultRule r = rule(K::WrongChecksum);
    row("01 03 04 04 1A 00 00 25 3B rtu wrong CRC (DA C4 inverted)", Framing::Rtu, r, hex("01 03 04 04 1A 00 00 25 3B"));
    row(":010304000A000B1C ascii wrong LRC (E3 inverted)", Framing::Ascii, r, QByteArrayLiteral(":010304000A000B1C\r\n"));
    r = rule(K::WrongTransactionId);
    row("00 06 ... tcp tid + 1", Framing::Tcp, r, hex("00 06 00 00 00 07 01 03 04 00 0A 00 0B"));
    r.delta = 0xFFFF;
    row("00 04 ... tcp tid - 1 (delta FFFF)", Framing::Tcp, r, hex("00 04 00 00 00 07 01 03 04 00 0A 00 0B"));
    r = rule(K::WrongUnit);
    row("02 03 04 04 1A 00 00 E9 C4 rtu unit + 1, CRC recomputed", Framing::Rtu, r, hex("02 03 04 04 1A 00 00 E9 C4"));
    r.delta = 255;
    row("00 03 04 04 1A 00 00 CA 04 rtu unit - 1", Framing::Rtu, r, hex("00 03 04 04 1A 00 00 CA 04"));
    row("00 05 00 00 00 07 00 03 ... tcp unit - 1", Framing::Tcp, r, hex("00 05 00 00 00 07 00 03 04 00 0A 00 0B"));
    r = rule(K::Exception);
    row("01 83 04 40 F3 rtu exception 04", Framing::Rtu, r, hex("01 83 04 40 F3"));
    row("00 05 00 00 00 03 01 83 04 tcp exception 04 (MBAP length 3)", Framing::Tcp, r, hex("00 05 00 00 00 03 01 83 04"));
    row(":01830478 ascii exception 04", Framing::Ascii, r, QByteArrayLiteral(":01830478\r\n"));
    r.exceptionCode = 2;
    row("01 83 02 C0 F1 rtu exception 02", Framing::Rtu, r, hex("01 83 02 C0 F1"));
    r = rule(K::FewerRegisters);
    row("01 03 02 04 1A 3B 4F rtu one register fewer", Framing::Rtu, r, hex("01 03 02 04 1A 3B 4F"));
    row("00 05 00 00 00 05 01 03 02 00 0A tcp one fewer (MBAP length 5)", Framing::Tcp, r, hex("00 05 00 00 00 05 01 03 02 00 0A"));
    row(":010302000AF0 ascii one fewer", Framing::Ascii, r, QByteArrayLiteral(":010302000AF0\r\n"));
    r.fewer = 5;
    row("01 03 00 20 F0 rtu five fewer of two: none left", Framing::Rtu, r, hex("01 03 00 20 F0"));
}

} // namespace faultcases

} // namespace mbscope
