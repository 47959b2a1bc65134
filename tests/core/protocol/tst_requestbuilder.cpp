#include "protocol/requestbuilder.h"

#include "protocol/functioncode.h"
#include "protocol/functionspec.h"

#include "buildertesting.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace buildertest;

// Request PDUs built from parameters. Expected bytes are the examples printed in the MODBUS
// Application Protocol Specification V1.1b3 (section 6.x) where it gives one; every limit is
// checked at its edge (valid) and just past it (an error naming the parameter).
namespace {

QList<FileRecordRead> reads(int count, int length)
{
    QList<FileRecordRead> list;
    for (int i = 0; i < count; ++i)
        list.append(FileRecordRead{i + 1, i, length});
    return list;
}

} // namespace

class TestRequestBuilder : public QObject
{
    Q_OBJECT
private slots:
    void bytes_data();
    void bytes();
    void limits_data();
    void limits();
    void errorsAreAllCollected();
    void errorStringNamesEveryParameter();
    void functionTable_data();
    void functionTable();
};

void TestRequestBuilder::bytes_data()
{
    bytesColumns();

    // 6.1-6.4 examples, and the RosRao request of the field publications.
    addBytes(RequestBuilder::readCoils(0x13, 0x13), hex("01 00 13 00 13"));
    addBytes(RequestBuilder::readDiscreteInputs(0xC4, 0x16), hex("02 00 C4 00 16"));
    addBytes(RequestBuilder::readHoldingRegisters(0x6B, 3), hex("03 00 6B 00 03"));
    addBytes(RequestBuilder::readHoldingRegisters(0x79, 0x16), hex("03 00 79 00 16"));
    addBytes(RequestBuilder::readHoldingRegisters(0xFFFF, 1), hex("03 FF FF 00 01"));
    addBytes(RequestBuilder::readInputRegisters(8, 1), hex("04 00 08 00 01"));
    addBytes(RequestBuilder::readInputRegisters(0, 125), hex("04 00 00 00 7D"));
    // 6.5, 6.6
    addBytes(RequestBuilder::writeSingleCoil(0xAC, true), hex("05 00 AC FF 00"));
    addBytes(RequestBuilder::writeSingleCoil(0xAC, false), hex("05 00 AC 00 00"));
    addBytes(RequestBuilder::writeSingleCoilValue(0xAC, 0xFF00), hex("05 00 AC FF 00"), "raw value");
    addBytes(RequestBuilder::writeSingleRegister(1, 3), hex("06 00 01 00 03"));
    addBytes(RequestBuilder::writeSingleRegister(0x1234, 0xABCD), hex("06 12 34 AB CD"));
    // 6.7-6.10, 6.13: no data
    addBytes(RequestBuilder::readExceptionStatus(), hex("07"));
    addBytes(RequestBuilder::getCommEventCounter(), hex("0B"));
    addBytes(RequestBuilder::getCommEventLog(), hex("0C"));
    addBytes(RequestBuilder::reportServerId(), hex("11"));
    // 6.8.1: every sub-function
    addBytes(RequestBuilder::diagnostics(0x00, hex("A5 37")), hex("08 00 00 A5 37"));
    addBytes(RequestBuilder::diagnostics(0x00, hex("01 02 03 04")), hex("08 00 00 01 02 03 04"));
    addBytes(RequestBuilder::diagnostics(0x00, QByteArray()), hex("08 00 00"));
    addBytes(RequestBuilder::restartCommunications(false), hex("08 00 01 00 00"));
    addBytes(RequestBuilder::restartCommunications(true), hex("08 00 01 FF 00"));
    addBytes(RequestBuilder::diagnostics(0x02), hex("08 00 02 00 00"));
    addBytes(RequestBuilder::changeAsciiInputDelimiter(0x3B), hex("08 00 03 3B 00"));
    addBytes(RequestBuilder::diagnostics(0x03, hex("0D 00")), hex("08 00 03 0D 00"));
    addBytes(RequestBuilder::diagnostics(0x04), hex("08 00 04 00 00"));
    for (int sub = 0x0A; sub <= 0x12; ++sub) {
        QByteArray expected = hex("08 00 00 00 00");
        expected[2] = char(sub);
        addBytes(RequestBuilder::diagnostics(sub), expected);
    }
    addBytes(RequestBuilder::diagnostics(0x14, hex("00 00")), hex("08 00 14 00 00"));
    // 6.11, 6.12
    addBytes(RequestBuilder::writeMultipleCoils(0x13, bits("1011001110")), hex("0F 00 13 00 0A 02 CD 01"));
    addBytes(RequestBuilder::writeMultipleCoils(0, bits("1")), hex("0F 00 00 00 01 01 01"));
    addBytes(RequestBuilder::writeMultipleCoils(0xFFFF, bits("0")), hex("0F FF FF 00 01 01 00"));
    addBytes(RequestBuilder::writeMultipleCoils(7, bits("11111111")), hex("0F 00 07 00 08 01 FF"));
    addBytes(RequestBuilder::writeMultipleCoils(7, bits("000000001")), hex("0F 00 07 00 09 02 00 01"));
    addBytes(RequestBuilder::writeMultipleRegisters(1, {0x000A, 0x0102}), hex("10 00 01 00 02 04 00 0A 01 02"));
    // 6.14, 6.15
    addBytes(RequestBuilder::readFileRecord({FileRecordRead{4, 1, 2}, FileRecordRead{3, 9, 2}}),
             hex("14 0E 06 00 04 00 01 00 02 06 00 03 00 09 00 02"));
    addBytes(RequestBuilder::readFileRecord({FileRecordRead{0xFFFF, 9999, 1}}), hex("14 07 06 FF FF 27 0F 00 01"));
    addBytes(RequestBuilder::writeFileRecord({FileRecordWrite{4, 7, {0x06AF, 0x04BE, 0x100D}}}),
             hex("15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D"));
    addBytes(RequestBuilder::writeFileRecord({FileRecordWrite{1, 0, {0x1111}}, FileRecordWrite{2, 5, {0x2222}}}),
             hex("15 12 06 00 01 00 00 00 01 11 11 06 00 02 00 05 00 01 22 22"));
    // 6.16-6.18
    addBytes(RequestBuilder::maskWriteRegister(4, 0xF2, 0x25), hex("16 00 04 00 F2 00 25"));
    addBytes(RequestBuilder::readWriteMultipleRegisters(3, 6, 0x0E, {0xFF, 0xFF, 0xFF}),
             hex("17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF"));
    addBytes(RequestBuilder::readFifoQueue(0x04DE), hex("18 04 DE"));
    // 6.19-6.21
    addBytes(RequestBuilder::readDeviceIdentification(1, 0), hex("2B 0E 01 00"));
    addBytes(RequestBuilder::readDeviceIdentification(2, 3), hex("2B 0E 02 03"));
    addBytes(RequestBuilder::readDeviceIdentification(3, 0x80), hex("2B 0E 03 80"));
    addBytes(RequestBuilder::readDeviceIdentification(4, 0xFF), hex("2B 0E 04 FF"));
    addBytes(RequestBuilder::canopenGeneralReference(hex("00 01 02")), hex("2B 0D 00 01 02"));
    addBytes(RequestBuilder::canopenGeneralReference(QByteArray()), hex("2B 0D"));
    addBytes(RequestBuilder::encapsulatedInterface(0x0E, hex("01 00")), hex("2B 0E 01 00"), "generic MEI");
    // 5.1: user-defined codes, and anything at all through raw()
    addBytes(RequestBuilder::userDefined(65, hex("DE AD")), hex("41 DE AD"));
    addBytes(RequestBuilder::userDefined(72, QByteArray()), hex("48"));
    addBytes(RequestBuilder::userDefined(100, hex("01")), hex("64 01"));
    addBytes(RequestBuilder::userDefined(110, hex("02 03")), hex("6E 02 03"));
    addBytes(RequestBuilder::raw(0x03, hex("00 00 00 00")), hex("03 00 00 00 00"));
    addBytes(RequestBuilder::raw(0x00, QByteArray()), hex("00"));
    addBytes(RequestBuilder::raw(0xFF, hex("01")), hex("FF 01"));
    addBytes(RequestBuilder::raw(0x5A, hex("11 22 33")), hex("5A 11 22 33"));
}

void TestRequestBuilder::bytes()
{
    checkBytes();
}

void TestRequestBuilder::limits_data()
{
    limitsColumns();

    using R = RequestBuilder;
    // 01/02: 1-2000 (V1.1b3, 6.1/6.2)
    addLimit("01 quantity 1", R::readCoils(0, 1));
    addLimit("01 quantity 2000", R::readCoils(0, 2000));
    addLimit("01 quantity 0", R::readCoils(0, 0), "quantity", "quantity 0 is out of range: Read Coils reads 1-2000 coils");
    addLimit("01 quantity 2001", R::readCoils(0, 2001), "quantity", "quantity 2001 is out of range: Read Coils reads 1-2000 coils");
    addLimit("02 quantity 2000", R::readDiscreteInputs(100, 2000));
    addLimit("02 quantity 2001", R::readDiscreteInputs(100, 2001), "quantity",
             "quantity 2001 is out of range: Read Discrete Inputs reads 1-2000 discrete inputs");
    addLimit("02 quantity 0", R::readDiscreteInputs(100, 0), "quantity", "quantity 0 is out of range");
    // start address 0-65535 and the span start + quantity <= 65536 (V1.1b3, 4.4)
    addLimit("01 start 65535", R::readCoils(65535, 1));
    addLimit("01 start 65536", R::readCoils(65536, 1), "startAddress",
             "start address 65536 is out of range: Read Coils addresses are 0-65535");
    addLimit("01 start -1", R::readCoils(-1, 1), "startAddress", "start address -1 is out of range");
    addLimit("01 span ends at 65535", R::readCoils(65536 - 2000, 2000));
    addLimit("01 span ends at 65536", R::readCoils(65537 - 2000, 2000), "quantity",
             "start address 63537 with quantity 2000 ends at 65536, past the last address 65535");
    addLimit("02 span 65535+2", R::readDiscreteInputs(65535, 2), "quantity", "ends at 65536, past the last address 65535");
    // 03/04: 1-125
    addLimit("03 quantity 1", R::readHoldingRegisters(0, 1));
    addLimit("03 quantity 125", R::readHoldingRegisters(0, 125));
    addLimit("03 quantity 0", R::readHoldingRegisters(0, 0), "quantity",
             "quantity 0 is out of range: Read Holding Registers reads 1-125 registers");
    addLimit("03 quantity 126", R::readHoldingRegisters(0, 126), "quantity",
             "quantity 126 is out of range: Read Holding Registers reads 1-125 registers");
    addLimit("03 span ends at 65535", R::readHoldingRegisters(65411, 125));
    addLimit("03 span ends at 65536", R::readHoldingRegisters(65412, 125), "quantity", "past the last address 65535");
    addLimit("03 start 65536", R::readHoldingRegisters(65536, 1), "startAddress", "start address 65536 is out of range");
    addLimit("04 quantity 125", R::readInputRegisters(0, 125));
    addLimit("04 quantity 126", R::readInputRegisters(0, 126), "quantity",
             "quantity 126 is out of range: Read Input Registers reads 1-125 registers");
    addLimit("04 quantity 0", R::readInputRegisters(0, 0), "quantity", "quantity 0 is out of range");
    // 05: FF00 or 0000 only (V1.1b3, 6.5)
    addLimit("05 value FF00", R::writeSingleCoilValue(0, 0xFF00));
    addLimit("05 value 0000", R::writeSingleCoilValue(0, 0x0000));
    addLimit("05 value 0001", R::writeSingleCoilValue(0, 0x0001), "value",
             "value 1 (0x0001) is not a coil value: Write Single Coil accepts only 0xFF00 (ON) or 0x0000 (OFF)");
    addLimit("05 value FF01", R::writeSingleCoilValue(0, 0xFF01), "value", "(0xFF01) is not a coil value");
    addLimit("05 value FEFF", R::writeSingleCoilValue(0, 0xFEFF), "value", "(0xFEFF) is not a coil value");
    addLimit("05 value FFFF", R::writeSingleCoilValue(0, 0xFFFF), "value", "(0xFFFF) is not a coil value");
    addLimit("05 address 65535", R::writeSingleCoil(65535, true));
    addLimit("05 address 65536", R::writeSingleCoil(65536, true), "address",
             "address 65536 is out of range: Write Single Coil addresses are 0-65535");
    // 06: 16-bit address and value
    addLimit("06 value 65535", R::writeSingleRegister(65535, 65535));
    addLimit("06 value 65536", R::writeSingleRegister(0, 65536), "value",
             "value 65536 is out of range: Write Single Register takes a 16-bit value, 0-65535");
    addLimit("06 value -1", R::writeSingleRegister(0, -1), "value", "value -1 is out of range");
    addLimit("06 address 65536", R::writeSingleRegister(65536, 0), "address", "address 65536 is out of range");
    // 0F: 1-1968 (V1.1b3, 6.11)
    addLimit("0F quantity 1", R::writeMultipleCoils(0, QList<bool>(1, true)));
    addLimit("0F quantity 1968", R::writeMultipleCoils(0, QList<bool>(1968, true)));
    addLimit("0F quantity 0", R::writeMultipleCoils(0, {}), "values",
             "quantity 0 is out of range: Write Multiple Coils writes 1-1968 coils");
    addLimit("0F quantity 1969", R::writeMultipleCoils(0, QList<bool>(1969, true)), "values",
             "quantity 1969 is out of range: Write Multiple Coils writes 1-1968 coils");
    addLimit("0F span ends at 65535", R::writeMultipleCoils(65536 - 1968, QList<bool>(1968, false)));
    addLimit("0F span ends at 65536", R::writeMultipleCoils(65537 - 1968, QList<bool>(1968, false)), "values",
             "past the last address 65535");
    addLimit("0F start 65536", R::writeMultipleCoils(65536, QList<bool>(1, false)), "startAddress", "start address 65536");
    // 10: 1-123 (V1.1b3, 6.12)
    addLimit("10 quantity 123", R::writeMultipleRegisters(0, words(123)));
    addLimit("10 quantity 124", R::writeMultipleRegisters(0, words(124)), "values",
             "quantity 124 is out of range: Write Multiple Registers writes 1-123 registers");
    addLimit("10 quantity 0", R::writeMultipleRegisters(0, {}), "values", "quantity 0 is out of range");
    addLimit("10 span ends at 65535", R::writeMultipleRegisters(65535, words(1)));
    addLimit("10 span ends at 65536", R::writeMultipleRegisters(65535, words(2)), "values", "past the last address 65535");
    // 16
    addLimit("16 masks FFFF", R::maskWriteRegister(65535, 0xFFFF, 0xFFFF));
    addLimit("16 and mask 65536", R::maskWriteRegister(0, 65536, 0), "andMask", "AND mask 65536 is out of range");
    addLimit("16 or mask -1", R::maskWriteRegister(0, 0, -1), "orMask", "OR mask -1 is out of range");
    addLimit("16 address 65536", R::maskWriteRegister(65536, 0, 0), "address", "address 65536 is out of range");
    // 17: read 1-125, write 1-121 (V1.1b3, 6.17)
    addLimit("17 read 125 write 121", R::readWriteMultipleRegisters(0, 125, 0, words(121)));
    addLimit("17 read 1 write 1", R::readWriteMultipleRegisters(0, 1, 0, words(1)));
    addLimit("17 read 126", R::readWriteMultipleRegisters(0, 126, 0, words(1)), "readQuantity",
             "read quantity 126 is out of range: Read/Write Multiple Registers reads 1-125 registers");
    addLimit("17 read 0", R::readWriteMultipleRegisters(0, 0, 0, words(1)), "readQuantity", "read quantity 0 is out of range");
    addLimit("17 write 122", R::readWriteMultipleRegisters(0, 1, 0, words(122)), "writeValues",
             "write quantity 122 is out of range: Read/Write Multiple Registers writes 1-121 registers");
    addLimit("17 write 0", R::readWriteMultipleRegisters(0, 1, 0, {}), "writeValues", "write quantity 0 is out of range");
    addLimit("17 read span 65536", R::readWriteMultipleRegisters(65535, 2, 0, words(1)), "readQuantity",
             "read start address 65535 with quantity 2 ends at 65536");
    addLimit("17 write span 65536", R::readWriteMultipleRegisters(0, 1, 65535, words(2)), "writeValues",
             "write start address 65535 with quantity 2 ends at 65536");
    addLimit("17 write span 65535", R::readWriteMultipleRegisters(65535, 1, 65535, words(1)));
    addLimit("17 write start 65536", R::readWriteMultipleRegisters(0, 1, 65536, words(1)), "writeStartAddress",
             "write start address 65536 is out of range");
    // 18
    addLimit("18 address 65535", R::readFifoQueue(65535));
    addLimit("18 address 65536", R::readFifoQueue(65536), "fifoAddress", "FIFO pointer address 65536 is out of range");
    // 08: sub-functions and their data (V1.1b3, 6.8.1)
    addLimit("08 sub 05 reserved", R::diagnostics(0x05), "subFunction",
             "sub-function 5 (0x0005) is reserved: Diagnostics defines 0x00-0x04, 0x0A-0x12 and 0x14");
    addLimit("08 sub 09 reserved", R::diagnostics(0x09), "subFunction", "(0x0009) is reserved");
    addLimit("08 sub 13 reserved", R::diagnostics(0x13), "subFunction", "(0x0013) is reserved");
    addLimit("08 sub 15 reserved", R::diagnostics(0x15), "subFunction", "(0x0015) is reserved");
    addLimit("08 sub FFFF reserved", R::diagnostics(0xFFFF), "subFunction", "(0xFFFF) is reserved");
    addLimit("08 sub 65536", R::diagnostics(0x10000), "subFunction", "sub-function 65536 is out of range");
    addLimit("08 00 data 250 bytes", R::diagnostics(0x00, QByteArray(250, 'x')));
    addLimit("08 00 data 252 bytes", R::diagnostics(0x00, QByteArray(252, 'x')), "data",
             "data of 252 bytes does not fit: a PDU holds at most 253 bytes, which leaves 250 bytes");
    addLimit("08 00 odd data", R::diagnostics(0x00, hex("A5")), "data",
             "data of 1 bytes is not allowed: Return Query Data (sub-function 0x0000) takes whole 16-bit words");
    addLimit("08 01 data 12 34", R::diagnostics(0x01, hex("12 34")), "data",
             "data 12 34 is not allowed: Restart Communications Option (sub-function 0x0001) takes 00 00");
    addLimit("08 01 data FF 01", R::diagnostics(0x01, hex("FF 01")), "data", "data FF 01 is not allowed");
    addLimit("08 02 data 00 01", R::diagnostics(0x02, hex("00 01")), "data",
             "data 00 01 is not allowed: Return Diagnostic Register (sub-function 0x0002) takes 00 00");
    addLimit("08 03 data 0A 01", R::diagnostics(0x03, hex("0A 01")), "data",
             "data 0A 01 is not allowed: Change ASCII Input Delimiter (sub-function 0x0003) takes the delimiter "
             "character followed by 00");
    addLimit("08 03 delimiter 255", R::changeAsciiInputDelimiter(255));
    addLimit("08 03 delimiter 256", R::changeAsciiInputDelimiter(256), "character", "delimiter character 256 is out of range");
    addLimit("08 04 data 00", R::diagnostics(0x04, hex("00")), "data", "data 00 is not allowed: Force Listen Only Mode");
    addLimit("08 0A no data", R::diagnostics(0x0A, QByteArray()), "data",
             "data (none) is not allowed: Clear Counters and Diagnostic Register (sub-function 0x000A) takes 00 00");
    addLimit("08 0B data 00 00 00", R::diagnostics(0x0B, hex("00 00 00")), "data", "Return Bus Message Count");
    addLimit("08 12 data 01 00", R::diagnostics(0x12, hex("01 00")), "data", "Return Bus Character Overrun Count");
    addLimit("08 14 data FF 00", R::diagnostics(0x14, hex("FF 00")), "data", "Clear Overrun Counter and Flag");
    // 14: 1-35 sub-requests, reference type 6, file 1-65535, record 0-9999, response within 253 bytes
    addLimit("14 35 sub-requests", R::readFileRecord(reads(35, 1)));
    addLimit("14 36 sub-requests", R::readFileRecord(reads(36, 1)), "subRequests",
             "36 sub-requests need a byte count of 252: Read File Record allows 7-245 (0x07-0xF5)");
    addLimit("14 no sub-request", R::readFileRecord({}), "subRequests", "no sub-requests: Read File Record needs 1-35");
    addLimit("14 reference type 5", R::readFileRecord({FileRecordRead{1, 0, 1, 5}}), "subRequests[0].referenceType",
             "reference type 5 is out of range: Read File Record requires reference type 6");
    addLimit("14 file 0", R::readFileRecord({FileRecordRead{0, 0, 1}}), "subRequests[0].fileNumber",
             "file number 0 is out of range: Read File Record addresses files 1-65535");
    addLimit("14 file 65535", R::readFileRecord({FileRecordRead{65535, 0, 1}}));
    addLimit("14 file 65536", R::readFileRecord({FileRecordRead{1, 0, 1}, FileRecordRead{65536, 0, 1}}),
             "subRequests[1].fileNumber", "file number 65536 is out of range");
    addLimit("14 record 9999", R::readFileRecord({FileRecordRead{1, 9999, 1}}));
    addLimit("14 record 10000", R::readFileRecord({FileRecordRead{1, 10000, 1}}), "subRequests[0].recordNumber",
             "record number 10000 is out of range: Read File Record addresses records 0-9999 (0x0000-0x270F)");
    addLimit("14 record -1", R::readFileRecord({FileRecordRead{1, -1, 1}}), "subRequests[0].recordNumber",
             "record number -1 is out of range");
    addLimit("14 length 0", R::readFileRecord({FileRecordRead{1, 0, 0}}), "subRequests[0].recordLength",
             "record length 0 is out of range: Read File Record reads 1-124 registers per sub-request");
    addLimit("14 length 124", R::readFileRecord({FileRecordRead{1, 0, 124}}));
    addLimit("14 length 125", R::readFileRecord({FileRecordRead{1, 0, 125}}), "subRequests[0].recordLength",
             "record length 125 is out of range");
    addLimit("14 record 9998 length 2", R::readFileRecord({FileRecordRead{1, 9998, 2}}));
    addLimit("14 record 9999 length 2", R::readFileRecord({FileRecordRead{1, 9999, 2}}), "subRequests[0].recordLength",
             "record number 9999 with record length 2 ends at record 10000, past the last record 9999");
    addLimit("14 response 252 bytes", R::readFileRecord({FileRecordRead{1, 0, 62}, FileRecordRead{2, 0, 61}}));
    addLimit("14 response 254 bytes", R::readFileRecord({FileRecordRead{1, 0, 62}, FileRecordRead{2, 0, 62}}),
             "subRequests", "the response would be 254 bytes");
    // 15: request data length 9-251
    addLimit("15 122 registers", R::writeFileRecord({FileRecordWrite{1, 0, words(122)}}));
    addLimit("15 123 registers", R::writeFileRecord({FileRecordWrite{1, 0, words(123)}}), "subRequests[0].values",
             "record length 123 is out of range: Write File Record writes 1-122 registers per sub-request");
    addLimit("15 no registers", R::writeFileRecord({FileRecordWrite{1, 0, {}}}), "subRequests[0].values",
             "record length 0 is out of range");
    addLimit("15 no sub-request", R::writeFileRecord({}), "subRequests", "no sub-requests: Write File Record");
    addLimit("15 data length 250", R::writeFileRecord({FileRecordWrite{1, 0, words(60)}, FileRecordWrite{2, 0, words(58)}}));
    addLimit("15 data length 252", R::writeFileRecord({FileRecordWrite{1, 0, words(60)}, FileRecordWrite{2, 0, words(59)}}),
             "subRequests", "request data length 252 is out of range: Write File Record allows 9-251 (0x09-0xFB)");
    addLimit("15 reference type 7", R::writeFileRecord({FileRecordWrite{1, 0, words(1), 7}}), "subRequests[0].referenceType",
             "reference type 7 is out of range: Write File Record requires reference type 6");
    addLimit("15 file 0", R::writeFileRecord({FileRecordWrite{0, 0, words(1)}}), "subRequests[0].fileNumber",
             "file number 0 is out of range");
    addLimit("15 record 9999 length 2", R::writeFileRecord({FileRecordWrite{1, 9999, words(2)}}), "subRequests[0].values",
             "past the last record 9999");
    // 2B/0E: read device ID code 1-4, object ID 0-255
    addLimit("2B0E code 1", R::readDeviceIdentification(1, 0));
    addLimit("2B0E code 4", R::readDeviceIdentification(4, 0));
    addLimit("2B0E code 0", R::readDeviceIdentification(0, 0), "readDeviceIdCode",
             "read device ID code 0 is out of range: Read Device Identification takes 1-4");
    addLimit("2B0E code 5", R::readDeviceIdentification(5, 0), "readDeviceIdCode", "read device ID code 5 is out of range");
    addLimit("2B0E object 255", R::readDeviceIdentification(4, 255));
    addLimit("2B0E object 256", R::readDeviceIdentification(4, 256), "objectId", "object ID 256 is out of range");
    // 2B/0D and generic MEI: 253-byte PDU
    addLimit("2B0D data 251", R::canopenGeneralReference(QByteArray(251, 'x')));
    addLimit("2B0D data 252", R::canopenGeneralReference(QByteArray(252, 'x')), "data",
             "data of 252 bytes does not fit: a PDU holds at most 253 bytes, which leaves 251 bytes");
    addLimit("2B MEI 256", R::encapsulatedInterface(256, {}), "meiType", "MEI type 256 is out of range");
    // user-defined 65-72, 100-110
    addLimit("user 64", R::userDefined(64, {}), "functionCode",
             "function code 64 is not user-defined: user-defined function codes are 65-72 (0x41-0x48) and 100-110");
    addLimit("user 65", R::userDefined(65, {}));
    addLimit("user 72", R::userDefined(72, {}));
    addLimit("user 73", R::userDefined(73, {}), "functionCode", "function code 73 is not user-defined");
    addLimit("user 99", R::userDefined(99, {}), "functionCode", "function code 99 is not user-defined");
    addLimit("user 100", R::userDefined(100, {}));
    addLimit("user 110", R::userDefined(110, {}));
    addLimit("user 111", R::userDefined(111, {}), "functionCode", "function code 111 is not user-defined");
    addLimit("user data 252", R::userDefined(65, QByteArray(252, 'x')));
    addLimit("user data 253", R::userDefined(65, QByteArray(253, 'x')), "data",
             "data of 253 bytes does not fit: a PDU holds at most 253 bytes, which leaves 252 bytes for it (function "
             "code 0x41, User-defined function)");
    // raw: any code, any data within 253 bytes
    addLimit("raw code 255", R::raw(255, {}));
    addLimit("raw code 256", R::raw(256, {}), "functionCode", "function code 256 is out of range");
    addLimit("raw code -1", R::raw(-1, {}), "functionCode", "function code -1 is out of range");
    addLimit("raw data 252", R::raw(0x03, QByteArray(252, 'x')));
    addLimit("raw data 253", R::raw(0x03, QByteArray(253, 'x')), "data", "data of 253 bytes does not fit");
}

void TestRequestBuilder::limits()
{
    checkLimit();
}

void TestRequestBuilder::errorsAreAllCollected()
{
    const BuildResult result = RequestBuilder::readHoldingRegisters(70000, 0);
    QCOMPARE(result.errors.size(), 2);
    QVERIFY(result.hasError(u"startAddress"));
    QVERIFY(result.hasError(u"quantity"));
    const BuildResult files = RequestBuilder::readFileRecord({FileRecordRead{0, 10000, 0, 5}});
    QCOMPARE(files.errors.size(), 4);
    QVERIFY(files.pdu.isEmpty());
}

void TestRequestBuilder::errorStringNamesEveryParameter()
{
    const BuildResult result = RequestBuilder::maskWriteRegister(-1, 65536, 0);
    QCOMPARE(result.errorString(),
             QStringLiteral("address: address -1 is out of range: Mask Write Register addresses are 0-65535 "
                            "(0x0000-0xFFFF); andMask: AND mask 65536 is out of range: Mask Write Register takes a "
                            "16-bit value, 0-65535 (0x0000-0xFFFF)"));
    QVERIFY(RequestBuilder::readCoils(0, 1).errorString().isEmpty());
}

// The function table (functionspec.h) against the builders: the request the builder makes for
// each public function has the table's shape, and a quantity is accepted at the table's limit
// and refused one past it.
namespace {

BuildResult buildWith(quint8 code, int quantity)
{
    const QList<quint16> registers(quantity, 0);
    switch (code) {
    case 0x01: return RequestBuilder::readCoils(0, quantity);
    case 0x02: return RequestBuilder::readDiscreteInputs(0, quantity);
    case 0x03: return RequestBuilder::readHoldingRegisters(0, quantity);
    case 0x04: return RequestBuilder::readInputRegisters(0, quantity);
    case 0x05: return RequestBuilder::writeSingleCoil(0, true);
    case 0x06: return RequestBuilder::writeSingleRegister(0, 1);
    case 0x07: return RequestBuilder::readExceptionStatus();
    case 0x0B: return RequestBuilder::getCommEventCounter();
    case 0x0C: return RequestBuilder::getCommEventLog();
    case 0x0F: return RequestBuilder::writeMultipleCoils(0, QList<bool>(quantity, true));
    case 0x10: return RequestBuilder::writeMultipleRegisters(0, registers);
    case 0x11: return RequestBuilder::reportServerId();
    case 0x16: return RequestBuilder::maskWriteRegister(0, 0xFFFF, 0);
    case 0x17: return RequestBuilder::readWriteMultipleRegisters(0, quantity, 0, {1});
    case 0x18: return RequestBuilder::readFifoQueue(0);
    default: return {};
    }
}

// The request's length after the function code that the shape implies (-1: it varies).
int shapeLength(RequestShape shape, int quantity, quint8 code)
{
    switch (shape) {
    case RequestShape::Bare: return 0;
    case RequestShape::Range: return 4;
    case RequestShape::Single: return 4;
    case RequestShape::Mask: return 6;
    case RequestShape::Pointer: return 2;
    case RequestShape::RangeValues: return 5 + (code == 0x0F ? (quantity + 7) / 8 : 2 * quantity);
    case RequestShape::ReadWrite: return 9 + 2; // one value written
    default: return -1;
    }
}

} // namespace

void TestRequestBuilder::functionTable_data()
{
    QTest::addColumn<int>("index");
    for (int i = 0; i < int(std::size(kFunctionSpecs)); ++i)
        QTest::newRow(kFunctionSpecs[i].name) << i;
}

void TestRequestBuilder::functionTable()
{
    QFETCH(int, index);
    const FunctionSpec &spec = kFunctionSpecs[index];
    QCOMPARE(functionSpec(spec.code), &spec);
    QCOMPARE(functionKind(spec.code), FunctionKind::Public);
    QCOMPARE(QByteArray(functionName(spec.code)), QByteArray(spec.name));
    const QByteArray name(spec.name);
    QCOMPARE(spec.writes, name.contains("Write"));
    QCOMPARE(QByteArray(spec.clause).startsWith("6."), true);
    QCOMPARE(spec.maxQuantity > 0, spec.unit != nullptr);

    const int quantity = spec.maxQuantity > 0 ? spec.maxQuantity : 1;
    const BuildResult built = buildWith(spec.code, quantity);
    if (built.pdu.isEmpty() && built.isValid())
        QSKIP("no one-call builder for this function's variable request (08, 14, 15, 2B): the dissector tests cover it");
    QVERIFY2(built.isValid(), qPrintable(built.errorString()));
    QCOMPARE(quint8(built.pdu.at(0)), spec.code);
    QCOMPARE(int(built.pdu.size()) - 1, shapeLength(spec.shape, quantity, spec.code));
    if (spec.maxQuantity > 0) {
        const BuildResult over = buildWith(spec.code, spec.maxQuantity + 1);
        QVERIFY2(!over.isValid(), "one past the table's limit was accepted");
    }
}

QTEST_GUILESS_MAIN(TestRequestBuilder)
#include "tst_requestbuilder.moc"
