#include "pduexpect.h"

#include <QtTest/QtTest>

using namespace mbscope;
using namespace pdutest;

// Dissection of 14 Read File Record, 15 Write File Record, 16 Mask Write Register, 17 Read/Write
// Multiple Registers and 18 Read FIFO Queue, both directions, against MODBUS Application
// Protocol Specification V1.1b3 sections 6.14-6.18 (their worked examples are the "spec" rows).
// Expectations use the notation of pduexpect.h.
class TestPduRecords : public QObject
{
    Q_OBJECT
private slots:
    void readFileRecord_data();
    void readFileRecord() { check(); }
    void writeFileRecord_data();
    void writeFileRecord() { check(); }
    void maskWrite_data();
    void maskWrite() { check(); }
    void readWrite_data();
    void readWrite() { check(); }
    void fifo_data();
    void fifo() { check(); }
};

// A 14 request's sub-request, in the notation: reference type, file, record, length.
#define SUBREQ(ref, file, record, length) \
    "file_subrequest|>reference_type=" #ref "|>file_number=" #file "|>record_number=" #record "|>record_length=" #length

void TestPduRecords::readFileRecord_data()
{
    columns();
    const char *specRequest = "14 0E 06 00 04 00 01 00 02 06 00 03 00 09 00 02";
    req(specRequest, "byte_count=14|" SUBREQ(6, 4, 1, 2) "|" SUBREQ(6, 3, 9, 2), "spec 6.14");
    req("14 07 06 00 04 00 01 00 02", "byte_count=7|" SUBREQ(6, 4, 1, 2));
    req("14 07 07 00 04 00 01 00 02",
        "byte_count=7|file_subrequest|>reference_type=7!E~reference type 7 is not allowed: it must be 6"
        "|>file_number=4|>record_number=1|>record_length=2");
    req("14 07 06 00 00 00 01 00 02",
        "byte_count=7|file_subrequest|>reference_type=6%file record|>file_number=0!W~file number 0: the specification numbers files 1-65535"
        "|>record_number=1|>record_length=2");
    req("14 07 06 00 04 27 10 00 02",
        "byte_count=7|file_subrequest|>reference_type=6|>file_number=4"
        "|>record_number=10000!E~record number 10000 is out of range: a file holds records 0-9999 (0x0000-0x270F)|>record_length=2");
    req("14 07 06 00 04 27 0F 00 01", "byte_count=7|" SUBREQ(6, 4, 9999, 1), "last record");
    req("14 07 06 00 04 27 0F 00 02",
        "byte_count=7|file_subrequest|>reference_type=6|>file_number=4|>record_number=9999"
        "|>record_length=2!W~records 9999-10000 run past record 9999");
    req("14 07 06 00 04 00 01 00 00",
        "byte_count=7|file_subrequest|>reference_type=6|>file_number=4|>record_number=1|>record_length=0!W~record length 0");
    req("14 08 06 00 04 00 01 00 02 06",
        "byte_count=8!E~byte count 8 is not a multiple of 7: each sub-request is 7 bytes|" SUBREQ(6, 4, 1, 2)
        "|file_subrequest|>reference_type=6|>data!E~the byte count ends 1 byte into a sub-request");
    req("14 00", "byte_count=0!E~byte count 0 is out of range: Read File Record allows 7-245 (0x07-0xF5)");
    req("14 F6", "byte_count=246!E~byte count 246 is out of range|missing!E~byte count 246 announces 246 data bytes but only 0 are present");
    req("14 0E 06 00 04 00 01 00 02 06 00 03",
        "byte_count=14|" SUBREQ(6, 4, 1, 2) "|file_subrequest|>reference_type=6|>file_number=3"
        "|>missing!E~missing: byte count 14 announces 14 data bytes but only 10 are present; expected 4 more bytes");
    req("14 0E 06 00 04 00 01 00 02 06 00 03 00",
        "byte_count=14|" SUBREQ(6, 4, 1, 2) "|file_subrequest|>reference_type=6|>file_number=3"
        "|>missing!E%00~only 11 are present; expected 3 more bytes", "cut inside the record number");
    req("14 0E 06 00 04 00 01 00 02",
        "byte_count=14|" SUBREQ(6, 4, 1, 2) "|missing!E~only 7 are present; expected 7 more bytes", "cut between sub-requests");
    req("14 07 06 00 04 00 01 00 02 FF", "byte_count=7|" SUBREQ(6, 4, 1, 2) "|trailing!E~1 byte after the end");
    req("14 0E 06 00 04 00 01 00 64 06 00 03 00 09 00 64",
        "byte_count=14!E~the sub-requests ask for 200 registers: the response would be 406 bytes, more than the 253"
        "|" SUBREQ(6, 4, 1, 100) "|" SUBREQ(6, 3, 9, 100), "response too large");
    req("14", "missing!E~missing: byte count and sub-requests; expected at least 8 more bytes");

    rsp("14 0C 05 06 0D FE 00 20 05 06 33 CD 00 40",
        "byte_count=12|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[3582,32]@1"
        "|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[13261,64]@9",
        specRequest, "spec 6.14");
    rsp("14 0C 05 06 0D FE 00 20 05 06 33 CD 00 40",
        "byte_count=12|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[3582,32]@0"
        "|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[13261,64]@0",
        "", "no request: registers by index");
    rsp("14 0C 05 06 0D FE 00 20 05 06 33 CD 00 40",
        "byte_count=12!E~byte count 12 does not match the request: 14 bytes expected for its 2 sub-requests"
        "|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[3582,32]@1"
        "|file_subresponse|>subresponse_length=5!E~sub-response length 5 does not match the request: sub-request 2 asks for 3 registers, "
        "which need length 7|>reference_type=6|>register_value=[13261,64]@9",
        "14 0E 06 00 04 00 01 00 02 06 00 03 00 09 00 03", "lengths against the request");
    rsp("14 04 04 06 00 01",
        "byte_count=4|file_subresponse|>subresponse_length=4!E~sub-response length 4 is even"
        "|>reference_type=6|>register_value=[1]@0");
    rsp("14 04 05 06 00 01",
        "byte_count=4|file_subresponse|>subresponse_length=5!E~runs past the byte count: only 3 bytes are left"
        "|>reference_type=6|>register_value=[1]@0");
    rsp("14 05 04 06 00 01 00",
        "byte_count=5|file_subresponse|>subresponse_length=4!E~is even|>reference_type=6|>register_value=[1]@0"
        "|>data!E~1 byte left over");
    rsp("14 04 03 07 00 01",
        "byte_count=4|file_subresponse|>subresponse_length=3|>reference_type=7!E~must be 6|>register_value=[1]@0");
    rsp("14 08 03 06 00 01 03 06 00 02",
        "byte_count=8!E~does not match the request: 4 bytes expected for its 1 sub-request"
        "|file_subresponse|>subresponse_length=3|>reference_type=6|>register_value=[1]@1"
        "|file_subresponse!E~no matching sub-request: the request has 1 sub-request|>subresponse_length=3|>reference_type=6"
        "|>register_value=[2]@0",
        "14 07 06 00 04 00 01 00 01", "one sub-response too many");
    rsp("14 04 03 06 00 01",
        "byte_count=4!E~the response carries 1 sub-response but the request has 2 sub-requests"
        "|file_subresponse|>subresponse_length=3|>reference_type=6|>register_value=[1]@1",
        "14 0E 06 00 04 00 01 00 01 06 00 03 00 09 00 01", "one sub-response too few");
    rsp("14 0C 05 06 0D FE 00 20 05 06 33",
        "byte_count=12|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[3582,32]@1"
        "|file_subresponse|>subresponse_length=5|>reference_type=6"
        "|>missing!E~missing: byte count 12 announces 12 data bytes but only 9 are present; expected 3 more bytes",
        specRequest, "truncated");
    rsp("14 0C 05 06 0D FE 00 20 05",
        "byte_count=12|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[3582,32]@0"
        "|file_subresponse|>subresponse_length=5|>missing!E~only 7 are present; expected 5 more bytes",
        "", "cut after a length byte");
    rsp("14 0C 05 06 0D FE 00 20",
        "byte_count=12|file_subresponse|>subresponse_length=5|>reference_type=6|>register_value=[3582,32]@0"
        "|missing!E~only 6 are present; expected 6 more bytes", "", "cut between sub-responses");
    rsp("14 04 03 06 00 01 00", "byte_count=4|file_subresponse|>subresponse_length=3|>reference_type=6|>register_value=[1]"
                                "|trailing!E~1 byte after the end");
    rsp("14 00", "byte_count=0!E~byte count 0 is out of range");
    rsp("14", "missing!E~missing: byte count and sub-responses; expected at least 5 more bytes");
}

void TestPduRecords::writeFileRecord_data()
{
    columns();
    const char *spec = "15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0D";
    const char *fields = "|>reference_type=6|>file_number=4|>record_number=7|>record_length=3|>register_value=[1711,1214,4109]@7";
    req(spec, qPrintable(QStringLiteral("byte_count=13|file_subrequest") + QLatin1String(fields)), "spec 6.15");
    rsp(spec, qPrintable(QStringLiteral("byte_count=13|file_subresponse") + QLatin1String(fields)), spec, "spec 6.15 echo");
    rsp(spec, qPrintable(QStringLiteral("byte_count=13|file_subresponse") + QLatin1String(fields)), "", "spec 6.15, no request");
    rsp("15 0D 06 00 04 00 07 00 03 06 AF 04 BE 10 0E",
        "byte_count=13|file_subresponse|>reference_type=6|>file_number=4|>record_number=7|>record_length=3"
        "|>register_value=[1711,1214]@7|>register_value=4110@9!E~does not match the request: the request's record 9 is 4109",
        spec, "echo differs");
    rsp("15 0D 06 00 05 00 07 00 03 06 AF 04 BE 10 0D",
        "byte_count=13|file_subresponse|>reference_type=6|>file_number=5!E~the request's file number is 4"
        "|>record_number=7|>record_length=3|>register_value=[1711,1214,4109]@7",
        spec, "echo differs in the file number");
    rsp("15 0F 06 00 04 00 07 00 04 06 AF 04 BE 10 0D 00 00",
        "byte_count=15!E~the request's byte count is 13|file_subresponse|>reference_type=6|>file_number=4|>record_number=7"
        "|>record_length=4!E~the request's record length is 3|>register_value=[1711,1214,4109]@7"
        "|>register_value=0@10!E~the request ends before this record 10",
        spec, "echo longer than the request");
    req("15 14 06 00 04 00 07 00 01 00 0A 06 00 05 00 00 00 02 00 0B 00 0C",
        "byte_count=20|file_subrequest|>reference_type=6|>file_number=4|>record_number=7|>record_length=1|>register_value=[10]@7"
        "|file_subrequest|>reference_type=6|>file_number=5|>record_number=0|>record_length=2|>register_value=[11,12]@0",
        "two sub-requests");
    req("15 09 06 00 04 00 07 00 03 06 AF",
        "byte_count=9|file_subrequest|>reference_type=6|>file_number=4|>record_number=7"
        "|>record_length=3!E~record length 3 needs 6 bytes of record data but the byte count leaves 2|>register_value=[1711]@7");
    req("15 0A 06 00 04 00 07 00 03 06 AF 04",
        "byte_count=10|file_subrequest|>reference_type=6|>file_number=4|>record_number=7"
        "|>record_length=3!E~byte count leaves 3|>register_value=[1711]@7|>data!E~1 byte left over");
    req("15 0D 06 00 04 00 07 00 03 06 AF 04",
        "byte_count=13|file_subrequest|>reference_type=6|>file_number=4|>record_number=7|>record_length=3|>register_value=[1711]@7"
        "|>missing!E%04~missing: byte count 13 announces 13 data bytes but only 10 are present; expected 3 more bytes",
        "truncated");
    req("15 0D 06 00 04 00",
        "byte_count=13|file_subrequest|>reference_type=6|>file_number=4|>missing!E%00~only 4 are present; expected 9 more bytes");
    req("15 0C 06 00 04 00 07 00 01 00 0A 06 00 05",
        "byte_count=12|file_subrequest|>reference_type=6|>file_number=4|>record_number=7|>record_length=1|>register_value=[10]@7"
        "|file_subrequest|>reference_type=6|>file_number=5|>data!E~the byte count ends 3 bytes into a sub-request",
        "byte count ends inside a header");
    req("15 08 06 00 04 00 07 00 00 00",
        "byte_count=8!E~byte count 8 is out of range: Write File Record allows 9-251 (0x09-0xFB)"
        "|file_subrequest|>reference_type=6|>file_number=4|>record_number=7|>record_length=0!W"
        "|file_subrequest|>reference_type=0!E|>data!E~the byte count ends 1 byte into");
    req("15 09 06 00 04 00 07 00 00 00 00",
        "byte_count=9|file_subrequest|>reference_type=6|>file_number=4|>record_number=7|>record_length=0!W~record length 0: the sub-request writes no registers"
        "|file_subrequest|>reference_type=0!E~must be 6|>data!E%00~the byte count ends 2 bytes into");
    req("15 09 06 00 04 00 07 00 01 00 0A 00", "byte_count=9|file_subrequest|>reference_type=6|>file_number=4|>record_number=7"
                                               "|>record_length=1|>register_value=[10]@7|trailing!E~1 byte after the end");
    req("15", "missing!E~missing: byte count and sub-requests; expected at least 10 more bytes");
    rsp("15", "missing!E~missing: byte count and sub-requests", spec);
}

void TestPduRecords::maskWrite_data()
{
    columns();
    const char *spec = "16 00 04 00 F2 00 25";
    req(spec, "address=4%4 (0x0004)|and_mask=0xF2%0x00F2 bits kept|or_mask=0x25%0x0025 bits set where the AND mask is 0", "spec 6.16");
    rsp(spec, "address=4|and_mask=0xF2|or_mask=0x25", spec, "spec 6.16 echo");
    rsp(spec, "address=4|and_mask=0xF2|or_mask=0x25", "", "no request");
    rsp("16 00 04 00 F2 00 26", "address=4|and_mask=0xF2|or_mask=0x26!E~does not match the request: the request's OR mask is 0x0025", spec);
    rsp("16 00 05 00 F2 00 25", "address=5!E~the request's reference address is 4 (0x0004)|and_mask=0xF2|or_mask=0x25", spec);
    rsp("16 00 04 00 F3 00 25", "address=4|and_mask=0xF3!E~the request's AND mask is 0x00F2|or_mask=0x25", spec);
    req("16 00 04 FF FF 00 25", "address=4|and_mask=0xFFFF!I~AND mask 0xFFFF keeps every bit|or_mask=0x25");
    req("16 00 04 00 F2 00 25 00", "address=4|and_mask=0xF2|or_mask=0x25|trailing!E~1 byte after the end");
    req("16 00 04 00", "address=4|missing!E%00~missing: AND mask and OR mask; expected 3 more bytes");
    req("16 00 04 00 F2", "address=4|and_mask=0xF2|missing!E~missing: OR mask; expected 2 more bytes");
    req("16", "missing!E~missing: reference address, AND mask and OR mask; expected 6 more bytes");
    rsp("16 00 04 00 F2 00", "address=4|and_mask=0xF2|missing!E~expected 1 more byte", spec);
}

void TestPduRecords::readWrite_data()
{
    columns();
    const char *spec = "17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00 FF";
    req(spec, "read_start_address=3%3 (0x0003)|read_quantity=6|write_start_address=14%14 (0x000E)|write_quantity=3|byte_count=6"
              "|register_value=[255,255,255]@14", "spec 6.17");
    rsp("17 0C 00 FE 0A CD 00 01 00 03 00 0D 00 FF", "byte_count=12|register_value=[254,2765,1,3,13,255]@3", spec, "spec 6.17");
    rsp("17 0C 00 FE 0A CD 00 01 00 03 00 0D 00 FF", "byte_count=12|register_value=[254,2765,1,3,13,255]@0", "", "no request");
    req("17 00 00 00 7D 00 00 00 79 F2", "read_start_address=0|read_quantity=125|write_start_address=0|write_quantity=121|byte_count=242"
                                         "|missing!E~byte count 242 announces 242 data bytes but only 0 are present",
        "largest quantities");
    req("17 00 00 00 7E 00 00 00 01 02 00 01",
        "read_start_address=0|read_quantity=126!E~read quantity 126 is out of range: Read/Write Multiple Registers allows 1-125 (0x0001-0x007D)"
        "|write_start_address=0|write_quantity=1|byte_count=2|register_value=[1]@0");
    req("17 00 00 00 01 00 00 00 7A 00",
        "read_start_address=0|read_quantity=1|write_start_address=0"
        "|write_quantity=122!E~write quantity 122 is out of range: Read/Write Multiple Registers allows 1-121 (0x0001-0x0079)"
        "|byte_count=0!E~byte count 0 does not match write quantity 122, which needs 244 bytes");
    req("17 00 00 00 00 00 00 00 00 00",
        "read_start_address=0|read_quantity=0!E~read quantity 0 is out of range|write_start_address=0"
        "|write_quantity=0!E~write quantity 0 is out of range|byte_count=0");
    req("17 FF FF 00 02 FF FF 00 02 04 00 01 00 02",
        "read_start_address=65535|read_quantity=2!E~range wraps past 0xFFFF: start address 65535 + read quantity 2"
        "|write_start_address=65535|write_quantity=2!E~start address 65535 + write quantity 2|byte_count=4|register_value=[1,2]@65535");
    req("17 00 03 00 06 00 0E 00 03 05 00 FF 00 FF 00",
        "read_start_address=3|read_quantity=6|write_start_address=14|write_quantity=3"
        "|byte_count=5!E~byte count 5 is odd"
        "|register_value=[255,255]@14|data!E~1 byte left over");
    req("17 00 03 00 06 00 0E 00 03 06 00 FF 00 FF 00",
        "read_start_address=3|read_quantity=6|write_start_address=14|write_quantity=3|byte_count=6|register_value=[255,255]@14"
        "|missing!E%00~only 5 are present; expected 1 more byte");
    req("17 00 03 00 06 00 0E 00 03",
        "read_start_address=3|read_quantity=6|write_start_address=14|write_quantity=3"
        "|missing!E~missing: byte count and write register values; expected 7 more bytes");
    req("17 00 03 00 06 00 0E",
        "read_start_address=3|read_quantity=6|write_start_address=14"
        "|missing!E~missing: write quantity, byte count and write values; expected at least 5 more bytes");
    req("17", "missing!E~missing: read start address, read quantity, write start address, write quantity, byte count and write values");
    req("17 00 03 00 06 00 0E 00 01 02 00 FF 00",
        "read_start_address=3|read_quantity=6|write_start_address=14|write_quantity=1|byte_count=2|register_value=[255]@14"
        "|trailing!E~1 byte after the end");

    rsp("17 02 00 01", "byte_count=2!E~byte count 2 does not match the request: read quantity 6 needs 12 bytes|register_value=[1]@3", spec);
    rsp("17 03 00 01 00", "byte_count=3!E~is odd|register_value=[1]@0|data!E~1 byte left over");
    rsp("17 00", "byte_count=0!E~byte count 0 is out of range");
    rsp("17 0C 00 FE 0A CD", "byte_count=12|register_value=[254,2765]@3|missing!E~only 4 are present; expected 8 more bytes", spec);
    rsp("17 02 00 01 00", "byte_count=2|register_value=[1]@0|trailing!E~1 byte after the end");
    rsp("17", "missing!E~missing: byte count and read register values; expected at least 3 more bytes");
}

void TestPduRecords::fifo_data()
{
    columns();
    req("18 04 DE", "fifo_address=1246%1246 (0x04DE)", "spec 6.18");
    req("18 04", "missing!E%04~missing: FIFO pointer address; expected 1 more byte");
    req("18 04 DE 00", "fifo_address=1246|trailing!E~1 byte after the end");
    rsp("18 00 06 00 02 01 B8 12 84", "byte_count=6|fifo_count=2|register_value=[440,4740]@0", "18 04 DE", "spec 6.18");
    rsp("18 00 02 00 00", "byte_count=2|fifo_count=0", "", "empty queue");
    rsp("18 00 04 00 02 01 B8", "byte_count=4!E~byte count 4 does not match FIFO count 2, which needs a byte count of 6"
                                "|fifo_count=2|register_value=[440]@0");
    rsp("18 00 05 00 02 01 B8 12",
        "byte_count=5!E~which needs a byte count of 6|fifo_count=2|register_value=[440]@0|data!E~1 byte left over");
    rsp("18 00 00 00 00", "byte_count=0!E~which needs a byte count of 2|fifo_count=0");
    rsp("18 00 06 00 02 01 B8", "byte_count=6|fifo_count=2|register_value=[440]@0"
                                "|missing!E~missing: byte count 6 announces 6 data bytes but only 4 are present; expected 2 more bytes");
    rsp("18 00 06 00 02 01 B8 12 84 00", "byte_count=6|fifo_count=2|register_value=[440,4740]|trailing!E~1 byte after the end");
    rsp("18 00 06 00", "byte_count=6|missing!E%00~missing: FIFO count and FIFO values; expected 5 more bytes");
    rsp("18 00 01 00", "byte_count=1|missing!E~missing: FIFO count and FIFO values; expected at least 1 more byte");
    rsp("18 00", "missing!E%00~missing: byte count, FIFO count and FIFO values; expected at least 3 more bytes");
    row(Direction::Response, pdutest::bytes("18 00 40 00 1F") + QByteArray(62, '\x07'),
        QStringLiteral("byte_count=64|fifo_count=31|register_value*31@0"), {}, "31 values");
    row(Direction::Response, pdutest::bytes("18 00 42 00 20") + QByteArray(64, '\x07'),
        QStringLiteral("byte_count=66|fifo_count=32!E~FIFO count 32 is out of range: a FIFO queue returns 0-31 values"
                       "|register_value*32@0"),
        {}, "32 values");
}

QTEST_GUILESS_MAIN(TestPduRecords)
#include "tst_pdurecords.moc"
