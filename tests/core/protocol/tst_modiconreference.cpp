#include "protocol/modiconreference.h"

#include <QtTest/QtTest>

using namespace mbscope;

namespace {

constexpr int kCoils = int(ModbusTable::Coils);
constexpr int kDiscrete = int(ModbusTable::DiscreteInputs);
constexpr int kInput = int(ModbusTable::InputRegisters);
constexpr int kHolding = int(ModbusTable::HoldingRegisters);
constexpr int kFive = int(ModiconReference::Form::FiveDigit);
constexpr int kSix = int(ModiconReference::Form::SixDigit);
constexpr int kPrefixed = int(ModiconReference::Form::Prefixed);

QString codes(std::span<const FunctionCode> list)
{
    QStringList out;
    for (FunctionCode code : list)
        out.append(QString::number(int(code), 16).toUpper().rightJustified(2, QLatin1Char('0')));
    return out.join(QLatin1Char(' '));
}

} // namespace

// Published references: the RosRao request 01 03 00 79 reads from 40122 (PDU address 121); the
// tutorial's 07 03 00 C8 reads 40201-40204 (PDU 200) and 07 04 01 2C reads 30301-30303 (PDU 300).
// The rest are the boundaries of the five- and six-digit forms (V1.1b3, 4.4: element X is PDU X-1).
class TestModiconReference : public QObject
{
    Q_OBJECT
private slots:
    void addressHint_data()
    {
        // A PDU address of 10001 or more that reads as a reference (V1.1b3, 4.4): the guide's mistake.
        QTest::addColumn<qint64>("address");
        QTest::addColumn<QString>("hint");
        QTest::newRow("40122") << qint64(40122) << QStringLiteral("40122 looks like a Modicon reference; its PDU address is 121 (0x0079)");
        QTest::newRow("400122") << qint64(400122) << QStringLiteral("400122 looks like a Modicon reference; its PDU address is 121 (0x0079)");
        QTest::newRow("10001") << qint64(10001) << QStringLiteral("10001 looks like a Modicon reference; its PDU address is 0 (0x0000)");
        QTest::newRow("30301") << qint64(30301) << QStringLiteral("30301 looks like a Modicon reference; its PDU address is 300 (0x012C)");
        QTest::newRow("465536") << qint64(465536) << QStringLiteral("465536 looks like a Modicon reference; its PDU address is 65535 (0xFFFF)");
        QTest::newRow("10000: below") << qint64(10000) << QString();
        QTest::newRow("121: an address") << qint64(121) << QString();
        QTest::newRow("20000: no table 2") << qint64(20000) << QString();
        QTest::newRow("40000: no element 0") << qint64(40000) << QString();
        QTest::newRow("465537: beyond") << qint64(465537) << QString();
    }
    void addressHint()
    {
        QFETCH(qint64, address);
        QFETCH(QString, hint);
        QCOMPARE(ModiconReference::addressHint(address), hint);
    }
    void parses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("table");
        QTest::addColumn<int>("address");
        QTest::addColumn<int>("form");
        QTest::addColumn<QString>("five");
        QTest::addColumn<QString>("six");
        auto row = [](const char *name, const char *text, int table, int address, int form, const char *five,
                      const char *six) {
            QTest::newRow(name) << QString::fromLatin1(text) << table << address << form << QString::fromLatin1(five)
                                << QString::fromLatin1(six);
        };
        row("40122 (rosrao 01 03 00 79 00 16 15 DD)", "40122", kHolding, 121, kFive, "40122", "400122");
        row("400122 (rosrao, six digits)", "400122", kHolding, 121, kSix, "40122", "400122");
        row("4x122 (rosrao, prefixed)", "4x122", kHolding, 121, kPrefixed, "40122", "400122");
        row("4X0122 (prefixed, leading zero)", "4X0122", kHolding, 121, kPrefixed, "40122", "400122");
        row("4x00122 (prefixed, two leading zeros)", "4x00122", kHolding, 121, kPrefixed, "40122", "400122");
        row("40201 (tutorial 07 03 00 C8 00 04 C5 91)", "40201", kHolding, 200, kFive, "40201", "400201");
        row("40204 (tutorial, last of four)", "40204", kHolding, 203, kFive, "40204", "400204");
        row("30301 (tutorial 07 04 01 2C 00 03 70 58)", "30301", kInput, 300, kFive, "30301", "300301");
        row("30303 (tutorial, last of three)", "30303", kInput, 302, kFive, "30303", "300303");
        row("300301 (tutorial, six digits)", "300301", kInput, 300, kSix, "30301", "300301");
        row("3x301", "3x301", kInput, 300, kPrefixed, "30301", "300301");
        row("40001 first holding register", "40001", kHolding, 0, kFive, "40001", "400001");
        row("400001 first holding register, six digits", "400001", kHolding, 0, kSix, "40001", "400001");
        row("49999 last five-digit holding register", "49999", kHolding, 9998, kFive, "49999", "409999");
        row("409999 same, six digits", "409999", kHolding, 9998, kSix, "49999", "409999");
        row("410000 first beyond the five-digit form", "410000", kHolding, 9999, kSix, "", "410000");
        row("465536 last holding register", "465536", kHolding, 65535, kSix, "", "465536");
        row("4x10000", "4x10000", kHolding, 9999, kPrefixed, "", "410000");
        row("4x65536", "4x65536", kHolding, 65535, kPrefixed, "", "465536");
        row("00001 first coil", "00001", kCoils, 0, kFive, "00001", "000001");
        row("000001 first coil, six digits", "000001", kCoils, 0, kSix, "00001", "000001");
        row("09999 last five-digit coil", "09999", kCoils, 9998, kFive, "09999", "009999");
        row("065536 last coil", "065536", kCoils, 65535, kSix, "", "065536");
        row("0x1 coil, prefixed", "0x1", kCoils, 0, kPrefixed, "00001", "000001");
        row("0x0079 is coil 79, not hex", "0x0079", kCoils, 78, kPrefixed, "00079", "000079");
        row("10001 first discrete input", "10001", kDiscrete, 0, kFive, "10001", "100001");
        row("19999 last five-digit discrete input", "19999", kDiscrete, 9998, kFive, "19999", "109999");
        row("165536 last discrete input", "165536", kDiscrete, 65535, kSix, "", "165536");
        row("1x1", "1x1", kDiscrete, 0, kPrefixed, "10001", "100001");
        row("30001 first input register", "30001", kInput, 0, kFive, "30001", "300001");
        row("365536 last input register", "365536", kInput, 65535, kSix, "", "365536");
        row(" 40001 with spaces", "  40001 ", kHolding, 0, kFive, "40001", "400001");
    }
    void parses()
    {
        QFETCH(QString, text);
        QFETCH(int, table);
        QFETCH(int, address);
        QFETCH(int, form);
        QFETCH(QString, five);
        QFETCH(QString, six);
        const ModiconReferenceResult result = ModiconReference::parse(text);
        QVERIFY2(result.ok, qPrintable(result.error));
        QVERIFY(result.error.isEmpty());
        QCOMPARE(int(result.reference.table()), table);
        QCOMPARE(int(result.reference.address()), address);
        QCOMPARE(result.reference.number(), address + 1);
        QCOMPARE(int(result.form), form);
        QCOMPARE(result.reference.fiveDigit(), five);
        QCOMPARE(result.reference.hasFiveDigitForm(), !five.isEmpty());
        QCOMPARE(result.reference.sixDigit(), six);
    }

    void rejects_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("fragment");
        auto row = [](const char *text, const char *fragment) {
            QTest::newRow(text) << QString::fromLatin1(text) << QString::fromLatin1(fragment);
        };
        row("40000", "'40000' is not a reference: holding registers start at 40001");
        row("400000", "'400000' is not a reference: holding registers start at 400001");
        row("30000", "input registers start at 30001");
        row("00000", "coils start at 00001");
        row("10000", "discrete inputs start at 10001");
        row("100000", "discrete inputs start at 100001");
        row("465537", "'465537' is out of range: holding registers end at 465536 (PDU address 65535)");
        row("499999", "holding registers end at 465536");
        row("099999", "coils end at 065536");
        row("365537", "input registers end at 365536");
        row("165537", "discrete inputs end at 165536");
        row("20001", "'20001' is not a reference: the leading digit 2 names no table (0 coils, 1 discrete inputs, "
                     "3 input registers, 4 holding registers)");
        row("50001", "the leading digit 5 names no table");
        row("600001", "6xxxx is Modicon's extended memory");
        row("70001", "the leading digit 7 names no table");
        row("80001", "the leading digit 8");
        row("90001", "the leading digit 9");
        row("2012", "the leading digit 2 names no table");
        row("4012", "'4012' is not a reference: it has 4 digits; holding register references have five "
                    "digits (40001-49999) or six (400001-465536)");
        row("4000001", "it has 7 digits");
        row("3", "it has 1 digit; input register references have five digits (30001-39999) or six (300001-365536)");
        row("0001", "coil references have five digits (00001-09999)");
        row("", "the reference is empty");
        row("   ", "the reference is empty");
        row("40a01", "'40a01' is not a reference: 'a' at character 3 is not a digit");
        row("-40001", "'-' at character 1 is not a digit");
        row("%MW100", "'%' at character 1 is not a digit");
        row("40 001", "' ' at character 3 is not a digit");
        row("4x", "'4x' is not a reference: a number (1-65536) must follow 4x");
        row("4x0", "'4x0' is not a reference: holding registers start at 4x1");
        row("4x0000", "holding registers start at 4x1");
        row("4X65537", "'4X65537' is out of range: holding registers end at 4X65536 (PDU address 65535)");
        row("4x9999999", "is out of range");
        row("4x0000065537", "is out of range");
        row("2x1", "the leading digit 2 names no table");
        row("4xx1", "'x' at character 3 is not a digit");
        row("4x1.5", "'.' at character 4 is not a digit");
        row("x401", "'x' at character 1 is not a digit");
    }
    void rejects()
    {
        QFETCH(QString, text);
        QFETCH(QString, fragment);
        const ModiconReferenceResult result = ModiconReference::parse(text);
        QVERIFY(!result.ok);
        QVERIFY2(result.error.contains(fragment), qPrintable(result.error));
    }

    void describes_data()
    {
        QTest::addColumn<int>("table");
        QTest::addColumn<int>("address");
        QTest::addColumn<QString>("text");
        QTest::newRow("holding 121 (rosrao)") << kHolding << 121
            << QStringLiteral("PDU address 121 (0x0079), register number 122, Modicon 40122 / 400122");
        QTest::newRow("holding 0") << kHolding << 0
            << QStringLiteral("PDU address 0 (0x0000), register number 1, Modicon 40001 / 400001");
        QTest::newRow("holding 200 (tutorial)") << kHolding << 200
            << QStringLiteral("PDU address 200 (0x00C8), register number 201, Modicon 40201 / 400201");
        QTest::newRow("input 300 (tutorial)") << kInput << 300
            << QStringLiteral("PDU address 300 (0x012C), register number 301, Modicon 30301 / 300301");
        QTest::newRow("coil 0") << kCoils << 0
            << QStringLiteral("PDU address 0 (0x0000), coil number 1, Modicon 00001 / 000001");
        QTest::newRow("discrete input 9998") << kDiscrete << 9998
            << QStringLiteral("PDU address 9998 (0x270E), discrete input number 9999, Modicon 19999 / 109999");
        QTest::newRow("holding 9999: no five-digit form") << kHolding << 9999
            << QStringLiteral("PDU address 9999 (0x270F), register number 10000, Modicon 410000 "
                              "(no five-digit form: 40001-49999 reach PDU addresses 0-9998 only)");
        QTest::newRow("holding 65535") << kHolding << 65535
            << QStringLiteral("PDU address 65535 (0xFFFF), register number 65536, Modicon 465536 "
                              "(no five-digit form: 40001-49999 reach PDU addresses 0-9998 only)");
        QTest::newRow("coil 10000") << kCoils << 10000
            << QStringLiteral("PDU address 10000 (0x2710), coil number 10001, Modicon 010001 "
                              "(no five-digit form: 00001-09999 reach PDU addresses 0-9998 only)");
    }
    void describes()
    {
        QFETCH(int, table);
        QFETCH(int, address);
        QFETCH(QString, text);
        QCOMPARE(ModiconReference(ModbusTable(table), quint16(address)).describe(), text);
    }

    // Every address of every table, in each form, reads back to itself.
    void everyAddressRoundTrips()
    {
        for (ModbusTable table : {ModbusTable::Coils, ModbusTable::DiscreteInputs, ModbusTable::InputRegisters,
                                  ModbusTable::HoldingRegisters}) {
            for (int address = 0; address <= 65535; ++address) {
                const ModiconReference ref(table, quint16(address));
                const ModiconReferenceResult six = ModiconReference::parse(ref.sixDigit());
                QVERIFY(six.ok && six.reference == ref && six.form == ModiconReference::Form::SixDigit);
                if (ref.hasFiveDigitForm()) {
                    const ModiconReferenceResult five = ModiconReference::parse(ref.fiveDigit());
                    QVERIFY(five.ok && five.reference == ref && five.form == ModiconReference::Form::FiveDigit);
                } else {
                    QVERIFY(ref.fiveDigit().isEmpty());
                }
                const QString prefixed = QString::number(ref.tableDigit()) + QLatin1Char('x') + QString::number(ref.number());
                const ModiconReferenceResult pre = ModiconReference::parse(prefixed);
                QVERIFY(pre.ok && pre.reference == ref);
            }
        }
    }

    void fromNumber_data()
    {
        QTest::addColumn<int>("table");
        QTest::addColumn<int>("number");
        QTest::addColumn<int>("address"); // -1: refused
        QTest::addColumn<QString>("error");
        QTest::newRow("register 122 -> 121") << kHolding << 122 << 121 << QString();
        QTest::newRow("register 1 -> 0") << kHolding << 1 << 0 << QString();
        QTest::newRow("register 65536 -> 65535") << kHolding << 65536 << 65535 << QString();
        QTest::newRow("coil 10000 -> 9999") << kCoils << 10000 << 9999 << QString();
        QTest::newRow("register 0 refused") << kHolding << 0 << -1
            << QStringLiteral("register number 0 is out of range: holding registers are numbered 1-65536 "
                              "(PDU addresses 0-65535)");
        QTest::newRow("coil 65537 refused") << kCoils << 65537 << -1
            << QStringLiteral("coil number 65537 is out of range: coils are numbered 1-65536");
        QTest::newRow("discrete input -1 refused") << kDiscrete << -1 << -1
            << QStringLiteral("discrete input number -1 is out of range");
    }
    void fromNumber()
    {
        QFETCH(int, table);
        QFETCH(int, number);
        QFETCH(int, address);
        QFETCH(QString, error);
        const ModiconReferenceResult result = ModiconReference::fromNumber(ModbusTable(table), number);
        QCOMPARE(result.ok, address >= 0);
        if (result.ok) {
            QCOMPARE(int(result.reference.address()), address);
            QCOMPARE(int(result.reference.table()), table);
        } else {
            QVERIFY2(result.error.contains(error), qPrintable(result.error));
        }
    }

    void functions_data()
    {
        QTest::addColumn<int>("table");
        QTest::addColumn<QString>("read");
        QTest::addColumn<QString>("write");
        QTest::addColumn<bool>("writable");
        QTest::newRow("coils: 01 / 05 0F") << kCoils << QStringLiteral("01") << QStringLiteral("05 0F") << true;
        QTest::newRow("discrete inputs: 02") << kDiscrete << QStringLiteral("02") << QString() << false;
        QTest::newRow("input registers: 04") << kInput << QStringLiteral("04") << QString() << false;
        QTest::newRow("holding registers: 03 17 / 06 10 16 17") << kHolding << QStringLiteral("03 17")
                                                                << QStringLiteral("06 10 16 17") << true;
    }
    void functions()
    {
        QFETCH(int, table);
        QFETCH(QString, read);
        QFETCH(QString, write);
        QFETCH(bool, writable);
        QCOMPARE(codes(ModiconReference::readFunctions(ModbusTable(table))), read);
        QCOMPARE(codes(ModiconReference::writeFunctions(ModbusTable(table))), write);
        QCOMPARE(ModiconReference::isWritable(ModbusTable(table)), writable);
        // Each listed code maps back to this table.
        for (FunctionCode code : ModiconReference::readFunctions(ModbusTable(table)))
            QCOMPARE(int(ModiconReference::tableOf(quint8(code)).value()), table);
        for (FunctionCode code : ModiconReference::writeFunctions(ModbusTable(table)))
            QCOMPARE(int(ModiconReference::tableOf(quint8(code)).value()), table);
    }

    void tableOf_data()
    {
        QTest::addColumn<int>("code");
        QTest::addColumn<int>("table"); // -1: no table
        QTest::newRow("01") << 0x01 << kCoils;
        QTest::newRow("02") << 0x02 << kDiscrete;
        QTest::newRow("03") << 0x03 << kHolding;
        QTest::newRow("04") << 0x04 << kInput;
        QTest::newRow("05") << 0x05 << kCoils;
        QTest::newRow("06") << 0x06 << kHolding;
        QTest::newRow("0F") << 0x0F << kCoils;
        QTest::newRow("10") << 0x10 << kHolding;
        QTest::newRow("16") << 0x16 << kHolding;
        QTest::newRow("17") << 0x17 << kHolding;
        for (int code : {0x00, 0x07, 0x08, 0x0B, 0x0C, 0x11, 0x14, 0x15, 0x18, 0x2B, 0x41, 0x64, 0x83, 0xFF})
            QTest::addRow("%02X has no table", code) << code << -1;
    }
    void tableOf()
    {
        QFETCH(int, code);
        QFETCH(int, table);
        const std::optional<ModbusTable> found = ModiconReference::tableOf(quint8(code));
        QCOMPARE(found.has_value(), table >= 0);
        if (found)
            QCOMPARE(int(*found), table);
    }

    void names()
    {
        QCOMPARE(QLatin1String(ModiconReference::tableName(ModbusTable::HoldingRegisters)), QLatin1String("holding registers"));
        QCOMPARE(QLatin1String(ModiconReference::tableName(ModbusTable::Coils)), QLatin1String("coils"));
        QCOMPARE(QLatin1String(ModiconReference::numberName(ModbusTable::DiscreteInputs)),
                 QLatin1String("discrete input number"));
        QCOMPARE(ModiconReference::tableDigit(ModbusTable::InputRegisters), 3);
        QCOMPARE(ModiconReference().describe(),
                 QStringLiteral("PDU address 0 (0x0000), register number 1, Modicon 40001 / 400001"));
    }
};

QTEST_GUILESS_MAIN(TestModiconReference)
#include "tst_modiconreference.moc"
