// SimProcessor's file records (14/15, V1.1b3 6.14-6.15) and Read Device Identification
// (2B/0E, 6.21): answers, exception order, paging of objects that do not fit one response.

#include "protocol/requestbuilder.h"
#include "protocol/responsebuilder.h"
#include "sim/simprocessor.h"
#include "simfixture.h"

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using namespace mbscope;
using namespace mbscope::simtest;

namespace {

QByteArray ex(int functionCode, int code)
{
    return pduOf(ResponseBuilder::exception(functionCode, code));
}

void row(const QByteArray &request, const QByteArray &expected)
{
    QTest::newRow(qPrintable(hexOf(request))) << request << expected;
}

QList<quint16> file1(int record, int length)
{
    QList<quint16> values;
    for (int r = record; r < record + length; ++r)
        values.append(quint16(0x0100 + r));
    return values;
}

QByteArray deviceId(int code, int conformity, bool more, int next, const QList<DeviceIdObject> &objects)
{
    return pduOf(ResponseBuilder::readDeviceIdentification(code, conformity, more, next, objects));
}

const QList<DeviceIdObject> kBasic = {{0, "mbscope"}, {1, "SIM"}, {2, "1.0"}};
const QList<DeviceIdObject> kRegular = kBasic + QList<DeviceIdObject>{{3, "https://example.invalid"}, {4, "Simulator"}, {5, "S-1"}, {6, "tests"}};

} // namespace

class TestSimRecords : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void answers_data();
    void answers();
    void writeFileRecord();
    void refusedFileWriteChangesNothing();
    void deviceIdPaging();
    void deviceIdLongObject();
    void deviceIdWithoutIndividualAccess();
};

void TestSimRecords::answers_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("expected");
    // 14 Read File Record
    row(pduOf(RequestBuilder::readFileRecord({{1, 2, 3, 6}, {1, 0, 1, 6}})),
        pduOf(ResponseBuilder::readFileRecord({file1(2, 3), file1(0, 1)})));
    row(pduOf(RequestBuilder::readFileRecord({{2, 0, 4, 6}})),
        pduOf(ResponseBuilder::readFileRecord({{0x0200, 0x0201, 0x0202, 0x0203}})));
    row(hex("14 06 06 00 01 00 00 00"), ex(0x14, 3));                   // byte count 6
    row(hex("14 0E 06 00 01 00 00 00 01"), ex(0x14, 3));                // announces 14, 7 present
    row(hex("14 08 06 00 01 00 00 00 01 00"), ex(0x14, 3));             // not a multiple of 7
    row(hex("14 07 06 00 01 00 00 00 00"), ex(0x14, 3));                // record length 0
    row(hex("14 07 05 00 01 00 00 00 01"), ex(0x14, 2));                // reference type 5
    row(hex("14 07 06 00 03 00 00 00 01"), ex(0x14, 2));                // no file 3
    row(hex("14 07 06 00 00 00 00 00 01"), ex(0x14, 2));                // no file 0
    row(hex("14 07 06 00 01 00 1C 00 03"), ex(0x14, 2));                // records 28-30 of 30
    row(hex("14 07 06 00 01 27 10 00 01"), ex(0x14, 2));                // record 10000
    row(hex("14 0E 06 00 03 00 00 00 01 06 00 01 00 00 00 00"), ex(0x14, 3)); // 03 (length 0) before 02 (file 3)
    // Five sub-requests of 30 records need 312 bytes: too many for one response.
    row(hex("14 23") + hex("06 00 01 00 00 00 1E").repeated(5), ex(0x14, 3));
    row(hex("14"), ex(0x14, 3));
    // 15 Write File Record: the echo
    row(pduOf(RequestBuilder::writeFileRecord({{1, 3, {0xAAAA, 0xBBBB}, 6}})),
        pduOf(ResponseBuilder::writeFileRecord({{1, 3, {0xAAAA, 0xBBBB}, 6}})));
    row(hex("15 07 06 00 01 00 00 00 00"), ex(0x15, 3));                // data length 7
    row(hex("15 09 06 00 01 00 00 00 01 00"), ex(0x15, 3));             // announces 9, 8 present
    row(hex("15 09 06 00 01 00 00 00 02 00 01"), ex(0x15, 3));          // length 2 needs 4 bytes
    row(hex("15 09 06 00 01 00 00 00 00 00 01"), ex(0x15, 3));          // length 0
    row(hex("15 09 06 00 02 00 00 00 01 00 01"), ex(0x15, 2));          // file 2 is read-only
    row(hex("15 09 06 00 01 00 1D 00 01 00 01"), hex("15 09 06 00 01 00 1D 00 01 00 01")); // the last record
    row(hex("15 0B 06 00 01 00 1D 00 02 00 01 00 02"), ex(0x15, 2));    // past the end
    row(hex("15 09 07 00 01 00 00 00 01 00 01"), ex(0x15, 2));          // reference type 7
    // 2B/0E Read Device Identification
    row(pduOf(RequestBuilder::readDeviceIdentification(1, 0)), deviceId(1, 0x83, false, 0, kBasic));
    row(pduOf(RequestBuilder::readDeviceIdentification(2, 0)), deviceId(2, 0x83, false, 0, kRegular));
    row(pduOf(RequestBuilder::readDeviceIdentification(3, 0)),
        deviceId(3, 0x83, false, 0, kRegular + QList<DeviceIdObject>{{0x80, "extended"}}));
    row(pduOf(RequestBuilder::readDeviceIdentification(2, 4)), deviceId(2, 0x83, false, 0, kRegular.mid(4)));
    row(pduOf(RequestBuilder::readDeviceIdentification(1, 5)), deviceId(1, 0x83, false, 0, kBasic)); // 5 is not basic: from 0
    row(pduOf(RequestBuilder::readDeviceIdentification(2, 0x42)), deviceId(2, 0x83, false, 0, kRegular)); // unknown: from 0
    row(pduOf(RequestBuilder::readDeviceIdentification(4, 3)), deviceId(4, 0x83, false, 0, {{3, "https://example.invalid"}}));
    row(pduOf(RequestBuilder::readDeviceIdentification(4, 0x80)), deviceId(4, 0x83, false, 0, {{0x80, "extended"}}));
    row(hex("2B 0E 04 07"), ex(0x2B, 2));  // individual access to a missing object
    row(hex("2B 0E 05 00"), ex(0x2B, 3));  // Read Device ID code 5
    row(hex("2B 0E 00 00"), ex(0x2B, 3));
    row(hex("2B 0E 05 07"), ex(0x2B, 3));  // 03 before 02
    row(hex("2B 0E 01"), ex(0x2B, 3));
    row(hex("2B 0E 01 00 00"), ex(0x2B, 3));
    row(hex("2B 0D 00 00"), ex(0x2B, 1));  // CANopen General Reference: MEI type not served
    row(hex("2B"), ex(0x2B, 3));
}

void TestSimRecords::answers()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, expected);
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    const SimReply reply = processor.process(request);
    QCOMPARE(hexOf(reply.pdu), hexOf(expected));
    QString why;
    QVERIFY2(dissectsCleanly(request, reply.pdu, &why), qPrintable(why));
}

void TestSimRecords::writeFileRecord()
{
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    QSignalSpy written(unit.get(), &SimUnit::fileWritten);
    const QByteArray request = pduOf(RequestBuilder::writeFileRecord({{1, 3, {0xAAAA, 0xBBBB}, 6}, {1, 29, {0xCCCC}, 6}}));
    QCOMPARE(processor.process(request).kind, SimReply::Kind::Normal);
    QCOMPARE(unit->fileRecords(1).mid(2, 3), (QList<quint16>{0x0102, 0xAAAA, 0xBBBB}));
    QCOMPARE(unit->fileRecords(1).last(), quint16(0xCCCC));
    QCOMPARE(written.size(), 2);
    // Read back through 14.
    const SimReply read = processor.process(pduOf(RequestBuilder::readFileRecord({{1, 3, 2, 6}})));
    QCOMPARE(hexOf(read.pdu), hexOf(pduOf(ResponseBuilder::readFileRecord({{0xAAAA, 0xBBBB}}))));
}

void TestSimRecords::refusedFileWriteChangesNothing()
{
    auto unit = makeUnit();
    SimProcessor processor(unit.get());
    // The first sub-request is fine, the second aims at read-only file 2: nothing is written.
    const QByteArray request = pduOf(RequestBuilder::writeFileRecord({{1, 0, {0xAAAA}, 6}, {2, 0, {0xBBBB}, 6}}));
    QCOMPARE(hexOf(processor.process(request).pdu), hexOf(ex(0x15, 2)));
    QCOMPARE(unit->fileRecords(1).first(), quint16(0x0100));
    QCOMPARE(unit->fileRecords(2).first(), quint16(0x0200));
}

void TestSimRecords::deviceIdPaging()
{
    SimUnit unit(1);
    unit.setDeviceIdObject(0, "A");
    unit.setDeviceIdObject(1, "B");
    unit.setDeviceIdObject(2, "C");
    for (int id = 0x80; id <= 0x83; ++id)
        unit.setDeviceIdObject(quint8(id), QByteArray(100, char('a' + id - 0x80)));
    SimProcessor processor(&unit);
    // 7 header bytes + 3 x 3 + 2 x 102 = 220; a third 102-byte object would make 322 > 253.
    const QList<DeviceIdObject> first = {{0, "A"}, {1, "B"}, {2, "C"}, {0x80, QByteArray(100, 'a')}, {0x81, QByteArray(100, 'b')}};
    SimReply reply = processor.process(hex("2B 0E 03 00"));
    QCOMPARE(hexOf(reply.pdu), hexOf(deviceId(3, 0x83, true, 0x82, first)));
    // The client asks again from the next object id.
    reply = processor.process(hex("2B 0E 03 82"));
    const QList<DeviceIdObject> second = {{0x82, QByteArray(100, 'c')}, {0x83, QByteArray(100, 'd')}};
    QCOMPARE(hexOf(reply.pdu), hexOf(deviceId(3, 0x83, false, 0, second)));
    // Basic stream access is not affected by the extended objects.
    reply = processor.process(hex("2B 0E 01 00"));
    QCOMPARE(hexOf(reply.pdu), hexOf(deviceId(1, 0x83, false, 0, first.mid(0, 3))));
}

void TestSimRecords::deviceIdLongObject()
{
    // An object longer than a response can carry is cut to 244 bytes (253 - 7 header - 2).
    SimUnit unit(1);
    unit.setDeviceIdObject(0, QByteArray(250, 'x'));
    unit.setDeviceIdObject(1, "B");
    SimProcessor processor(&unit);
    SimReply reply = processor.process(hex("2B 0E 01 00"));
    QCOMPARE(hexOf(reply.pdu), hexOf(deviceId(1, 0x81, true, 1, {{0, QByteArray(244, 'x')}})));
    QCOMPARE(reply.pdu.size(), 253);
    reply = processor.process(hex("2B 0E 01 01"));
    QCOMPARE(hexOf(reply.pdu), hexOf(deviceId(1, 0x81, false, 0, {{1, "B"}})));
}

void TestSimRecords::deviceIdWithoutIndividualAccess()
{
    SimUnit unit(1);
    unit.setDeviceIdObject(0, "A");
    unit.setConformityLevel(0x01); // basic, stream access only
    SimProcessor processor(&unit);
    QCOMPARE(hexOf(processor.process(hex("2B 0E 04 00")).pdu), hexOf(ex(0x2B, 3)));
    QCOMPARE(hexOf(processor.process(hex("2B 0E 01 00")).pdu), hexOf(deviceId(1, 0x01, false, 0, {{0, "A"}})));
    SimUnit empty(2);
    SimProcessor none(&empty);
    QCOMPARE(hexOf(none.process(hex("2B 0E 01 00")).pdu), hexOf(ex(0x2B, 2)));
}

QTEST_GUILESS_MAIN(TestSimRecords)
#include "tst_simrecords.moc"
