// ReadAnswer: a read request paired with its answer gives the table, the addresses and the values
// (V1.1b3 6.1-6.4, 6.17), or says what is wrong and where. TableWrite: the write an edit makes,
// with the function the user chose (6.5, 6.6, 6.11, 6.12). Frames written from the spec's
// examples and the RosRao read (tests/data/published-frames.json).
#include "protocol/readanswer.h"
#include "protocol/tablewrite.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace Qt::StringLiterals;

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(QByteArray(text));
}

} // namespace

class TestReadAnswer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void answers_data();
    void answers();
    void refused_data();
    void refused();
    void valueAt();
    void texts();
    void writes_data();
    void writes();
    void coilText();
};

void TestReadAnswer::answers_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<int>("table");
    QTest::addColumn<int>("address");
    QTest::addColumn<QList<int>>("values");

    // V1.1b3 6.1 example: coils 20-38 (PDU 0x0013, 19 coils) answer CD 6B 05.
    QTest::newRow("01 spec example") << hex("0100130013") << hex("0103CD6B05") << int(ModbusTable::Coils) << 19
                                     << QList<int>{1, 0, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1, 0, 1, 1, 0, 1, 0, 1};
    // 6.2 example: inputs 197-218 (PDU 0x00C4, 22) answer AC DB 35.
    QTest::newRow("02 spec example") << hex("0200C40016") << hex("0203ACDB35") << int(ModbusTable::DiscreteInputs)
                                     << 196
                                     << QList<int>{0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 0, 1, 1, 0, 1, 1, 1, 0, 1, 0, 1, 1};
    // 6.3 example: registers 108-110 (PDU 0x006B) answer 022B 0000 0064.
    QTest::newRow("03 spec example") << hex("03006B0003") << hex("0306022B00000064") << int(ModbusTable::HoldingRegisters)
                                     << 107 << QList<int>{555, 0, 100};
    // 6.4 example: input register 9 (PDU 0x0008) answers 000A.
    QTest::newRow("04 spec example") << hex("0400080001") << hex("0402000A") << int(ModbusTable::InputRegisters) << 8
                                     << QList<int>{10};
    // 6.17 example: read 6 from 0x0003 while writing 3 at 0x000E.
    QTest::newRow("17 spec example") << hex("170003000600 0E0003 06 00FF00FF00FF") << hex("170C00FE0ACD00010003000D00FF")
                                     << int(ModbusTable::HoldingRegisters) << 3 << QList<int>{254, 2765, 1, 3, 13, 255};
    QTest::newRow("rosrao first registers") << hex("0300790003") << hex("0306041A00000000")
                                            << int(ModbusTable::HoldingRegisters) << 121 << QList<int>{1050, 0, 0};
}

void TestReadAnswer::answers()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(int, table);
    QFETCH(int, address);
    QFETCH(QList<int>, values);
    const ReadAnswerResult r = ReadAnswer::fromPdus(request, response);
    QVERIFY2(r.ok, qPrintable(r.error));
    QCOMPARE(int(r.answer.table), table);
    QCOMPARE(r.answer.address, address);
    QCOMPARE(r.answer.quantity, int(values.size()));
    QCOMPARE(r.answer.count(), int(values.size()));
    QList<int> got;
    for (int i = 0; i < r.answer.count(); ++i)
        got.append(r.answer.isBits() ? int(r.answer.bits.at(i)) : int(r.answer.registers.at(i)));
    QCOMPARE(got, values);
}

void TestReadAnswer::refused_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<QString>("error");

    QTest::newRow("empty request") << QByteArray() << hex("0302000A")
                                   << u"the request is empty: expected a read (01, 02, 03, 04 or 17)"_s;
    QTest::newRow("empty answer") << hex("0300000001") << QByteArray() << u"the answer is empty"_s;
    QTest::newRow("no byte count") << hex("0300000001") << hex("03")
                                   << u"the answer ends after the function code: the byte count is missing (offset 1)"_s;
    QTest::newRow("byte count too big") << hex("0300790016")
                                        << hex("032C041A0000") << u"the byte count (offset 1 of the answer) says 44 bytes but 4 follow it"_s;
    QTest::newRow("exception") << hex("0100000001") << hex("8101")
                               << u"the answer is exception 0x01 (Illegal Function) to 0x01 (Read Coils)"_s;
    QTest::newRow("beyond 65535") << hex("03FFFF0002") << hex("030400010002")
                                  << u"the read from PDU address 65535 for 2 values runs beyond address 65535"_s;
}

void TestReadAnswer::refused()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(QString, error);
    const ReadAnswerResult r = ReadAnswer::fromPdus(request, response);
    QVERIFY(!r.ok);
    QCOMPARE(r.error, error);
    QCOMPARE(r.answer.count(), 0);
}

void TestReadAnswer::valueAt()
{
    const ReadAnswerResult r = ReadAnswer::fromPdus(hex("0300000003"), hex("030642F6E9790001"));
    QVERIFY(r.ok);
    const RegisterFormat f32(RegisterType::Float32);
    QCOMPARE(r.answer.valueAt(0, f32)->toText(), u"123.456"_s);
    QVERIFY(!r.answer.valueAt(1, f32)); // inside the value
    QVERIFY(!r.answer.valueAt(2, f32)); // one register short
    QCOMPARE(r.answer.valueAt(2, RegisterFormat(RegisterType::UInt16))->toText(), u"1"_s);
}

void TestReadAnswer::texts()
{
    QCOMPARE(ReadAnswer::referenceText(ModiconReference(ModbusTable::HoldingRegisters, 121)), u"40122"_s);
    QCOMPARE(ReadAnswer::referenceText(ModiconReference(ModbusTable::InputRegisters, 9999)), u"310000"_s);
    QCOMPARE(ReadAnswer::referenceText(ModiconReference(ModbusTable::Coils, 0)), u"00001"_s);
    QCOMPARE(ReadAnswer::addressText(121), u"121 (0x0079)"_s);
}

void TestReadAnswer::writes_data()
{
    QTest::addColumn<bool>("coil");
    QTest::addColumn<int>("choice");
    QTest::addColumn<int>("address");
    QTest::addColumn<QList<quint16>>("words");
    QTest::addColumn<QByteArray>("pdu");
    QTest::addColumn<QString>("error");

    const int automatic = int(WriteChoice::Automatic);
    const int single = int(WriteChoice::Single);
    const int multiple = int(WriteChoice::Multiple);
    // V1.1b3 6.6 example: register 2 (PDU 1) = 3; 6.12 example: registers 2-3 = 000A 0102.
    QTest::newRow("06 spec example") << false << automatic << 1 << QList<quint16>{3} << hex("0600010003") << QString();
    QTest::newRow("10 spec example") << false << automatic << 1 << QList<quint16>{0x000A, 0x0102}
                                     << hex("100001000204000A0102") << QString();
    QTest::newRow("10 for one") << false << multiple << 1 << QList<quint16>{3} << hex("10000100010200 03") << QString();
    QTest::newRow("06 for two refused") << false << single << 121 << QList<quint16>{1, 2} << QByteArray()
                                        << u"06 (Write Single Register) writes one register, but the value spans 2 "
                                           u"registers from 40122 (PDU address 121): choose 10 (Write Multiple Registers)"_s;
    // 6.5 example: coil 173 (PDU 0x00AC) ON; 6.11: 0F with one coil.
    QTest::newRow("05 spec example") << true << automatic << 0xAC << QList<quint16>{1} << hex("0500ACFF00") << QString();
    QTest::newRow("05 single off") << true << single << 0xAC << QList<quint16>{0} << hex("0500AC0000") << QString();
    QTest::newRow("0F one coil") << true << multiple << 0xAC << QList<quint16>{1} << hex("0F00AC00010101") << QString();
    QTest::newRow("address beyond 65535") << false << automatic << 70000 << QList<quint16>{1} << QByteArray()
                                          << u"address: address 70000 is out of range: Write Single Register addresses are 0-65535"_s;
}

void TestReadAnswer::writes()
{
    QFETCH(bool, coil);
    QFETCH(int, choice);
    QFETCH(int, address);
    QFETCH(QList<quint16>, words);
    QFETCH(QByteArray, pdu);
    QFETCH(QString, error);
    const TableWriteResult r = coil ? TableWrite::coil(address, words.constFirst() != 0, WriteChoice(choice))
                                    : TableWrite::registers(address, words, WriteChoice(choice));
    QCOMPARE(r.error.isEmpty() ? QString() : r.error.left(error.size()), error);
    QCOMPARE(r.ok, error.isEmpty());
    QCOMPARE(r.pdu.toHex(' '), pdu.toHex(' '));
    if (r.ok)
        QCOMPARE(r.functionCode, quint8(pdu.at(0)));
}

void TestReadAnswer::coilText()
{
    for (const char *on : {"1", "on", "ON", " true "})
        QCOMPARE(TableWrite::coilFromText(QString::fromLatin1(on)), std::optional<bool>(true));
    for (const char *off : {"0", "off", "False"})
        QCOMPARE(TableWrite::coilFromText(QString::fromLatin1(off)), std::optional<bool>(false));
    for (const char *bad : {"", "2", "yes", "0x1"})
        QVERIFY(!TableWrite::coilFromText(QString::fromLatin1(bad)));
    QCOMPARE(TableWrite::functionFor(ModbusTable::InputRegisters, 1, WriteChoice::Automatic), quint8(0));
    QCOMPARE(TableWrite::functionFor(ModbusTable::HoldingRegisters, 4, WriteChoice::Automatic), quint8(0x10));
    QCOMPARE(TableWrite::functionFor(ModbusTable::HoldingRegisters, 4, WriteChoice::Single), quint8(0));
    QCOMPARE(TableWrite::functionFor(ModbusTable::Coils, 1, WriteChoice::Automatic), quint8(0x05));
}

QTEST_GUILESS_MAIN(TestReadAnswer)
#include "tst_readanswer.moc"
