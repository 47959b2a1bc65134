// ReadAnswerRows: the rows a register table shows for one read answer. Wide values follow the
// profile's multi-register entries (WideValueLayout) and say why they are incomplete; names,
// scaling and units come from the profile; changes are found by address; a transaction's ADUs
// give the answer. Expected values computed independently (Python's struct module: 230.5 as
// f32 is 43668000, 3.0 as f64 is 4008000000000000, 0x4008 0x0000 as f32 is 2.125).
#include "profile/readanswerrows.h"

#include "profile/profileloader.h"
#include "protocol/adubuilder.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace Qt::StringLiterals;

Q_DECLARE_METATYPE(mbscope::RowValue::Gap)

namespace {

UnitProfile unitOf(const QByteArray &json)
{
    const ProfileLoadResult r = ProfileLoader::parse(json, QStringLiteral("test"));
    if (!r.ok)
        qFatal("test profile: %s", qPrintable(r.errorText()));
    return *r.profile.unit(1);
}

// A status word, a float at 1-2, a double at 3-6, a counter at 7.
UnitProfile wideProfile()
{
    return unitOf(R"({"name": "wide", "units": [{"id": 1, "tables": {"holding": [
        {"address": 0, "name": "status", "type": "u16"},
        {"address": 1, "name": "voltage", "type": "f32-abcd", "unit": "V", "value": 230.5},
        {"address": 3, "name": "energy", "type": "f64", "unit": "kWh", "value": 3},
        {"address": 7, "name": "count", "type": "u16"}
    ]}}]})");
}

// Scaling, an offset, units, an entry of three values and a named coil.
UnitProfile scaledProfile()
{
    return unitOf(R"({"name": "scaled", "units": [{"id": 1, "tables": {
        "coils": [{"address": 4, "name": "relay"}],
        "holding": [
        {"address": 0, "name": "setpoint", "type": "i16", "scale": 0.1, "unit": "degC", "value": 21.5},
        {"address": 1, "name": "pressure", "type": "u16", "scale": 0.01, "offset": 900, "unit": "hPa"},
        {"address": 2, "name": "voltage", "type": "f32-cdab", "unit": "V", "value": 230},
        {"address": 4, "name": "code", "type": "hex", "count": 3}
    ]}}]})");
}

const QList<quint16> kWideRegisters{7, 0x4366, 0x8000, 0x4008, 0, 0, 0, 42};

ReadAnswer holding(int address, const QList<quint16> &registers)
{
    ReadAnswer a;
    a.table = ModbusTable::HoldingRegisters;
    a.functionCode = 0x03;
    a.address = address;
    a.quantity = int(registers.size());
    a.registers = registers;
    return a;
}

ReadAnswer coils(int address, const QList<bool> &bits)
{
    ReadAnswer a;
    a.table = ModbusTable::Coils;
    a.functionCode = 0x01;
    a.address = address;
    a.quantity = int(bits.size());
    a.bits = bits;
    return a;
}

RegisterFormat format(const QString &name)
{
    const RegisterFormatResult r = RegisterFormat::parse(name);
    if (!r.ok)
        qFatal("bad format in a test row: %s", qPrintable(r.error));
    return r.format;
}

} // namespace

class TestReadAnswerRows : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void values_data();
    void values();
    void entries_data();
    void entries();
    void bits();
    void changedRows_data();
    void changedRows();
    void answerOf();
};

void TestReadAnswerRows::values_data()
{
    QTest::addColumn<bool>("profile"); // the wide profile, or none
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("address"); // of the read, into kWideRegisters
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("row");
    QTest::addColumn<int>("start");
    QTest::addColumn<int>("end");
    QTest::addColumn<int>("span");
    QTest::addColumn<RowValue::Gap>("gap");
    QTest::addColumn<QString>("value"); // the decoded value's text, empty when not decoded

    using Gap = RowValue::Gap;
    const QString f32 = u"f32-abcd"_s;
    const QString f64 = u"f64"_s;
    QTest::newRow("u16 stands alone") << true << u"u16"_s << 0 << 8 << 7 << 7 << 8 << 1 << Gap::None << u"42"_s;
    // From the answer's first register f32 would read 0007 4366: the profile's float starts at 1.
    QTest::newRow("f32: status cut by the float") << true << f32 << 0 << 8 << 0 << 0 << 1 << 1 << Gap::CutByProfile << QString();
    QTest::newRow("f32: the float on its address") << true << f32 << 0 << 8 << 1 << 1 << 3 << 2 << Gap::None << u"230.5"_s;
    QTest::newRow("f32: inside the float") << true << f32 << 0 << 8 << 2 << 1 << 3 << 0 << Gap::None << u"230.5"_s;
    QTest::newRow("f32: first half of the double") << true << f32 << 0 << 8 << 3 << 3 << 5 << 2 << Gap::None << u"2.125"_s;
    QTest::newRow("f32: the answer ends") << true << f32 << 0 << 8 << 7 << 7 << 8 << 1 << Gap::EndsAfter << QString();
    QTest::newRow("f64: the double on its address") << true << f64 << 0 << 8 << 3 << 3 << 7 << 4 << Gap::None << u"3"_s;
    QTest::newRow("f64: float cut by the double") << true << f64 << 0 << 8 << 1 << 1 << 3 << 2 << Gap::CutByProfile << QString();
    QTest::newRow("f32: answer begins inside the float") << true << f32 << 2 << 5 << 0 << -1 << 1 << 1 << Gap::BeginsBefore << QString();
    QTest::newRow("f32: after the cut, the double") << true << f32 << 2 << 5 << 1 << 1 << 3 << 2 << Gap::None << u"2.125"_s;
    QTest::newRow("f64 from the double's second register") << true << f64 << 4 << 4 << 0 << -1 << 3 << 3 << Gap::BeginsBefore << QString();
    QTest::newRow("f64 continued before the answer") << true << f64 << 4 << 4 << 2 << -1 << 3 << 0 << Gap::BeginsBefore << QString();
    // Without a profile the values count from the answer's first register.
    QTest::newRow("no profile: f32 from the first register") << false << f32 << 3 << 5 << 0 << 0 << 2 << 2 << Gap::None << u"2.125"_s;
    QTest::newRow("no profile: f32 continued") << false << f32 << 3 << 5 << 1 << 0 << 2 << 0 << Gap::None << u"2.125"_s;
    QTest::newRow("no profile: f64 ends after the answer") << false << f64 << 0 << 6 << 4 << 4 << 6 << 2 << Gap::EndsAfter << QString();
}

void TestReadAnswerRows::values()
{
    QFETCH(bool, profile);
    QFETCH(QString, format);
    QFETCH(int, address);
    QFETCH(int, count);
    QFETCH(int, row);
    QFETCH(int, start);
    QFETCH(int, end);
    QFETCH(int, span);
    QFETCH(RowValue::Gap, gap);
    QFETCH(QString, value);

    const ReadAnswerRows rows(holding(address, kWideRegisters.mid(address, count)),
                              profile ? std::optional(wideProfile()) : std::nullopt);
    QCOMPARE(rows.rowCount(), count);
    const RowValue v = rows.valueAt(row, ::format(format));
    QCOMPARE(v.start, start);
    QCOMPARE(v.end, end);
    QCOMPARE(v.span(), span);
    QCOMPARE(v.continuation, span == 0);
    QCOMPARE(v.gap, gap);
    QCOMPARE(v.isComplete(), gap == RowValue::Gap::None);
    QCOMPARE(v.value ? v.value->toText() : QString(), value);
}

void TestReadAnswerRows::entries_data()
{
    QTest::addColumn<int>("address"); // of the read
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("row");
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("registerIndex");
    QTest::addColumn<bool>("complete");
    QTest::addColumn<QString>("scaled");

    // Registers 0-6: setpoint 215 (21.5 degC), pressure 11325 (1013.25 hPa), 230.0 as f32-cdab
    // (0000 4366), codes 0x00AB 0x00CD 0x00EF.
    QTest::newRow("scaled with unit") << 0 << 7 << 0 << u"setpoint"_s << 0 << true << u"21.5 degC"_s;
    QTest::newRow("scale and offset") << 0 << 7 << 1 << u"pressure"_s << 0 << true << u"1013.25 hPa"_s;
    QTest::newRow("float, word swapped") << 0 << 7 << 2 << u"voltage"_s << 0 << true << u"230 V"_s;
    QTest::newRow("float's second register") << 0 << 7 << 3 << u"voltage"_s << 1 << false << QString();
    QTest::newRow("unscaled keeps the format's text") << 0 << 7 << 4 << u"code[0]"_s << 0 << true << u"0x00AB"_s;
    QTest::newRow("an entry's third value") << 0 << 7 << 6 << u"code[2]"_s << 0 << true << u"0x00EF"_s;
    QTest::newRow("float cut by the answer's end") << 0 << 3 << 2 << u"voltage"_s << 0 << false << QString();
    QTest::newRow("answer begins inside the float") << 3 << 2 << 0 << u"voltage"_s << 1 << false << QString();
    QTest::newRow("no entry") << 7 << 1 << 0 << QString() << 0 << false << QString();
}

void TestReadAnswerRows::entries()
{
    QFETCH(int, address);
    QFETCH(int, count);
    QFETCH(int, row);
    QFETCH(QString, name);
    QFETCH(int, registerIndex);
    QFETCH(bool, complete);
    QFETCH(QString, scaled);

    const QList<quint16> registers{215, 11325, 0x0000, 0x4366, 0x00AB, 0x00CD, 0x00EF, 9};
    const ReadAnswerRows rows(holding(address, registers.mid(address, count)), scaledProfile());
    const RowEntry entry = rows.entryAt(row);
    QCOMPARE(entry.name(), name);
    QCOMPARE(entry.entry != nullptr, !name.isEmpty());
    QCOMPARE(entry.registerIndex, registerIndex);
    QCOMPARE(entry.complete, complete);
    QCOMPARE(rows.scaledText(row), scaled);
    QCOMPARE(rows.address(row), address + row);
    QCOMPARE(rows.raw(row), int(registers.at(address + row)));
}

void TestReadAnswerRows::bits()
{
    const ReadAnswerRows rows(coils(3, {true, false, true}), scaledProfile());
    QVERIFY(rows.isBits());
    QCOMPARE(rows.rowCount(), 3);
    QCOMPARE(rows.raw(0), 1);
    QCOMPARE(rows.raw(1), 0);
    QCOMPARE(rows.reference(1).describe(), ModiconReference(ModbusTable::Coils, 4).describe());
    QCOMPARE(rows.entryAt(1).name(), u"relay"_s);
    QVERIFY(!rows.entryAt(0).entry);
    QCOMPARE(rows.scaledText(1), QString()); // bits have no scaled value
    const RowValue v = rows.valueAt(2, RegisterFormat(RegisterType::Float32));
    QCOMPARE(v.span(), 1);
    QVERIFY(!v.value);
}

void TestReadAnswerRows::changedRows_data()
{
    QTest::addColumn<int>("previousAddress");
    QTest::addColumn<QList<quint16>>("previous");
    QTest::addColumn<int>("nextAddress");
    QTest::addColumn<QList<quint16>>("next");
    QTest::addColumn<QList<bool>>("changed");

    QTest::newRow("same range") << 10 << QList<quint16>{1, 2, 3} << 10 << QList<quint16>{1, 5, 3}
                                << QList<bool>{false, true, false};
    QTest::newRow("shifted range compares by address") << 10 << QList<quint16>{1, 2, 3} << 11
                                                        << QList<quint16>{2, 4, 9} << QList<bool>{false, true, false};
    QTest::newRow("no overlap") << 0 << QList<quint16>{1} << 5 << QList<quint16>{7, 8} << QList<bool>{false, false};
}

void TestReadAnswerRows::changedRows()
{
    QFETCH(int, previousAddress);
    QFETCH(QList<quint16>, previous);
    QFETCH(int, nextAddress);
    QFETCH(QList<quint16>, next);
    QFETCH(QList<bool>, changed);
    QCOMPARE(ReadAnswerRows::changedRows(holding(previousAddress, previous), holding(nextAddress, next)), changed);
    // Another table changes nothing, whatever its values.
    ReadAnswer other = holding(previousAddress, previous);
    other.table = ModbusTable::InputRegisters;
    QCOMPARE(ReadAnswerRows::changedRows(other, holding(nextAddress, next)), QList<bool>(next.size(), false));
    QCOMPARE(ReadAnswerRows::changedRows(coils(0, {true, false}), coils(1, {true, true})), (QList<bool>{true, false}));
}

void TestReadAnswerRows::answerOf()
{
    // 03 from 0x0079, two registers, over MBAP (V1.1b3 6.3 with a Modbus TCP header).
    Transaction t;
    t.status = TransactionStatus::Ok;
    t.request = QByteArray::fromHex("000100000006010300790002");
    t.response = QByteArray::fromHex("00010000000701030400070064");
    const ReadAnswerResult r = ReadAnswerRows::answerOf(t, Framing::Tcp);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(r.answer.address, 0x79);
    QCOMPARE(r.answer.registers, (QList<quint16>{7, 100}));

    t.status = TransactionStatus::Timeout;
    t.problem = u"no answer in 1000 ms"_s;
    const ReadAnswerResult refused = ReadAnswerRows::answerOf(t, Framing::Tcp);
    QVERIFY(!refused.ok);
    QCOMPARE(refused.error, u"the transaction ended with timeout: no answer in 1000 ms"_s);
}

QTEST_GUILESS_MAIN(TestReadAnswerRows)
#include "tst_readanswerrows.moc"
