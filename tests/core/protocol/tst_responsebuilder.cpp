#include "protocol/functioncode.h"
#include "protocol/responsebuilder.h"

#include "buildertesting.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace buildertest;

// Response PDUs built from values, as the simulator answers. Expected bytes are the examples of
// the MODBUS Application Protocol Specification V1.1b3 (section 6.x) where it prints one.
namespace {

QList<QList<quint16>> records(int count, int length)
{
    return QList<QList<quint16>>(count, words(length));
}

} // namespace

class TestResponseBuilder : public QObject
{
    Q_OBJECT
private slots:
    void bytes_data();
    void bytes();
    void exceptions_data();
    void exceptions();
    void limits_data();
    void limits();
};

void TestResponseBuilder::bytes_data()
{
    bytesColumns();

    using R = ResponseBuilder;
    // 6.1, 6.2: coils 20-38 (CD 6B 05), inputs 197-218 (AC DB 35); unused high bits are zero
    addBytes(R::readCoils(bits("1011001111010110101")), hex("01 03 CD 6B 05"));
    addBytes(R::readCoils(bits("1")), hex("01 01 01"));
    addBytes(R::readCoils(bits("00000001")), hex("01 01 80"));
    addBytes(R::readCoils(bits("000000001")), hex("01 02 00 01"));
    addBytes(R::readDiscreteInputs(bits("0011010111011011101011")), hex("02 03 AC DB 35"));
    // 6.3, 6.4
    addBytes(R::readHoldingRegisters({0x022B, 0x0000, 0x0064}), hex("03 06 02 2B 00 00 00 64"));
    addBytes(R::readInputRegisters({0x000A}), hex("04 02 00 0A"));
    // 6.5, 6.6: echoes
    addBytes(R::writeSingleCoil(0xAC, true), hex("05 00 AC FF 00"));
    addBytes(R::writeSingleCoil(0xAC, false), hex("05 00 AC 00 00"));
    addBytes(R::writeSingleCoilValue(0xAC, 0xFF00), hex("05 00 AC FF 00"), "raw value");
    addBytes(R::writeSingleRegister(1, 3), hex("06 00 01 00 03"));
    // 6.7
    addBytes(R::readExceptionStatus(0x6D), hex("07 6D"));
    addBytes(R::readExceptionStatus(0xFF), hex("07 FF"));
    // 6.8.1: every sub-function that answers
    addBytes(R::diagnostics(0x00, hex("A5 37")), hex("08 00 00 A5 37"));
    addBytes(R::diagnostics(0x00, hex("01 02 03 04")), hex("08 00 00 01 02 03 04"));
    addBytes(R::diagnostics(0x01, hex("FF 00")), hex("08 00 01 FF 00"));
    addBytes(R::diagnostics(0x01, hex("00 00")), hex("08 00 01 00 00"));
    addBytes(R::diagnosticsValue(0x02, 0x8001), hex("08 00 02 80 01"));
    addBytes(R::diagnostics(0x03, hex("3B 00")), hex("08 00 03 3B 00"));
    addBytes(R::diagnosticsValue(0x0A, 0), hex("08 00 0A 00 00"));
    for (int sub = 0x0B; sub <= 0x12; ++sub) {
        QByteArray expected = hex("08 00 00 01 08");
        expected[2] = char(sub);
        addBytes(R::diagnosticsValue(sub, 0x0108), expected);
    }
    addBytes(R::diagnostics(0x14, hex("00 00")), hex("08 00 14 00 00"));
    // 6.9, 6.10
    addBytes(R::getCommEventCounter(true, 0x108), hex("0B FF FF 01 08"));
    addBytes(R::getCommEventCounter(false, 0), hex("0B 00 00 00 00"));
    addBytes(R::getCommEventLog(false, 0x108, 0x121, hex("20 00")), hex("0C 08 00 00 01 08 01 21 20 00"));
    addBytes(R::getCommEventLog(true, 1, 2, QByteArray()), hex("0C 06 FF FF 00 01 00 02"));
    // 6.11, 6.12
    addBytes(R::writeMultipleCoils(0x13, 0x0A), hex("0F 00 13 00 0A"));
    addBytes(R::writeMultipleRegisters(1, 2), hex("10 00 01 00 02"));
    // 6.13
    addBytes(R::reportServerId(hex("42"), true, QByteArray("xyz")), hex("11 05 42 FF 78 79 7A"));
    addBytes(R::reportServerId(hex("01 02"), false), hex("11 03 01 02 00"));
    // 6.14, 6.15
    addBytes(R::readFileRecord({{0x0DFE, 0x0020}, {0x33CD, 0x0040}}), hex("14 0C 05 06 0D FE 00 20 05 06 33 CD 00 40"));
    addBytes(R::readFileRecord({{0x1234}}), hex("14 04 03 06 12 34"));
    addBytes(R::writeFileRecord({FileRecordWrite{4, 7, {0x06AF, 0x04BE, 0x100D}}}),
             hex("15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D"));
    // 6.16-6.18
    addBytes(R::maskWriteRegister(4, 0xF2, 0x25), hex("16 00 04 00 F2 00 25"));
    addBytes(R::readWriteMultipleRegisters({0x00FE, 0x0ACD, 0x0001, 0x0003, 0x000D, 0x00FF}),
             hex("17 0C 00 FE 0A CD 00 01 00 03 00 0D 00 FF"));
    addBytes(R::readFifoQueue({0x01B8, 0x1284}), hex("18 00 06 00 02 01 B8 12 84"));
    addBytes(R::readFifoQueue({}), hex("18 00 02 00 00"));
    // 6.21: stream access in one response, with more to follow, and an individual access
    addBytes(R::readDeviceIdentification(1, 0x01, false, 0,
                                         {{0x00, QByteArray("ACME")}, {0x01, QByteArray("PX-1")}, {0x02, QByteArray("V2.11")}}),
             hex("2B 0E 01 01 00 00 03 00 04 41 43 4D 45 01 04 50 58 2D 31 02 05 56 32 2E 31 31"));
    addBytes(R::readDeviceIdentification(1, 0x81, true, 0x02, {{0x00, QByteArray("A")}, {0x01, QByteArray("B")}}),
             hex("2B 0E 01 81 FF 02 02 00 01 41 01 01 42"));
    addBytes(R::readDeviceIdentification(4, 0x82, false, 0, {{0x80, QByteArray("x")}}), hex("2B 0E 04 82 00 00 01 80 01 78"));
    addBytes(R::readDeviceIdentification(3, 0x83, false, 0, {{0xFF, QByteArray()}}), hex("2B 0E 03 83 00 00 01 FF 00"));
    addBytes(R::canopenGeneralReference(hex("AA BB")), hex("2B 0D AA BB"));
    // 5.1
    addBytes(R::userDefined(0x41, hex("01 02")), hex("41 01 02"));
    addBytes(R::userDefined(0x6E, QByteArray()), hex("6E"));
    addBytes(R::raw(0x09, hex("01")), hex("09 01"));
}

void TestResponseBuilder::bytes()
{
    checkBytes();
}

void TestResponseBuilder::exceptions_data()
{
    QTest::addColumn<int>("function");
    QTest::addColumn<int>("exception");
    // Every public code with every exception code of V1.1b3, 7 (and 07, Modicon's NAK), plus a
    // user-defined code and codes the specification does not define.
    const int functions[] = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x0B, 0x0C,
                             0x0F, 0x10, 0x11, 0x14, 0x15, 0x16, 0x17, 0x18, 0x2B};
    for (int function : functions) {
        for (int exception = 0x01; exception <= 0x0B; ++exception) {
            if (exception == 0x09)
                continue;
            QTest::addRow("%02X %02X", function | 0x80, exception) << function << exception;
        }
    }
    QTest::addRow("C1 01") << 0x41 << 0x01;
    QTest::addRow("FF 04") << 0x7F << 0x04;
    QTest::addRow("83 00") << 0x03 << 0x00;
    QTest::addRow("83 09") << 0x03 << 0x09;
    QTest::addRow("83 FF") << 0x03 << 0xFF;
}

void TestResponseBuilder::exceptions()
{
    QFETCH(int, function);
    QFETCH(int, exception);
    const BuildResult result = ResponseBuilder::exception(function, exception);
    QVERIFY2(result.isValid(), qPrintable(result.errorString()));
    QByteArray expected;
    expected.append(char(function | 0x80));
    expected.append(char(exception));
    QCOMPARE(spaced(result.pdu), spaced(expected));
    QCOMPARE(functionKind(quint8(result.pdu.at(0))), FunctionKind::Exception);
}

void TestResponseBuilder::limits_data()
{
    limitsColumns();

    using R = ResponseBuilder;
    addLimit("01 2000 coils", R::readCoils(QList<bool>(2000, true)));
    addLimit("01 2001 coils", R::readCoils(QList<bool>(2001, true)), "values",
             "quantity 2001 is out of range: Read Coils reads 1-2000 coils");
    addLimit("01 no coils", R::readCoils({}), "values", "quantity 0 is out of range");
    addLimit("02 2000 inputs", R::readDiscreteInputs(QList<bool>(2000, false)));
    addLimit("02 2001 inputs", R::readDiscreteInputs(QList<bool>(2001, false)), "values",
             "quantity 2001 is out of range: Read Discrete Inputs reads 1-2000 discrete inputs");
    addLimit("03 125 registers", R::readHoldingRegisters(words(125)));
    addLimit("03 126 registers", R::readHoldingRegisters(words(126)), "values",
             "quantity 126 is out of range: Read Holding Registers returns 1-125 registers");
    addLimit("03 no registers", R::readHoldingRegisters({}), "values", "quantity 0 is out of range");
    addLimit("04 125 registers", R::readInputRegisters(words(125)));
    addLimit("04 126 registers", R::readInputRegisters(words(126)), "values",
             "quantity 126 is out of range: Read Input Registers returns 1-125 registers");
    addLimit("05 value 0001", R::writeSingleCoilValue(1, 1), "value", "is not a coil value");
    addLimit("06 value 65536", R::writeSingleRegister(1, 65536), "value", "value 65536 is out of range");
    addLimit("07 outputs 255", R::readExceptionStatus(255));
    addLimit("07 outputs 256", R::readExceptionStatus(256), "outputs", "output data 256 is out of range");
    addLimit("08 04 has no response", R::diagnostics(0x04, hex("00 00")), "subFunction",
             "Force Listen Only Mode (sub-function 0x0004) has no response");
    addLimit("08 05 reserved", R::diagnostics(0x05, hex("00 00")), "subFunction", "is reserved");
    addLimit("08 02 one byte", R::diagnostics(0x02, hex("01")), "data",
             "data 01 is not allowed: Return Diagnostic Register (sub-function 0x0002) takes the 2-byte diagnostic register");
    addLimit("08 0E three bytes", R::diagnostics(0x0E, hex("01 02 03")), "data", "takes the 2-byte counter value");
    addLimit("08 0A echo 00 01", R::diagnostics(0x0A, hex("00 01")), "data", "takes 00 00");
    addLimit("08 00 echo 250 bytes", R::diagnostics(0x00, QByteArray(250, 'e')));
    addLimit("08 00 echo 252 bytes", R::diagnostics(0x00, QByteArray(252, 'e')), "data", "data of 252 bytes does not fit");
    addLimit("08 value 65536", R::diagnosticsValue(0x0B, 65536), "value", "value 65536 is out of range");
    addLimit("0B event count 65535", R::getCommEventCounter(false, 65535));
    addLimit("0B event count 65536", R::getCommEventCounter(false, 65536), "eventCount", "event count 65536 is out of range");
    addLimit("0C 64 events", R::getCommEventLog(false, 0, 0, QByteArray(64, '\0')));
    addLimit("0C 65 events", R::getCommEventLog(false, 0, 0, QByteArray(65, '\0')), "events",
             "number of event bytes 65 is out of range: Get Comm Event Log returns 0-64 event bytes");
    addLimit("0C message count 65536", R::getCommEventLog(false, 0, 65536, {}), "messageCount",
             "message count 65536 is out of range");
    addLimit("0F quantity 1968", R::writeMultipleCoils(0, 1968));
    addLimit("0F quantity 1969", R::writeMultipleCoils(0, 1969), "quantity",
             "quantity 1969 is out of range: Write Multiple Coils writes 1-1968 coils");
    addLimit("0F quantity 0", R::writeMultipleCoils(0, 0), "quantity", "quantity 0 is out of range");
    addLimit("0F span 65536", R::writeMultipleCoils(65535, 2), "quantity", "past the last address 65535");
    addLimit("10 quantity 123", R::writeMultipleRegisters(65536 - 123, 123));
    addLimit("10 quantity 124", R::writeMultipleRegisters(0, 124), "quantity",
             "quantity 124 is out of range: Write Multiple Registers writes 1-123 registers");
    addLimit("10 span 65536", R::writeMultipleRegisters(65537 - 123, 123), "quantity", "past the last address 65535");
    addLimit("11 additional 249", R::reportServerId(hex("01"), true, QByteArray(249, 'a')));
    addLimit("11 additional 250", R::reportServerId(hex("01"), true, QByteArray(250, 'a')), "additionalData",
             "server ID, run indicator and additional data of 252 bytes does not fit");
    addLimit("11 no server id", R::reportServerId({}, true), "serverId", "no server ID");
    addLimit("14 35 sub-responses", R::readFileRecord(records(35, 1)));
    addLimit("14 36 sub-responses", R::readFileRecord(records(36, 1)), "records",
             "sub-response count 36 is out of range: Read File Record answers 1-35 sub-requests");
    addLimit("14 no sub-response", R::readFileRecord({}), "records", "sub-response count 0 is out of range");
    addLimit("14 124 registers", R::readFileRecord(records(1, 124)));
    addLimit("14 125 registers", R::readFileRecord(records(1, 125)), "records[0]", "record length 125 is out of range");
    addLimit("14 empty record", R::readFileRecord({{1}, {}}), "records[1]", "record length 0 is out of range");
    addLimit("14 data length 250", R::readFileRecord({words(62), words(61)}));
    addLimit("14 data length 252", R::readFileRecord({words(62), words(62)}), "records",
             "response data length 252 is out of range");
    addLimit("15 echo 123 registers", R::writeFileRecord({FileRecordWrite{1, 0, words(123)}}), "subRequests[0].values",
             "record length 123 is out of range");
    addLimit("16 or mask 65536", R::maskWriteRegister(0, 0, 65536), "orMask", "OR mask 65536 is out of range");
    addLimit("17 125 registers", R::readWriteMultipleRegisters(words(125)));
    addLimit("17 126 registers", R::readWriteMultipleRegisters(words(126)), "values",
             "read quantity 126 is out of range: Read/Write Multiple Registers returns 1-125 registers");
    addLimit("17 no registers", R::readWriteMultipleRegisters({}), "values", "read quantity 0 is out of range");
    addLimit("18 31 values", R::readFifoQueue(words(31)));
    addLimit("18 32 values", R::readFifoQueue(words(32)), "values",
             "FIFO count 32 is out of range: Read FIFO Queue returns 0-31 queued registers");
    // 2B/0E
    const QList<DeviceIdObject> one = {{0x00, QByteArray("A")}};
    addLimit("2B0E code 0", R::readDeviceIdentification(0, 0x01, false, 0, one), "readDeviceIdCode",
             "read device ID code 0 is out of range");
    addLimit("2B0E code 5", R::readDeviceIdentification(5, 0x01, false, 0, one), "readDeviceIdCode",
             "read device ID code 5 is out of range");
    addLimit("2B0E conformity 03", R::readDeviceIdentification(1, 0x03, false, 0, one));
    addLimit("2B0E conformity 04", R::readDeviceIdentification(1, 0x04, false, 0, one), "conformityLevel",
             "conformity level 0x04 is not defined: Read Device Identification uses 0x01-0x03");
    addLimit("2B0E conformity 00", R::readDeviceIdentification(1, 0x00, false, 0, one), "conformityLevel",
             "conformity level 0x00 is not defined");
    addLimit("2B0E conformity 80", R::readDeviceIdentification(1, 0x80, false, 0, one), "conformityLevel",
             "conformity level 0x80 is not defined");
    addLimit("2B0E conformity 83", R::readDeviceIdentification(1, 0x83, false, 0, one));
    addLimit("2B0E conformity 84", R::readDeviceIdentification(1, 0x84, false, 0, one), "conformityLevel",
             "conformity level 0x84 is not defined");
    addLimit("2B0E individual needs 81-83", R::readDeviceIdentification(4, 0x02, false, 0, one), "conformityLevel",
             "conformity level 0x02 does not allow individual access");
    addLimit("2B0E individual more follows", R::readDeviceIdentification(4, 0x82, true, 1, one), "moreFollows",
             "more follows is not allowed for an individual access");
    addLimit("2B0E individual two objects", R::readDeviceIdentification(4, 0x82, false, 0, {one[0], one[0]}), "objects",
             "2 objects is not allowed: an individual access (read device ID code 4) returns exactly one object");
    addLimit("2B0E next object without more", R::readDeviceIdentification(1, 0x01, false, 5, one), "nextObjectId",
             "next object ID 5 is not allowed: when no more objects follow");
    addLimit("2B0E next object 255", R::readDeviceIdentification(1, 0x01, true, 255, one));
    addLimit("2B0E next object 256", R::readDeviceIdentification(1, 0x01, true, 256, one), "nextObjectId",
             "next object ID 256 is out of range");
    addLimit("2B0E object id 256", R::readDeviceIdentification(1, 0x01, false, 0, {{256, QByteArray("A")}}),
             "objects[0].id", "object ID 256 is out of range");
    addLimit("2B0E object 244 bytes", R::readDeviceIdentification(3, 0x03, false, 0, {{0x80, QByteArray(244, 'v')}}));
    addLimit("2B0E object 245 bytes", R::readDeviceIdentification(3, 0x03, false, 0, {{0x80, QByteArray(245, 'v')}}),
             "objects", "the object list of 247 bytes does not fit: a PDU holds at most 253 bytes, which leaves 246 bytes");
    addLimit("2B0E object 256 bytes", R::readDeviceIdentification(3, 0x03, false, 0, {{0x80, QByteArray(256, 'v')}}),
             "objects[0].value", "object length 256 is out of range");
    addLimit("2B0D data 251", R::canopenGeneralReference(QByteArray(251, 'c')));
    addLimit("2B0D data 252", R::canopenGeneralReference(QByteArray(252, 'c')), "data", "data of 252 bytes does not fit");
    // exceptions
    addLimit("exception function 7F", R::exception(0x7F, 1));
    addLimit("exception function 0", R::exception(0, 1), "functionCode",
             "function code 0 is out of range: an exception answers function codes 1-127");
    addLimit("exception function 83", R::exception(0x83, 1), "functionCode",
             "function code 0x83 already has the exception bit set");
    addLimit("exception function 256", R::exception(256, 1), "functionCode", "function code 256 is out of range");
    addLimit("exception code 256", R::exception(3, 256), "exceptionCode", "exception code 256 is out of range");
    addLimit("exception code -1", R::exception(3, -1), "exceptionCode", "exception code -1 is out of range");
    addLimit("user 73", R::userDefined(73, {}), "functionCode", "function code 73 is not user-defined");
    addLimit("raw data 253", R::raw(0x41, QByteArray(253, 'r')), "data", "data of 253 bytes does not fit");
}

void TestResponseBuilder::limits()
{
    checkLimit();
}

QTEST_GUILESS_MAIN(TestResponseBuilder)
#include "tst_responsebuilder.moc"
