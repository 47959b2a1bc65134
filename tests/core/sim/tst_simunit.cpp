// SimUnit's data model and SimProcessor's data access function codes (01-06, 0F, 10, 16, 17,
// 18): answers, exception codes and their order (V1.1b3 6.x state diagrams, section 7).

#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/simmodbusserver.h"
#include "sim/simprocessor.h"
#include "simfixture.h"

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

namespace {

QList<bool> coilsFrom(int start, int count)
{
    QList<bool> bits;
    for (int a = start; a < start + count; ++a)
        bits.append(a % 3 == 0);
    return bits;
}

void row(const QByteArray &request, const QByteArray &expected)
{
    QTest::newRow(qPrintable(hexOf(request))) << request << expected;
}

QByteArray ex(int functionCode, int code)
{
    return pduOf(ResponseBuilder::exception(functionCode, code));
}

} // namespace

class TestSimUnit : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void ranges();
    void rangeErrors();
    void localAndClientWrites();
    void answers_data();
    void answers();
    void exceptionOrderForUnsupported_data();
    void exceptionOrderForUnsupported();
    void writeEffects_data();
    void writeEffects();
    void refusedWritesChangeNothing_data();
    void refusedWritesChangeNothing();
    void setMapThroughQt();
};

void TestSimUnit::ranges()
{
    auto unit = makeUnit();
    QVERIFY(unit->contains(SimTable::HoldingRegisters, 0, 32));
    QVERIFY(!unit->contains(SimTable::HoldingRegisters, 0, 33));
    QVERIFY(!unit->contains(SimTable::HoldingRegisters, 31, 10)); // through the gap 32-39
    QVERIFY(unit->contains(SimTable::HoldingRegisters, 40, 8));
    QVERIFY(unit->isWritable(SimTable::HoldingRegisters, 0, 32));
    QVERIFY(!unit->isWritable(SimTable::HoldingRegisters, 40, 1));
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 41), std::optional<quint16>(0xA001));
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 35), std::nullopt);
    QCOMPARE(unit->values(SimTable::InputRegisters, 8, 2), (QList<quint16>{1008, 1009}));
    QVERIFY(unit->values(SimTable::InputRegisters, 8, 3).isEmpty());
    QCOMPARE(unit->ranges(SimTable::Coils).size(), 2);
    QCOMPARE(unit->ranges(SimTable::Coils).at(1).start, quint16(100));

    // Two adjacent ranges read as one span.
    SimRange next;
    next.table = SimTable::HoldingRegisters;
    next.start = 32;
    next.count = 8;
    next.values = {1, 2, 3};
    QVERIFY(unit->addRange(next));
    QVERIFY(unit->contains(SimTable::HoldingRegisters, 30, 12));
    QCOMPARE(unit->values(SimTable::HoldingRegisters, 31, 4), (QList<quint16>{310, 1, 2, 3}));
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 39), std::optional<quint16>(0)); // padded with 0
    QVERIFY(!unit->isWritable(SimTable::HoldingRegisters, 38, 3)); // 40 is read-only
}

void TestSimUnit::rangeErrors()
{
    auto unit = makeUnit();
    QString error;
    SimRange r;
    r.table = SimTable::HoldingRegisters;
    r.start = 20;
    r.count = 25;
    QVERIFY(!unit->addRange(r, &error));
    QCOMPARE(error, QStringLiteral("holding registers range 20-44 overlaps range 0-31"));
    r.start = 0xFFF0;
    r.count = 17;
    QVERIFY(!unit->addRange(r, &error));
    QCOMPARE(error, QStringLiteral("holding registers range 65520 + 17 runs past address 65535"));
    r.count = 16;
    QVERIFY(unit->addRange(r, &error));
    r.count = 0;
    QVERIFY(!unit->addRange(r, &error));
}

void TestSimUnit::localAndClientWrites()
{
    auto unit = makeUnit();
    QSignalSpy changed(unit.get(), &SimUnit::valuesChanged);
    QSignalSpy wrote(unit.get(), &SimUnit::clientWrote);
    // Local writes ignore the writable flag and do not count as client writes.
    QVERIFY(unit->setValue(SimTable::HoldingRegisters, 40, 7));
    QVERIFY(unit->setValues(SimTable::InputRegisters, 0, {1, 2}));
    QVERIFY(unit->setValue(SimTable::Coils, 1, 5)); // a bit: any non-zero value is 1
    QCOMPARE(unit->value(SimTable::Coils, 1), std::optional<quint16>(1));
    QVERIFY(!unit->setValues(SimTable::HoldingRegisters, 30, {1, 2, 3})); // 32 missing: nothing set
    QCOMPARE(unit->value(SimTable::HoldingRegisters, 30), std::optional<quint16>(300));
    QCOMPARE(changed.size(), 3);
    QCOMPARE(wrote.size(), 0);
    // Client writes respect it.
    QVERIFY(!unit->clientWrite(SimTable::HoldingRegisters, 40, {1}));
    QVERIFY(unit->clientWrite(SimTable::HoldingRegisters, 2, {5, 6}));
    QCOMPARE(wrote.size(), 1);
    QCOMPARE(wrote.at(0).at(0).value<SimTable>(), SimTable::HoldingRegisters);
    QCOMPARE(wrote.at(0).at(1).toInt(), 2);
    QCOMPARE(wrote.at(0).at(2).toInt(), 2);
    QCOMPARE(changed.size(), 4);
}

void TestSimUnit::answers_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("expected");

    // 01 Read Coils (6.1)
    row(pduOf(RequestBuilder::readCoils(0, 10)), pduOf(ResponseBuilder::readCoils(coilsFrom(0, 10))));
    row(pduOf(RequestBuilder::readCoils(5, 59)), pduOf(ResponseBuilder::readCoils(coilsFrom(5, 59))));
    row(pduOf(RequestBuilder::readCoils(100, 8)), pduOf(ResponseBuilder::readCoils(QList<bool>(8, true))));
    row(hex("01 00 00 00 00"), ex(0x01, 3));          // quantity 0
    row(hex("01 00 00 07 D1"), ex(0x01, 3));          // quantity 2001
    row(hex("01 90 00 07 D1"), ex(0x01, 3));          // bad quantity before bad address
    row(hex("01 00 3C 00 05"), ex(0x01, 2));          // 60-64: 64 missing
    row(hex("01 00 40 00 01"), ex(0x01, 2));          // in the gap
    row(hex("01 00 62 00 03"), ex(0x01, 2));          // 98-100: 98 missing
    row(hex("01 00 00 00 0A 00"), ex(0x01, 3));       // a byte too many
    row(hex("01 00 00 00"), ex(0x01, 3));             // a byte short
    // 02 Read Discrete Inputs (6.2)
    row(pduOf(RequestBuilder::readDiscreteInputs(0, 9)),
        pduOf(ResponseBuilder::readDiscreteInputs({false, true, false, true, false, true, false, true, false})));
    row(hex("02 00 1F 00 02"), ex(0x02, 2));
    row(hex("02 00 00 07 D1"), ex(0x02, 3));
    // 03 Read Holding Registers (6.3)
    row(pduOf(RequestBuilder::readHoldingRegisters(0, 3)), pduOf(ResponseBuilder::readHoldingRegisters({0, 10, 20})));
    row(pduOf(RequestBuilder::readHoldingRegisters(45, 3)),
        pduOf(ResponseBuilder::readHoldingRegisters({0xA005, 0xA006, 0xA007})));
    row(hex("03 00 1E 00 0A"), ex(0x03, 2));          // 30-39: through the gap
    row(hex("03 00 00 00 7D"), ex(0x03, 2));          // 125 is allowed, the map is shorter
    row(hex("03 00 00 00 7E"), ex(0x03, 3));          // 126 is not
    row(hex("03 FF FF 00 02"), ex(0x03, 2));          // past 65535
    // 04 Read Input Registers (6.4)
    row(pduOf(RequestBuilder::readInputRegisters(8, 2)), pduOf(ResponseBuilder::readInputRegisters({1008, 1009})));
    row(hex("04 00 09 00 02"), ex(0x04, 2));
    row(hex("04 00 00 00 00"), ex(0x04, 3));
    // 05 Write Single Coil (6.5)
    row(pduOf(RequestBuilder::writeSingleCoil(1, true)), pduOf(ResponseBuilder::writeSingleCoil(1, true)));
    row(pduOf(RequestBuilder::writeSingleCoil(63, false)), pduOf(ResponseBuilder::writeSingleCoil(63, false)));
    row(hex("05 00 01 12 34"), ex(0x05, 3));          // neither FF00 nor 0000
    row(hex("05 00 64 12 34"), ex(0x05, 3));          // bad value before read-only
    row(hex("05 00 64 FF 00"), ex(0x05, 2));          // read-only coil 100
    row(hex("05 00 50 FF 00"), ex(0x05, 2));          // missing coil 80
    row(hex("05 00 01 FF 00 00"), ex(0x05, 3));
    // 06 Write Single Register (6.6)
    row(pduOf(RequestBuilder::writeSingleRegister(5, 0x1234)), pduOf(ResponseBuilder::writeSingleRegister(5, 0x1234)));
    row(hex("06 00 28 00 01"), ex(0x06, 2));          // read-only 40
    row(hex("06 00 23 00 01"), ex(0x06, 2));          // missing 35
    row(hex("06 00 01 00"), ex(0x06, 3));
    // 0F Write Multiple Coils (6.11)
    row(pduOf(RequestBuilder::writeMultipleCoils(0, {true, false, true, true})), pduOf(ResponseBuilder::writeMultipleCoils(0, 4)));
    row(pduOf(RequestBuilder::writeMultipleCoils(60, {true, true, true, true})), pduOf(ResponseBuilder::writeMultipleCoils(60, 4)));
    row(hex("0F 00 00 00 0A 01 FF"), ex(0x0F, 3));    // byte count 1 for 10 coils
    row(hex("0F 00 00 00 04 01 0F 00"), ex(0x0F, 3)); // a byte more than the byte count
    row(hex("0F 00 00 00 00 00"), ex(0x0F, 3));       // quantity 0
    row(hex("0F 00 64 00 02 01 03"), ex(0x0F, 2));    // read-only 100-101
    row(hex("0F 00 3E 00 04 01 0F"), ex(0x0F, 2));    // 62-65: 64 missing
    row(hex("0F 00 00"), ex(0x0F, 3));
    // 10 Write Multiple Registers (6.12)
    row(pduOf(RequestBuilder::writeMultipleRegisters(30, {7, 8})), pduOf(ResponseBuilder::writeMultipleRegisters(30, 2)));
    row(hex("10 00 00 00 02 02 00 01"), ex(0x10, 3)); // byte count 2 for 2 registers
    row(hex("10 00 00 00 7C F8") + QByteArray(248, 0), ex(0x10, 3)); // 124 registers
    row(hex("10 00 28 00 01 02 00 01"), ex(0x10, 2)); // read-only 40
    row(hex("10 00 1F 00 02 04 00 01 00 02"), ex(0x10, 2)); // 31-32: 32 missing
    // 16 Mask Write Register (6.16)
    row(pduOf(RequestBuilder::maskWriteRegister(4, 0x00F2, 0x0025)), pduOf(ResponseBuilder::maskWriteRegister(4, 0x00F2, 0x0025)));
    row(hex("16 00 28 00 F2 00 25"), ex(0x16, 2));
    row(hex("16 00 23 00 F2 00 25"), ex(0x16, 2));
    row(hex("16 00 04 00 F2 00"), ex(0x16, 3));
    // 17 Read/Write Multiple Registers (6.17): the write happens before the read
    row(pduOf(RequestBuilder::readWriteMultipleRegisters(0, 3, 1, {0x0101, 0x0202})),
        pduOf(ResponseBuilder::readWriteMultipleRegisters({0, 0x0101, 0x0202})));
    row(pduOf(RequestBuilder::readWriteMultipleRegisters(40, 2, 0, {1})),
        pduOf(ResponseBuilder::readWriteMultipleRegisters({0xA000, 0xA001})));
    row(hex("17 00 00 00 7D 00 00 00 01 02 00 01"), ex(0x17, 2)); // read 125: allowed, map shorter
    row(hex("17 00 00 00 7E 00 00 00 01 02 00 01"), ex(0x17, 3)); // read 126
    row(hex("17 00 00 00 01 00 00 00 7A F4") + QByteArray(244, 0), ex(0x17, 3)); // write 122
    row(hex("17 00 00 00 01 00 00 00 02 02 00 01"), ex(0x17, 3)); // byte count 2 for 2
    row(hex("17 00 00 00 01 00 00 00 01 02 00 01 00"), ex(0x17, 3)); // a byte too many
    row(hex("17 00 23 00 01 00 00 00 01 02 00 01"), ex(0x17, 2)); // read missing 35
    row(hex("17 00 00 00 01 00 28 00 01 02 00 01"), ex(0x17, 2)); // write read-only 40
    row(hex("17 00 00 00 01"), ex(0x17, 3));
    // 18 Read FIFO Queue (6.18; the example's queue)
    row(pduOf(RequestBuilder::readFifoQueue(0x04DE)), pduOf(ResponseBuilder::readFifoQueue({0x01B8, 0x1284})));
    row(hex("18 04 DF"), ex(0x18, 2));                // no queue there
    row(hex("18 05 00"), ex(0x18, 3));                // 32 registers queued
    row(hex("18 04 DE 00"), ex(0x18, 3));
    // Codes the simulator does not serve (section 7: 01)
    row(hex("41 00 01"), ex(0x41, 1));
    row(hex("09"), ex(0x09, 1));
    row(hex("00"), hex("80 01"));
    row(hex("FF 00"), hex("FF 01"));
}

void TestSimUnit::answers()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, expected);
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    const SimReply reply = processor.process(request);
    QCOMPARE(hexOf(reply.pdu), hexOf(expected));
    QCOMPARE(reply.kind, quint8(expected[0]) & 0x80 ? SimReply::Kind::Exception : SimReply::Kind::Normal);
    if (reply.kind == SimReply::Kind::Exception)
        QVERIFY2(!reply.note.isEmpty(), "an exception says why");
    QString why;
    if (quint8(request[0]) != 0 && quint8(request[0]) < 0x80)
        QVERIFY2(dissectsCleanly(request, reply.pdu, &why), qPrintable(why));
}

void TestSimUnit::exceptionOrderForUnsupported_data()
{
    QTest::addColumn<QByteArray>("request");
    // Every one of these is also malformed: 01 comes first (V1.1b3 section 7 and 6.x diagrams).
    QTest::newRow("01 00 00 00 00") << hex("01 00 00 00 00");
    QTest::newRow("03 90 00 00 7E") << hex("03 90 00 00 7E");
    QTest::newRow("10 00 00") << hex("10 00 00");
    QTest::newRow("08") << hex("08");
    QTest::newRow("2B 0E 09 00") << hex("2B 0E 09 00");
}

void TestSimUnit::exceptionOrderForUnsupported()
{
    QFETCH(QByteArray, request);
    auto unit = makeUnit();
    unit->setSupportedFunctions({0x05, 0x06}); // nothing of the above
    SimProcessor processor(unit.get());
    QCOMPARE(hexOf(processor.process(request).pdu), hexOf(ex(quint8(request[0]), 1)));
}

void TestSimUnit::writeEffects_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<int>("table");
    QTest::addColumn<int>("start");
    QTest::addColumn<QList<quint16>>("after");
    const int coils = int(SimTable::Coils);
    const int holding = int(SimTable::HoldingRegisters);
    QTest::newRow("05 00 01 FF 00") << hex("05 00 01 FF 00") << coils << 0 << QList<quint16>{1, 1, 0};
    QTest::newRow("05 00 00 00 00") << hex("05 00 00 00 00") << coils << 0 << QList<quint16>{0, 0, 0};
    QTest::newRow("0F 00 08 00 0A 02 CD 01") << hex("0F 00 08 00 0A 02 CD 01") << coils << 8
                                             << QList<quint16>{1, 0, 1, 1, 0, 0, 1, 1, 1, 0, 1}; // 18 unchanged
    QTest::newRow("06 00 05 12 34") << hex("06 00 05 12 34") << holding << 4 << QList<quint16>{0x12, 0x1234, 60};
    QTest::newRow("10 00 1E 00 02 04 00 07 00 08") << hex("10 00 1E 00 02 04 00 07 00 08") << holding << 29
                                                  << QList<quint16>{290, 7, 8};
    // 6.16's example: 0x12 AND 0xF2 OR (0x25 AND NOT 0xF2) = 0x17.
    QTest::newRow("16 00 04 00 F2 00 25") << hex("16 00 04 00 F2 00 25") << holding << 4 << QList<quint16>{0x17};
    QTest::newRow("17 00 00 00 01 00 02 00 01 02 AB CD") << hex("17 00 00 00 01 00 02 00 01 02 AB CD") << holding << 1
                                                          << QList<quint16>{10, 0xABCD, 30};
}

void TestSimUnit::writeEffects()
{
    QFETCH(QByteArray, request);
    QFETCH(int, table);
    QFETCH(int, start);
    QFETCH(QList<quint16>, after);
    auto unit = makeUnit();
    unit->setValue(SimTable::HoldingRegisters, 4, 0x12);
    SimProcessor processor(unit.get());
    QSignalSpy wrote(unit.get(), &SimUnit::clientWrote);
    const SimReply reply = processor.process(request);
    QCOMPARE(reply.kind, SimReply::Kind::Normal);
    QCOMPARE(unit->values(SimTable(table), start, int(after.size())), after);
    QCOMPARE(wrote.size(), 1);
}

void TestSimUnit::refusedWritesChangeNothing_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::newRow("17 00 23 00 01 00 00 00 01 02 00 01") << hex("17 00 23 00 01 00 00 00 01 02 00 01");
    QTest::newRow("10 00 1F 00 02 04 00 01 00 02") << hex("10 00 1F 00 02 04 00 01 00 02");
    QTest::newRow("0F 00 3E 00 04 01 0F") << hex("0F 00 3E 00 04 01 0F");
    QTest::newRow("10 00 28 00 01 02 00 01") << hex("10 00 28 00 01 02 00 01");
}

void TestSimUnit::refusedWritesChangeNothing()
{
    QFETCH(QByteArray, request);
    auto unit = makeUnit();
    const auto before = unit->ranges(SimTable::HoldingRegisters);
    const auto coilsBefore = unit->ranges(SimTable::Coils);
    SimProcessor processor(unit.get());
    QSignalSpy changed(unit.get(), &SimUnit::valuesChanged);
    QCOMPARE(processor.process(request).kind, SimReply::Kind::Exception);
    QCOMPARE(changed.size(), 0);
    QCOMPARE(unit->ranges(SimTable::HoldingRegisters).at(0).values, before.at(0).values);
    QCOMPARE(unit->ranges(SimTable::Coils).at(0).values, coilsBefore.at(0).values);
}

void TestSimUnit::setMapThroughQt()
{
    // QModbusServer::setMap on the adapter becomes one writable range per table.
    SimUnit unit(7);
    SimModbusServer server(&unit);
    QModbusDataUnitMap map;
    map.insert(QModbusDataUnit::HoldingRegisters, QModbusDataUnit(QModbusDataUnit::HoldingRegisters, 100, {1, 2, 3}));
    QVERIFY(server.setMap(map));
    QCOMPARE(unit.values(SimTable::HoldingRegisters, 100, 3), (QList<quint16>{1, 2, 3}));
    quint16 v = 0;
    QVERIFY(server.data(QModbusDataUnit::HoldingRegisters, 101, &v));
    QCOMPARE(v, quint16(2));
    QVERIFY(server.setData(QModbusDataUnit::HoldingRegisters, 102, 9));
    QCOMPARE(unit.value(SimTable::HoldingRegisters, 102), std::optional<quint16>(9));
    QVERIFY(!server.data(QModbusDataUnit::HoldingRegisters, 103, &v));
}

QTEST_GUILESS_MAIN(TestSimUnit)
#include "tst_simunit.moc"
