#include "protocol/registervalue.h"

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

#include <cmath>
#include <limits>

using namespace mbscope;

namespace {

// "42F6 E979" -> {0x42F6, 0xE979}
QList<quint16> words(const QString &text)
{
    QList<quint16> out;
    for (const QString &w : text.split(QLatin1Char(' '), Qt::SkipEmptyParts))
        out.append(quint16(w.toUInt(nullptr, 16)));
    return out;
}

QString wordsText(const QList<quint16> &regs)
{
    QStringList parts;
    for (quint16 r : regs)
        parts.append(QString::number(r, 16).toUpper().rightJustified(4, QLatin1Char('0')));
    return parts.join(QLatin1Char(' '));
}

RegisterFormat format(const QString &name)
{
    const RegisterFormatResult result = RegisterFormat::parse(name);
    if (!result.ok)
        qFatal("bad format name in test data: %s", qPrintable(result.error));
    return result.format;
}

std::span<const quint16> span(const QList<quint16> &list)
{
    return std::span<const quint16>(list.constData(), size_t(list.size()));
}

} // namespace

// Vectors: float 123.456 = 0x42F6E979 and u32 0x12345678 in the four orders as tool vendors
// publish them (Modbus Poll, Simply Modbus "word/byte swap" tables); IEEE 754 bit patterns for the
// special values; register pairs from the RosRao and tutorial responses in tests/data.
class TestRegisterValue : public QObject
{
    Q_OBJECT
private slots:
    void vectors_data()
    {
        QTest::addColumn<QString>("registers");
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("encodes"); // fromText(text) gives these registers back
        auto row = [](const char *regs, const char *fmt, const QString &text, bool encodes = true) {
            QTest::addRow("%s %s", regs, fmt) << QString::fromLatin1(regs) << QString::fromLatin1(fmt) << text << encodes;
        };
        // float 123.456 in the four orders
        row("42F6 E979", "f32-abcd", QStringLiteral("123.456"));
        row("E979 42F6", "f32-cdab", QStringLiteral("123.456"));
        row("F642 79E9", "f32-badc", QStringLiteral("123.456"));
        row("79E9 F642", "f32-dcba", QStringLiteral("123.456"));
        // u32 and i32 0x12345678 in the four orders
        row("1234 5678", "u32-abcd", QStringLiteral("305419896"));
        row("5678 1234", "u32-cdab", QStringLiteral("305419896"));
        row("3412 7856", "u32-badc", QStringLiteral("305419896"));
        row("7856 3412", "u32-dcba", QStringLiteral("305419896"));
        row("1234 5678", "i32-abcd", QStringLiteral("305419896"));
        row("7856 3412", "i32-dcba", QStringLiteral("305419896"));
        row("FFFF FFFE", "i32-abcd", QStringLiteral("-2"));
        row("FFFE FFFF", "i32-cdab", QStringLiteral("-2"));
        row("FEFF FFFF", "i32-dcba", QStringLiteral("-2"));
        row("8000 0000", "i32-abcd", QStringLiteral("-2147483648"));
        row("FFFF FFFF", "u32-abcd", QStringLiteral("4294967295"));
        // 16-bit
        row("FFFF", "i16", QStringLiteral("-1"));
        row("FFFF", "u16", QStringLiteral("65535"));
        row("0000", "u16", QStringLiteral("0"));
        row("0000", "i16", QStringLiteral("0"));
        row("0009", "u16", QStringLiteral("9"));
        row("000A", "u16", QStringLiteral("10"));
        row("8000", "i16", QStringLiteral("-32768"));
        row("7FFF", "i16", QStringLiteral("32767"));
        row("FFFE", "i16-ba", QStringLiteral("-257"));
        row("0100", "u16-ba", QStringLiteral("1"));
        row("03E8", "u16", QStringLiteral("1000"));
        row("002A", "hex", QStringLiteral("0x002A"));
        row("2A00", "hex-ba", QStringLiteral("0x002A"));
        row("FFFF", "hex", QStringLiteral("0xFFFF"));
        row("0001", "bin", QStringLiteral("0b0000_0000_0000_0001"));
        row("A5F0", "bin", QStringLiteral("0b1010_0101_1111_0000"));
        row("0100", "bin-ba", QStringLiteral("0b0000_0000_0000_0001"));
        // ASCII
        row("4142", "ascii", QStringLiteral("AB"));
        row("4241", "ascii-ba", QStringLiteral("AB"));
        row("4100", "ascii", QStringLiteral("A\\x00"));
        row("2020", "ascii", QStringLiteral("  "));
        row("5C0A", "ascii", QStringLiteral("\\\\\\x0A"));
        row("7F80", "ascii", QStringLiteral("\\x7F\\x80"));
        row("0045", "ascii", QStringLiteral("\\x00E"));    // arduino response register 69
        row("0045", "ascii-ba", QStringLiteral("E\\x00"));
        // float32 special values
        row("3F80 0000", "f32-abcd", QStringLiteral("1"));
        row("C020 0000", "f32-abcd", QStringLiteral("-2.5"));
        row("0000 0000", "f32-abcd", QStringLiteral("0"));
        row("8000 0000", "f32-abcd", QStringLiteral("-0"));
        row("4049 0FDB", "f32-abcd", QStringLiteral("3.1415927"));
        row("3DCC CCCD", "f32-abcd", QStringLiteral("0.1"));
        row("7F7F FFFF", "f32-abcd", QStringLiteral("3.4028235e+38"));
        row("0000 0001", "f32-abcd", QStringLiteral("1e-45"));
        row("7F80 0000", "f32-abcd", QStringLiteral("Inf"));
        row("FF80 0000", "f32-abcd", QStringLiteral("-Inf"));
        row("0000 FF80", "f32-cdab", QStringLiteral("-Inf"));
        row("7FC0 0000", "f32-abcd", QStringLiteral("NaN"));
        row("C07F 0000", "f32-badc", QStringLiteral("NaN"));
        row("7FC0 0001", "f32-abcd", QStringLiteral("NaN"), false); // payload: shown as NaN, kept in bits
        row("FFC0 0000", "f32-abcd", QStringLiteral("NaN"), false); // negative NaN
        row("7F80 0001", "f32-abcd", QStringLiteral("NaN"), false); // signalling NaN
        // float64
        row("405E DD2F 1A9F BE77", "f64-abcdefgh", QStringLiteral("123.456"));
        row("BE77 1A9F DD2F 405E", "f64-ghefcdab", QStringLiteral("123.456"));
        row("5E40 2FDD 9F1A 77BE", "f64-badcfehg", QStringLiteral("123.456"));
        row("77BE 9F1A 2FDD 5E40", "f64-hgfedcba", QStringLiteral("123.456"));
        row("3FF0 0000 0000 0000", "f64-abcdefgh", QStringLiteral("1"));
        row("4009 21FB 5444 2D18", "f64-abcdefgh", QStringLiteral("3.141592653589793"));
        row("0000 0000 0000 0001", "f64-abcdefgh", QStringLiteral("5e-324"));
        row("7FEF FFFF FFFF FFFF", "f64-abcdefgh", QStringLiteral("1.7976931348623157e+308"));
        row("7FF0 0000 0000 0000", "f64-abcdefgh", QStringLiteral("Inf"));
        row("FFF0 0000 0000 0000", "f64-abcdefgh", QStringLiteral("-Inf"));
        row("7FF8 0000 0000 0000", "f64-abcdefgh", QStringLiteral("NaN"));
        row("0000 0000 0000 F87F", "f64-hgfedcba", QStringLiteral("NaN"));
        row("7FF0 0000 0000 0001", "f64-abcdefgh", QStringLiteral("NaN"), false);
        // 64-bit integers
        row("0102 0304 0506 0708", "u64-abcdefgh", QStringLiteral("72623859790382856"));
        row("0708 0506 0304 0102", "u64-ghefcdab", QStringLiteral("72623859790382856"));
        row("0201 0403 0605 0807", "u64-badcfehg", QStringLiteral("72623859790382856"));
        row("0807 0605 0403 0201", "u64-hgfedcba", QStringLiteral("72623859790382856"));
        row("FFFF FFFF FFFF FFFF", "u64-abcdefgh", QStringLiteral("18446744073709551615"));
        row("FFFF FFFF FFFF FFFF", "i64-abcdefgh", QStringLiteral("-1"));
        row("8000 0000 0000 0000", "i64-abcdefgh", QStringLiteral("-9223372036854775808"));
        row("7FFF FFFF FFFF FFFF", "i64-abcdefgh", QStringLiteral("9223372036854775807"));
        row("0000 0000 0000 0000", "i64-abcdefgh", QStringLiteral("0"));
        row("0000 0000 0000 0080", "i64-hgfedcba", QStringLiteral("-9223372036854775808"));
        row("FFFE FFFF FFFF FFFF", "i64-ghefcdab", QStringLiteral("-2"));
        // Register pairs from published responses
        row("041A 0000", "u32-abcd", QStringLiteral("68812800")); // rosrao registers 0-1
        row("041A 0000", "u32-cdab", QStringLiteral("1050"));
        row("03E8 01F4", "u32-abcd", QStringLiteral("65536500")); // tutorial input registers 300-301
        row("03E8 01F4", "u32-cdab", QStringLiteral("32769000")); // 500 * 65536 + 1000
    }
    void vectors()
    {
        QFETCH(QString, registers);
        QFETCH(QString, format);
        QFETCH(QString, text);
        QFETCH(bool, encodes);
        const RegisterFormat fmt = ::format(format);
        const QList<quint16> regs = words(registers);
        QCOMPARE(regs.size(), fmt.registerCount());

        const RegisterValueResult decoded = RegisterValue::fromRegisters(span(regs), fmt);
        QVERIFY2(decoded.ok, qPrintable(decoded.error));
        QCOMPARE(decoded.value.toText(), text);
        QCOMPARE(decoded.value.registers(), regs); // bits kept, even a NaN's payload

        if (encodes) {
            const RegisterValueResult encoded = RegisterValue::fromText(text, fmt);
            QVERIFY2(encoded.ok, qPrintable(encoded.error));
            QCOMPARE(wordsText(encoded.value.registers()), registers);
        }
    }

    void numbers()
    {
        const auto f32 = RegisterValue::fromRegisters(span(words(QStringLiteral("42F6 E979"))), format(QStringLiteral("f32")));
        QCOMPARE(f32.value.toDouble(), double(123.456f));
        QCOMPARE(f32.value.bits(), quint64(0x42F6E979));
        const auto cdab = RegisterValue::fromRegisters(span(words(QStringLiteral("E979 42F6"))), format(QStringLiteral("f32-cdab")));
        QCOMPARE(cdab.value.bits(), quint64(0x42F6E979)); // bits() is independent of the order
        const auto i16 = RegisterValue::fromRegisters(span(words(QStringLiteral("FFFF"))), format(QStringLiteral("i16")));
        QCOMPARE(i16.value.toInt64(), qint64(-1));
        QCOMPARE(i16.value.toDouble(), -1.0);
        const auto u16 = RegisterValue::fromRegisters(span(words(QStringLiteral("FFFF"))), format(QStringLiteral("u16")));
        QCOMPARE(u16.value.toInt64(), qint64(65535));
        const auto u64 = RegisterValue::fromRegisters(span(words(QStringLiteral("FFFF FFFF FFFF FFFF"))), format(QStringLiteral("u64")));
        QCOMPARE(u64.value.toInt64(), qint64(-1)); // documented wrap above 2^63
        QCOMPARE(u64.value.toDouble(), 18446744073709551615.0);
        const auto nan = RegisterValue::fromRegisters(span(words(QStringLiteral("7FC0 0000"))), format(QStringLiteral("f32")));
        QVERIFY(nan.value.isNaN());
        QVERIFY(std::isnan(nan.value.toDouble()));
        QVERIFY(!u16.value.isNaN());
        const auto inf = RegisterValue::fromRegisters(span(words(QStringLiteral("FFF0 0000 0000 0000"))), format(QStringLiteral("f64")));
        QCOMPARE(inf.value.toDouble(), -std::numeric_limits<double>::infinity());
    }

    void tooFewRegisters()
    {
        const QList<quint16> one = {0x42F6};
        const RegisterValueResult result = RegisterValue::fromRegisters(span(one), format(QStringLiteral("f32-cdab")));
        QVERIFY(!result.ok);
        QCOMPARE(result.error, QStringLiteral("f32-cdab needs 2 registers, 1 given"));
        const RegisterValueResult none = RegisterValue::fromRegisters({}, format(QStringLiteral("u16")));
        QVERIFY(!none.ok);
        QCOMPARE(none.error, QStringLiteral("u16 needs 1 register, 0 given"));
    }

    void extraRegistersAreIgnored()
    {
        const QList<quint16> three = {0x0001, 0x0002, 0x0003};
        const RegisterValueResult result = RegisterValue::fromRegisters(span(three), format(QStringLiteral("u32")));
        QVERIFY(result.ok);
        QCOMPARE(result.value.bits(), quint64(0x00010002));
    }

    void textAccepted_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("registers");
        auto row = [](const QString &text, const char *fmt, const char *regs) {
            QTest::addRow("'%s' %s", qPrintable(text), fmt) << text << QString::fromLatin1(fmt) << QString::fromLatin1(regs);
        };
        row(QStringLiteral("-0"), "u16", "0000");
        row(QStringLiteral("+5"), "u16", "0005");
        row(QStringLiteral(" 42 "), "u16", "002A");
        row(QStringLiteral("0042"), "u16", "002A");
        row(QStringLiteral("0xFFFF"), "i16", "FFFF");
        row(QStringLiteral("0b1111_1111_1111_1111"), "i16", "FFFF");
        row(QStringLiteral("0x0102"), "u16-ba", "0201");
        row(QStringLiteral("0x2A"), "hex", "002A");
        row(QStringLiteral("2a"), "hex", "002A");
        row(QStringLiteral("002A"), "hex-ba", "2A00");
        row(QStringLiteral("0x00_2A"), "hex", "002A");
        row(QStringLiteral("101010"), "bin", "002A");
        row(QStringLiteral("0b0000_0000_0010_1010"), "bin", "002A");
        row(QStringLiteral("-1"), "i32-cdab", "FFFF FFFF");
        row(QStringLiteral("-2"), "i32-cdab", "FFFE FFFF");
        row(QStringLiteral("0x12345678"), "u32-badc", "3412 7856");
        row(QStringLiteral("0xFFFFFFFF"), "i32", "FFFF FFFF");
        row(QStringLiteral("1.5e3"), "f32", "44BB 8000");
        row(QStringLiteral("1.5E3"), "f32", "44BB 8000");
        row(QStringLiteral(".5"), "f32", "3F00 0000");
        row(QStringLiteral("+2.5"), "f32", "4020 0000");
        row(QStringLiteral("-2.5"), "f32", "C020 0000");
        row(QStringLiteral("3"), "f32", "4040 0000");
        row(QStringLiteral("+inf"), "f32", "7F80 0000");
        row(QStringLiteral("-Infinity"), "f32", "FF80 0000");
        row(QStringLiteral("nan"), "f32-cdab", "0000 7FC0");
        row(QStringLiteral("NaN"), "f64", "7FF8 0000 0000 0000");
        row(QStringLiteral("3.4028235e38"), "f32", "7F7F FFFF");
        row(QStringLiteral("1e-45"), "f32", "0000 0001");
        row(QStringLiteral("123.456"), "f64-ghefcdab", "BE77 1A9F DD2F 405E");
        row(QStringLiteral("123.456"), "f64-cdab", "BE77 1A9F DD2F 405E");
        row(QStringLiteral("A"), "ascii", "4100");
        row(QStringLiteral(" "), "ascii", "2000");
        row(QStringLiteral("\\x00\\x01"), "ascii", "0001");
        row(QStringLiteral("\\\\"), "ascii", "5C00");
        row(QStringLiteral("OK"), "ascii-ba", "4B4F");
        row(QStringLiteral("-9223372036854775808"), "i64", "8000 0000 0000 0000");
        row(QStringLiteral("9223372036854775807"), "i64", "7FFF FFFF FFFF FFFF");
        row(QStringLiteral("18446744073709551615"), "u64", "FFFF FFFF FFFF FFFF");
        row(QStringLiteral("0x0102030405060708"), "u64-dcba", "0807 0605 0403 0201");
    }
    void textAccepted()
    {
        QFETCH(QString, text);
        QFETCH(QString, format);
        QFETCH(QString, registers);
        const RegisterValueResult result = RegisterValue::fromText(text, ::format(format));
        QVERIFY2(result.ok, qPrintable(result.error));
        QCOMPARE(wordsText(result.value.registers()), registers);
    }

    void textRejected_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("fragment");
        auto row = [](const QString &text, const char *fmt, const QString &fragment) {
            QTest::addRow("'%s' %s", qPrintable(text), fmt) << text << QString::fromLatin1(fmt) << fragment;
        };
        row(QStringLiteral("70000"), "u16", QStringLiteral("'70000' is out of range for u16 (0 to 65535)"));
        row(QStringLiteral("65536"), "u16", QStringLiteral("out of range for u16"));
        row(QStringLiteral("-1"), "u16", QStringLiteral("'-1' is out of range for u16 (0 to 65535)"));
        row(QStringLiteral("32768"), "i16", QStringLiteral("'32768' is out of range for i16 (-32768 to 32767)"));
        row(QStringLiteral("-32769"), "i16", QStringLiteral("out of range for i16"));
        row(QStringLiteral("4294967296"), "u32", QStringLiteral("out of range for u32 (0 to 4294967295)"));
        row(QStringLiteral("-1"), "u32", QStringLiteral("out of range for u32"));
        row(QStringLiteral("-2147483649"), "i32", QStringLiteral("out of range for i32 (-2147483648 to 2147483647)"));
        row(QStringLiteral("18446744073709551616"), "u64", QStringLiteral("out of range for u64 (0 to 18446744073709551615)"));
        row(QStringLiteral("99999999999999999999999"), "u64", QStringLiteral("out of range for u64"));
        row(QStringLiteral("9223372036854775808"), "i64",
            QStringLiteral("out of range for i64 (-9223372036854775808 to 9223372036854775807)"));
        row(QStringLiteral("-9223372036854775809"), "i64", QStringLiteral("out of range for i64"));
        row(QStringLiteral("12a"), "u16", QStringLiteral("'12a' is not a whole number: u16 takes decimal digits"));
        row(QStringLiteral("1.5"), "u16", QStringLiteral("is not a whole number"));
        row(QStringLiteral("--5"), "i16", QStringLiteral("is not a whole number"));
        row(QStringLiteral("0x"), "u16", QStringLiteral("is not a whole number"));
        row(QString(), "u16", QStringLiteral("no value given for u16"));
        row(QStringLiteral("   "), "i32", QStringLiteral("no value given for i32"));
        row(QStringLiteral("0x10000"), "u16", QStringLiteral("'0x10000' does not fit in the 16 bits of u16"));
        row(QStringLiteral("0x1FFFFFFFF"), "i32", QStringLiteral("does not fit in the 32 bits of i32"));
        row(QStringLiteral("0x1_0000_0000_0000_0000"), "u64", QStringLiteral("does not fit in the 64 bits of u64"));
        row(QStringLiteral("0xG"), "u16", QStringLiteral("'0xG': 'G' is not a hex digit"));
        row(QStringLiteral("0b102"), "u16", QStringLiteral("'2' is not a binary digit"));
        row(QStringLiteral("12G"), "hex", QStringLiteral("'G' is not a hex digit"));
        row(QStringLiteral("0x"), "hex", QStringLiteral("'0x' has no digits"));
        row(QStringLiteral("0x1FFFF"), "hex", QStringLiteral("does not fit in the 16 bits of hex"));
        row(QStringLiteral("2"), "bin", QStringLiteral("'2' is not a binary digit"));
        row(QStringLiteral("1_0000_0000_0000_0000"), "bin", QStringLiteral("does not fit in the 16 bits of bin"));
        row(QStringLiteral("1e39"), "f32", QStringLiteral("'1e39' is out of range for f32 (the largest finite value is 3.4028235e+38)"));
        row(QStringLiteral("3.4028236e38"), "f32", QStringLiteral("out of range for f32"));
        row(QStringLiteral("-1e39"), "f32-cdab", QStringLiteral("out of range for f32"));
        row(QStringLiteral("1e-50"), "f32", QStringLiteral("'1e-50' is too small for f32: it would round to 0 (the smallest nonzero value is 1e-45)"));
        row(QStringLiteral("7e-46"), "f32", QStringLiteral("too small for f32"));
        row(QStringLiteral("1e400"), "f64", QStringLiteral("out of range for f64 (the largest finite value is 1.7976931348623157e+308)"));
        row(QStringLiteral("1e-400"), "f64", QStringLiteral("too small for f64: it would round to 0 (the smallest nonzero value is 5e-324)"));
        row(QStringLiteral("1e99999"), "f64", QStringLiteral("out of range for f64"));
        row(QStringLiteral("1e-99999"), "f64", QStringLiteral("too small for f64"));
        row(QStringLiteral("abc"), "f32", QStringLiteral("'abc' is not a number: f32 takes decimal or scientific notation"));
        row(QStringLiteral("--5"), "f32", QStringLiteral("is not a number"));
        row(QStringLiteral("+-5"), "f64", QStringLiteral("is not a number"));
        row(QStringLiteral("1,5"), "f32", QStringLiteral("is not a number"));
        row(QStringLiteral("0x42F6E979"), "f32", QStringLiteral("is not a number"));
        row(QStringLiteral("1e"), "f32", QStringLiteral("is not a number"));
        row(QStringLiteral("."), "f64", QStringLiteral("is not a number"));
        row(QStringLiteral("infinit"), "f64", QStringLiteral("is not a number"));
        row(QStringLiteral("ABC"), "ascii", QStringLiteral("'ABC' is 3 characters; one register holds one or two"));
        row(QString(), "ascii", QStringLiteral("is 0 characters"));
        row(QStringLiteral("\u00E9"), "ascii", QStringLiteral("character 1 (U+00E9) is not ASCII"));
        row(QStringLiteral("\\q"), "ascii", QStringLiteral("the backslash at character 1 starts no escape"));
        row(QStringLiteral("A\\x4"), "ascii", QStringLiteral("the backslash at character 2 starts no escape"));
    }
    void textRejected()
    {
        QFETCH(QString, text);
        QFETCH(QString, format);
        QFETCH(QString, fragment);
        const RegisterValueResult result = RegisterValue::fromText(text, ::format(format));
        QVERIFY(!result.ok);
        QVERIFY2(result.error.contains(fragment), qPrintable(result.error));
    }

    void numericEncoding()
    {
        const RegisterFormat u16 = format(QStringLiteral("u16"));
        const RegisterFormat i16 = format(QStringLiteral("i16"));
        const RegisterFormat i64 = format(QStringLiteral("i64"));
        const RegisterFormat u64 = format(QStringLiteral("u64"));
        const RegisterFormat f32 = format(QStringLiteral("f32"));
        const RegisterFormat f32cdab = format(QStringLiteral("f32-cdab"));

        QCOMPARE(RegisterValue::fromSigned(-1, u16).error, QStringLiteral("-1 is out of range for u16 (0 to 65535)"));
        QCOMPARE(RegisterValue::fromSigned(-1, i16).value.registers(), QList<quint16>{0xFFFF});
        QCOMPARE(RegisterValue::fromSigned(65535, u16).value.registers(), QList<quint16>{0xFFFF});
        QVERIFY(!RegisterValue::fromSigned(65536, u16).ok);
        QVERIFY(!RegisterValue::fromSigned(32768, i16).ok);
        QVERIFY(!RegisterValue::fromSigned(-32769, i16).ok);
        QVERIFY(RegisterValue::fromSigned(std::numeric_limits<qint64>::min(), i64).ok);
        QVERIFY(!RegisterValue::fromSigned(-1, u64).ok);
        QCOMPARE(RegisterValue::fromSigned(3, f32).value.registers(), (QList<quint16>{0x4040, 0x0000}));

        QVERIFY(!RegisterValue::fromUnsigned(std::numeric_limits<quint64>::max(), i64).ok);
        QVERIFY(RegisterValue::fromUnsigned(0x7FFF, i16).ok);
        QCOMPARE(RegisterValue::fromUnsigned(0x8000, i16).error, QStringLiteral("32768 is out of range for i16 (-32768 to 32767)"));
        QVERIFY(RegisterValue::fromUnsigned(std::numeric_limits<quint64>::max(), u64).ok);
        // 2^24 + 1 is not a float32; it rounds to 2^24 = 0x4B800000.
        QCOMPARE(RegisterValue::fromUnsigned(16777217, f32).value.registers(), (QList<quint16>{0x4B80, 0x0000}));

        QCOMPARE(RegisterValue::fromDouble(1.5, u16).error, QStringLiteral("1.5 is not a whole number: u16 holds whole numbers only"));
        QCOMPARE(RegisterValue::fromDouble(std::nan(""), u16).error,
                 QStringLiteral("NaN cannot be stored in u16: only float formats hold NaN and infinity"));
        QVERIFY(!RegisterValue::fromDouble(std::numeric_limits<double>::infinity(), i64).ok);
        QCOMPARE(RegisterValue::fromDouble(65535.0, u16).value.registers(), QList<quint16>{0xFFFF});
        QCOMPARE(RegisterValue::fromDouble(65536.0, u16).error, QStringLiteral("65536 is out of range for u16 (0 to 65535)"));
        QCOMPARE(RegisterValue::fromDouble(-32768.0, i16).value.registers(), QList<quint16>{0x8000});
        QCOMPARE(RegisterValue::fromDouble(-0.0, u16).value.registers(), QList<quint16>{0x0000});
        QVERIFY(!RegisterValue::fromDouble(9223372036854775808.0, i64).ok);
        QVERIFY(RegisterValue::fromDouble(-9223372036854775808.0, i64).ok);
        QVERIFY(!RegisterValue::fromDouble(18446744073709551616.0, u64).ok);
        QCOMPARE(RegisterValue::fromDouble(1e39, f32).error,
                 QStringLiteral("1e+39 is out of range for f32 (the largest finite value is 3.4028235e+38)"));
        QVERIFY(RegisterValue::fromDouble(1e-50, f32).error.contains(QStringLiteral("too small for f32")));
        QCOMPARE(RegisterValue::fromDouble(std::numeric_limits<double>::infinity(), f32).value.registers(),
                 (QList<quint16>{0x7F80, 0x0000}));
        QVERIFY(RegisterValue::fromDouble(std::nan(""), f32).value.isNaN());
        QCOMPARE(RegisterValue::fromDouble(123.456, f32cdab).value.registers(), (QList<quint16>{0xE979, 0x42F6}));
        // Around FLT_MAX: halfway to the next power of two rounds to infinity (refused), just
        // below it rounds to FLT_MAX.
        QVERIFY(!RegisterValue::fromDouble(std::ldexp(double(0x1FFFFFF), 103), f32).ok);
        QCOMPARE(RegisterValue::fromDouble(std::nextafter(std::ldexp(double(0x1FFFFFF), 103), 0.0), f32).value.registers(),
                 (QList<quint16>{0x7F7F, 0xFFFF}));
        QCOMPARE(RegisterValue::fromDouble(-std::nextafter(std::ldexp(double(0x1FFFFFF), 103), 0.0), f32).value.registers(),
                 (QList<quint16>{0xFF7F, 0xFFFF}));
    }

    void joinAndSplit()
    {
        const QList<quint16> cdab = {0xE979, 0x42F6};
        QCOMPARE(RegisterValue::joinRegisters(span(cdab), RegisterOrder::CDAB), quint64(0x42F6E979));
        quint16 out[4] = {};
        RegisterValue::splitRegisters(0x0102030405060708, RegisterOrder::DCBA, out);
        QCOMPARE(out[0], quint16(0x0807));
        QCOMPARE(out[3], quint16(0x0201));
        RegisterValue::splitRegisters(0x42F6E979, RegisterOrder::BADC, std::span<quint16>(out, 2));
        QCOMPARE(out[0], quint16(0xF642));
        QCOMPARE(out[1], quint16(0x79E9));
        quint16 small[1] = {};
        RegisterValue::fromBits(0x42F6E979, format(QStringLiteral("f32"))).writeRegisters(small); // never beyond out
        QCOMPARE(small[0], quint16(0x42F6));
    }

    // Independent model of the documented mapping: the order's letters name the value's bytes
    // (A most significant) in wire order. Checked for every format over random values.
    void orderMatchesLetters()
    {
        QRandomGenerator random(20240501);
        for (const RegisterFormat &fmt : RegisterFormat::all()) {
            const QString letters = fmt.orderName();
            const int bytes = fmt.byteCount();
            QCOMPARE(letters.size(), bytes);
            for (int trial = 0; trial < 200; ++trial) {
                const quint64 bits = random.generate64() & (bytes == 8 ? ~quint64(0) : (quint64(1) << (8 * bytes)) - 1);
                QList<quint16> expected;
                for (int i = 0; i < bytes; i += 2) {
                    auto byteOf = [&](QChar letter) {
                        const int index = letter.unicode() - u'A'; // 0 = most significant
                        return quint16((bits >> (8 * (bytes - 1 - index))) & 0xFF);
                    };
                    expected.append(quint16((byteOf(letters[i]) << 8) | byteOf(letters[i + 1])));
                }
                const RegisterValue value = RegisterValue::fromBits(bits, fmt);
                QCOMPARE(value.registers(), expected);
                QCOMPARE(RegisterValue::joinRegisters(span(expected), fmt.order()), bits);
            }
        }
    }

    void roundTrip_data()
    {
        QTest::addColumn<QString>("format");
        for (const RegisterFormat &fmt : RegisterFormat::all())
            QTest::newRow(qPrintable(fmt.name())) << fmt.name();
    }
    void roundTrip()
    {
        QFETCH(QString, format);
        const RegisterFormat fmt = ::format(format);
        const int bits = 16 * fmt.registerCount();
        const quint64 mask = bits == 64 ? ~quint64(0) : (quint64(1) << bits) - 1;
        QList<quint64> samples = {0, mask, quint64(1) << (bits - 1), (quint64(1) << (bits - 1)) - 1, 1};
        if (fmt.type() == RegisterType::Float32)
            samples += {0x7FC00000, 0x7F800000, 0xFF800000, 0x7F800001, 0x00000001, 0x7F7FFFFF, 0x80000000};
        if (fmt.type() == RegisterType::Float64)
            samples += {0x7FF8000000000000, 0x7FF0000000000000, 0xFFF0000000000000, 0x0000000000000001};
        QRandomGenerator random(quint32(qHash(format)));
        for (int i = 0; i < 2000; ++i)
            samples.append(random.generate64() & mask);

        for (quint64 sample : samples) {
            const RegisterValue value = RegisterValue::fromBits(sample, fmt);
            QCOMPARE(value.bits(), sample);

            // registers -> value -> registers
            const QList<quint16> regs = value.registers();
            const RegisterValueResult decoded = RegisterValue::fromRegisters(span(regs), fmt);
            QVERIFY(decoded.ok);
            QCOMPARE(decoded.value, value);

            // value -> text -> value; a NaN comes back as a NaN (the canonical one)
            const QString text = value.toText();
            const RegisterValueResult parsed = RegisterValue::fromText(text, fmt);
            QVERIFY2(parsed.ok, qPrintable(parsed.error + QLatin1String(" for ") + text));
            if (value.isNaN())
                QVERIFY(parsed.value.isNaN());
            else
                QCOMPARE(parsed.value.bits(), sample);

            // value -> number -> value
            RegisterValueResult number;
            if (fmt.isFloat())
                number = RegisterValue::fromDouble(value.toDouble(), fmt);
            else if (fmt.isSigned())
                number = RegisterValue::fromSigned(value.toInt64(), fmt);
            else
                number = RegisterValue::fromUnsigned(value.bits(), fmt);
            QVERIFY2(number.ok, qPrintable(number.error));
            if (value.isNaN())
                QVERIFY(number.value.isNaN());
            else
                QCOMPARE(number.value.bits(), sample);
        }
    }

    void asciiText_data()
    {
        QTest::addColumn<QString>("registers");
        QTest::addColumn<bool>("swapped");
        QTest::addColumn<QString>("text");
        QTest::newRow("4845 4C4C 4F00 HELLO") << QStringLiteral("4845 4C4C 4F00") << false << QStringLiteral("HELLO\\x00");
        QTest::newRow("4548 4C4C 004F HELLO swapped") << QStringLiteral("4548 4C4C 004F") << true << QStringLiteral("HELLO\\x00");
        QTest::newRow("empty") << QString() << false << QString();
        QTest::newRow("5C5C backslashes") << QStringLiteral("5C5C") << false << QStringLiteral("\\\\\\\\");
        QTest::newRow("0D0A CR LF") << QStringLiteral("0D0A") << false << QStringLiteral("\\x0D\\x0A");
    }
    void asciiText()
    {
        QFETCH(QString, registers);
        QFETCH(bool, swapped);
        QFETCH(QString, text);
        const QList<quint16> regs = words(registers);
        QCOMPARE(RegisterValue::asciiText(span(regs), swapped), text);
        const RegisterListResult back = RegisterValue::asciiRegisters(text, swapped);
        QVERIFY2(back.ok, qPrintable(back.error));
        QCOMPARE(back.registers, regs);
    }

    void asciiRegisters()
    {
        const RegisterListResult odd = RegisterValue::asciiRegisters(QStringLiteral("HELLO"), false);
        QVERIFY(odd.ok);
        QCOMPARE(wordsText(odd.registers), QStringLiteral("4845 4C4C 4F00")); // padded with one NUL
        const RegisterListResult even = RegisterValue::asciiRegisters(QStringLiteral("ABCD"), true);
        QCOMPARE(wordsText(even.registers), QStringLiteral("4241 4443"));
        const RegisterListResult bad = RegisterValue::asciiRegisters(QStringLiteral("ab\u00FCc"), false);
        QVERIFY(!bad.ok);
        QCOMPARE(bad.error, QStringLiteral("character 3 (U+00FC) is not ASCII; write a byte above 0x7F as \\xNN"));
        const RegisterListResult escape = RegisterValue::asciiRegisters(QStringLiteral("ab\\"), false);
        QVERIFY(!escape.ok);
        QVERIFY(escape.error.contains(QStringLiteral("the backslash at character 3 starts no escape")));

        QRandomGenerator random(7);
        for (int trial = 0; trial < 200; ++trial) {
            QList<quint16> regs(random.bounded(40));
            for (quint16 &r : regs)
                r = quint16(random.bounded(65536));
            for (bool swapped : {false, true}) {
                const RegisterListResult back
                    = RegisterValue::asciiRegisters(RegisterValue::asciiText(span(regs), swapped), swapped);
                QVERIFY(back.ok);
                QCOMPARE(back.registers, regs);
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestRegisterValue)
#include "tst_registervalue.moc"
