#include "protocol/registerformat.h"

#include <QtCore/QSet>
#include <QtTest/QtTest>

using namespace mbscope;

// Register format names: what is accepted, its canonical spelling, and the refusals.
class TestRegisterFormat : public QObject
{
    Q_OBJECT
private slots:
    void parses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("registers");
        QTest::addColumn<QString>("order");
        QTest::newRow("u16") << QStringLiteral("u16") << QStringLiteral("u16") << 1 << QStringLiteral("AB");
        QTest::newRow("U16 upper case") << QStringLiteral("U16") << QStringLiteral("u16") << 1 << QStringLiteral("AB");
        QTest::newRow(" i16 with spaces") << QStringLiteral("  i16 ") << QStringLiteral("i16") << 1 << QStringLiteral("AB");
        QTest::newRow("uint16") << QStringLiteral("uint16") << QStringLiteral("u16") << 1 << QStringLiteral("AB");
        QTest::newRow("u16-ab is the default") << QStringLiteral("u16-ab") << QStringLiteral("u16") << 1 << QStringLiteral("AB");
        QTest::newRow("int16-ba") << QStringLiteral("int16-ba") << QStringLiteral("i16-ba") << 1 << QStringLiteral("BA");
        QTest::newRow("hex") << QStringLiteral("hex") << QStringLiteral("hex") << 1 << QStringLiteral("AB");
        QTest::newRow("hex16-BA") << QStringLiteral("hex16-BA") << QStringLiteral("hex-ba") << 1 << QStringLiteral("BA");
        QTest::newRow("bin") << QStringLiteral("bin") << QStringLiteral("bin") << 1 << QStringLiteral("AB");
        QTest::newRow("binary") << QStringLiteral("binary") << QStringLiteral("bin") << 1 << QStringLiteral("AB");
        QTest::newRow("ascii") << QStringLiteral("ascii") << QStringLiteral("ascii") << 1 << QStringLiteral("AB");
        QTest::newRow("ascii-ba (byte swapped)") << QStringLiteral("ascii-ba") << QStringLiteral("ascii-ba") << 1 << QStringLiteral("BA");
        QTest::newRow("u32 defaults to abcd") << QStringLiteral("u32") << QStringLiteral("u32-abcd") << 2 << QStringLiteral("ABCD");
        QTest::newRow("u32-abcd") << QStringLiteral("u32-abcd") << QStringLiteral("u32-abcd") << 2 << QStringLiteral("ABCD");
        QTest::newRow("f32-cdab") << QStringLiteral("f32-cdab") << QStringLiteral("f32-cdab") << 2 << QStringLiteral("CDAB");
        QTest::newRow("float") << QStringLiteral("float") << QStringLiteral("f32-abcd") << 2 << QStringLiteral("ABCD");
        QTest::newRow("float32-BADC") << QStringLiteral("float32-BADC") << QStringLiteral("f32-badc") << 2 << QStringLiteral("BADC");
        QTest::newRow("i32-dcba") << QStringLiteral("i32-dcba") << QStringLiteral("i32-dcba") << 2 << QStringLiteral("DCBA");
        QTest::newRow("int32-cdab") << QStringLiteral("int32-cdab") << QStringLiteral("i32-cdab") << 2 << QStringLiteral("CDAB");
        QTest::newRow("uint32-dcba") << QStringLiteral("uint32-dcba") << QStringLiteral("u32-dcba") << 2 << QStringLiteral("DCBA");
        QTest::newRow("f64 defaults to abcdefgh") << QStringLiteral("f64") << QStringLiteral("f64-abcdefgh") << 4 << QStringLiteral("ABCDEFGH");
        QTest::newRow("double-cdab (family name)") << QStringLiteral("double-cdab") << QStringLiteral("f64-ghefcdab") << 4 << QStringLiteral("GHEFCDAB");
        QTest::newRow("f64-ghefcdab") << QStringLiteral("f64-ghefcdab") << QStringLiteral("f64-ghefcdab") << 4 << QStringLiteral("GHEFCDAB");
        QTest::newRow("float64-dcba") << QStringLiteral("float64-dcba") << QStringLiteral("f64-hgfedcba") << 4 << QStringLiteral("HGFEDCBA");
        QTest::newRow("u64-hgfedcba") << QStringLiteral("u64-hgfedcba") << QStringLiteral("u64-hgfedcba") << 4 << QStringLiteral("HGFEDCBA");
        QTest::newRow("i64-badc") << QStringLiteral("i64-badc") << QStringLiteral("i64-badcfehg") << 4 << QStringLiteral("BADCFEHG");
        QTest::newRow("int64-BADCFEHG") << QStringLiteral("int64-BADCFEHG") << QStringLiteral("i64-badcfehg") << 4 << QStringLiteral("BADCFEHG");
        QTest::newRow("uint64-abcd") << QStringLiteral("uint64-abcd") << QStringLiteral("u64-abcdefgh") << 4 << QStringLiteral("ABCDEFGH");
    }
    void parses()
    {
        QFETCH(QString, text);
        QFETCH(QString, name);
        QFETCH(int, registers);
        QFETCH(QString, order);
        const RegisterFormatResult result = RegisterFormat::parse(text);
        QVERIFY2(result.ok, qPrintable(result.error));
        QVERIFY(result.error.isEmpty());
        QCOMPARE(result.format.name(), name);
        QCOMPARE(result.format.registerCount(), registers);
        QCOMPARE(result.format.byteCount(), 2 * registers);
        QCOMPARE(result.format.orderName(), order);
    }

    void rejects_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("fragment");
        QTest::newRow("empty") << QString() << QStringLiteral("the register format is empty: expected u16, i16, hex");
        QTest::newRow("spaces only") << QStringLiteral("   ") << QStringLiteral("the register format is empty");
        QTest::newRow("f33") << QStringLiteral("f33")
                             << QStringLiteral("'f33' is not a register format: expected u16, i16, hex, bin, ascii, u32, "
                                               "i32, u64, i64, f32 or f64");
        QTest::newRow("f33-abcd") << QStringLiteral("f33-abcd") << QStringLiteral("'f33' is not a type; expected u16");
        QTest::newRow("-abcd: no type") << QStringLiteral("-abcd") << QStringLiteral("'' is not a type");
        QTest::newRow("u16-cdab: word order on one register")
            << QStringLiteral("u16-cdab") << QStringLiteral("'u16-cdab' is not a register format: u16 takes the order ab or ba, not 'cdab'");
        QTest::newRow("ascii-dcba") << QStringLiteral("ascii-dcba") << QStringLiteral("ascii takes the order ab or ba");
        QTest::newRow("f32-ab: 16-bit order on 32 bits") << QStringLiteral("f32-ab")
                                                         << QStringLiteral("f32 takes the order abcd, cdab, badc or dcba, not 'ab'");
        QTest::newRow("f32-abdc: no such order") << QStringLiteral("f32-abdc") << QStringLiteral("not 'abdc'");
        QTest::newRow("f32-abcdefgh: 64-bit order on 32 bits") << QStringLiteral("f32-abcdefgh") << QStringLiteral("not 'abcdefgh'");
        QTest::newRow("f64-abcdefhg") << QStringLiteral("f64-abcdefhg")
                                      << QStringLiteral("f64 takes the order abcdefgh, ghefcdab, badcfehg or hgfedcba");
        QTest::newRow("f64-cdabghef: not a family member") << QStringLiteral("f64-cdabghef") << QStringLiteral("not 'cdabghef'");
        QTest::newRow("f32- empty order") << QStringLiteral("f32-") << QStringLiteral("not ''");
        QTest::newRow("f32-cdab-x") << QStringLiteral("f32-cdab-x") << QStringLiteral("not 'cdab-x'");
        QTest::newRow("u16_ba: underscore") << QStringLiteral("u16_ba") << QStringLiteral("'u16_ba' is not a register format");
        QTest::newRow("f32 cdab: space") << QStringLiteral("f32 cdab") << QStringLiteral("is not a register format");
    }
    void rejects()
    {
        QFETCH(QString, text);
        QFETCH(QString, fragment);
        const RegisterFormatResult result = RegisterFormat::parse(text);
        QVERIFY(!result.ok);
        QVERIFY2(result.error.contains(fragment), qPrintable(result.error));
    }

    void descriptions_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("description");
        QTest::newRow("u16") << QStringLiteral("u16") << QStringLiteral("unsigned 16-bit, high byte first (AB)");
        QTest::newRow("i16-ba") << QStringLiteral("i16-ba") << QStringLiteral("signed 16-bit, byte swap (BA)");
        QTest::newRow("f32-abcd") << QStringLiteral("f32-abcd") << QStringLiteral("float32 (IEEE 754 single), big endian (ABCD)");
        QTest::newRow("f32-cdab") << QStringLiteral("f32-cdab") << QStringLiteral("float32 (IEEE 754 single), word swap (CDAB)");
        QTest::newRow("u32-badc") << QStringLiteral("u32-badc") << QStringLiteral("unsigned 32-bit, byte swap (BADC)");
        QTest::newRow("i32-dcba") << QStringLiteral("i32-dcba") << QStringLiteral("signed 32-bit, little endian (DCBA)");
        QTest::newRow("f64-ghefcdab") << QStringLiteral("f64-ghefcdab") << QStringLiteral("float64 (IEEE 754 double), word swap (GHEFCDAB)");
        QTest::newRow("ascii-ba") << QStringLiteral("ascii-ba") << QStringLiteral("ASCII, two characters per register, byte swap (BA)");
    }
    void descriptions()
    {
        QFETCH(QString, name);
        QFETCH(QString, description);
        const RegisterFormatResult result = RegisterFormat::parse(name);
        QVERIFY2(result.ok, qPrintable(result.error));
        QCOMPARE(result.format.description(), description);
    }

    void oneRegisterOrdersAreNormalised()
    {
        // A single register has no word order: CDAB is AB, DCBA is BA.
        QCOMPARE(RegisterFormat(RegisterType::UInt16, RegisterOrder::CDAB), RegisterFormat(RegisterType::UInt16));
        QCOMPARE(RegisterFormat(RegisterType::Int16, RegisterOrder::DCBA),
                 RegisterFormat(RegisterType::Int16, RegisterOrder::BADC));
        QCOMPARE(RegisterFormat(RegisterType::Int16, RegisterOrder::DCBA).name(), QStringLiteral("i16-ba"));
        QVERIFY(RegisterFormat(RegisterType::Float32, RegisterOrder::CDAB) != RegisterFormat(RegisterType::Float32));
    }

    void flags()
    {
        const RegisterFormat f32cdab(RegisterType::Float32, RegisterOrder::CDAB);
        QVERIFY(f32cdab.isFloat() && !f32cdab.isSigned() && f32cdab.isWordSwapped() && !f32cdab.isByteSwapped());
        const RegisterFormat i64dcba(RegisterType::Int64, RegisterOrder::DCBA);
        QVERIFY(i64dcba.isSigned() && !i64dcba.isFloat() && i64dcba.isWordSwapped() && i64dcba.isByteSwapped());
        const RegisterFormat u32badc(RegisterType::UInt32, RegisterOrder::BADC);
        QVERIFY(!u32badc.isWordSwapped() && u32badc.isByteSwapped());
        QCOMPARE(RegisterFormat().name(), QStringLiteral("u16"));
    }

    void allFormatsAreDistinctAndParseBack()
    {
        const QList<RegisterFormat> formats = RegisterFormat::all();
        QCOMPARE(formats.size(), 34); // 5 one-register types x 2 + 6 wider types x 4
        QSet<QString> names;
        for (const RegisterFormat &format : formats) {
            names.insert(format.name());
            const RegisterFormatResult back = RegisterFormat::parse(format.name());
            QVERIFY2(back.ok, qPrintable(back.error));
            QVERIFY2(back.format == format, qPrintable(format.name()));
        }
        QCOMPARE(names.size(), 34);
    }
};

QTEST_GUILESS_MAIN(TestRegisterFormat)
#include "tst_registerformat.moc"
