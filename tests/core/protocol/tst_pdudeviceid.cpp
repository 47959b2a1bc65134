#include "diagtestsupport.h"

using namespace diagtest;

// Function 2B Encapsulated Interface Transport: MEI 0E Read Device Identification in both
// directions, stream and individual access, 0D CANopen General Reference and reserved MEI types
// shown raw (MODBUS Application Protocol Specification V1.1b3, 6.19-6.21). Rows are bare PDUs
// named by their hex; the expected text is the whole field tree.
#define F2B "modbus.function_code=0x2B Encapsulated Interface Transport"
#define MEI0E " | modbus.mei_type=0x0E Read Device Identification"
#define BASIC " | modbus.read_device_id_code=0x01 Basic device identification (stream access)"
#define REGULAR " | modbus.read_device_id_code=0x02 Regular device identification (stream access)"
#define SINGLE " | modbus.read_device_id_code=0x04 One specific identification object (individual access)"
#define NO_MORE " | modbus.more_follows=0x00 No more objects | modbus.next_object_id=0x00"
#define MORE " | modbus.more_follows=0xFF More objects follow: ask again from the next object ID"
#define OBJ(index, id, name, length, value) \
    " | modbus.object#" index "=" name " | >modbus.object_id=0x" id " " name " | >modbus.object_length=" length \
    " | >modbus.object_value=\"" value "\""

class TestPduDeviceId : public QObject
{
    Q_OBJECT
private slots:
    void request_data()
    {
        addColumns();
        req("2B 0E 01 00", F2B MEI0E BASIC " | modbus.object_id=0x00 VendorName");
        req("2B 0E 02 03", F2B MEI0E REGULAR " | modbus.object_id=0x03 VendorUrl");
        req("2B 0E 03 80", F2B MEI0E " | modbus.read_device_id_code=0x03 Extended device identification (stream access)"
            " | modbus.object_id=0x80 Private object (extended, device dependent)");
        req("2B 0E 04 05", F2B MEI0E SINGLE " | modbus.object_id=0x05 ModelName");
        req("2B 0E 04 06", F2B MEI0E SINGLE " | modbus.object_id=0x06 UserApplicationName");
        req("2B 0E 04 01", F2B MEI0E SINGLE " | modbus.object_id=0x01 ProductCode");
        req("2B 0E 04 02", F2B MEI0E SINGLE " | modbus.object_id=0x02 MajorMinorRevision");
        req("2B 0E 04 04", F2B MEI0E SINGLE " | modbus.object_id=0x04 ProductName");
        req("2B 0E 05 00", F2B MEI0E " | modbus.read_device_id_code=0x05 Undefined read device ID code !error"
            " | modbus.object_id=0x00 VendorName",
            "0x05 is not a read device ID code: 01 basic, 02 regular, 03 extended stream, 04 one specific object");
        req("2B 0E 00 00", F2B MEI0E " | modbus.read_device_id_code=0x00 Undefined read device ID code !error"
            " | modbus.object_id=0x00 VendorName", "0x00 is not a read device ID code");
        req("2B 0E 04 07", F2B MEI0E SINGLE " | modbus.object_id=0x07 Reserved object !warning",
            "0x07 is a reserved object ID (0x07-0x7F)");
        req("2B 0E 03 7F", F2B MEI0E " | modbus.read_device_id_code=0x03 Extended device identification (stream access)"
            " | modbus.object_id=0x7F Reserved object !warning", "0x7F is a reserved object ID");
        req("2B 0E 01 03", F2B MEI0E BASIC " | modbus.object_id=0x03 VendorUrl !info",
            "0x03 is outside the basic (0x00-0x02) category: the device answers from object 0x00");
        req("2B 0E 02 80", F2B MEI0E REGULAR " | modbus.object_id=0x80 Private object (extended, device dependent) !info",
            "0x80 is outside the regular (0x00-0x06) category");
        req("2B 0E 01", F2B MEI0E BASIC " | modbus.missing= !error", "modbus.missing: missing: object ID; expected 1 more byte");
        req("2B 0E", F2B MEI0E " | modbus.missing= !error",
            "modbus.missing: missing: read device ID code and object ID; expected 2 more bytes");
        req("2B", F2B " | modbus.missing= !error", "modbus.missing: missing: MEI type; expected at least 1 more byte");
        req("2B 0E 01 00 00", F2B MEI0E BASIC " | modbus.object_id=0x00 VendorName | modbus.trailing=00 !error",
            "1 byte after the end of the PDU: it should be 4 bytes long, 5 are present");
    }
    void request() { checkRow(); }

    void streamResponse_data()
    {
        addColumns();
        rsp("2B 0E 01 01 00 00 03 00 07 43 6F 6D 70 61 6E 79 01 04 50 43 2D 31 02 05 56 32 2E 31 31",
            F2B MEI0E BASIC " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE
            " | modbus.object_count=3" OBJ("0", "00", "VendorName", "7", "Company") OBJ("1", "01", "ProductCode", "4", "PC-1")
            OBJ("2", "02", "MajorMinorRevision", "5", "V2.11"), "", "2B 0E 01 00");
        rsp("2B 0E 02 82 FF 02 02 00 03 41 42 43 01 02 58 59",
            F2B MEI0E REGULAR " | modbus.conformity_level=0x82 Regular identification (stream access and individual access)"
            MORE " | modbus.next_object_id=0x02 MajorMinorRevision | modbus.object_count=2"
            OBJ("0", "00", "VendorName", "3", "ABC") OBJ("1", "01", "ProductCode", "2", "XY"), "", "2B 0E 02 00");
        rsp("2B 0E 03 83 00 00 02 06 01 41 80 02 01 5C",
            F2B MEI0E " | modbus.read_device_id_code=0x03 Extended device identification (stream access)"
            " | modbus.conformity_level=0x83 Extended identification (stream access and individual access)" NO_MORE
            " | modbus.object_count=2" OBJ("0", "06", "UserApplicationName", "1", "A")
            OBJ("1", "80", "Private object (extended, device dependent)", "2", "\\x01\\\\"));
        rsp("2B 0E 01 01 00 00 01 00 00",
            F2B MEI0E BASIC " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE
            " | modbus.object_count=1" OBJ("0", "00", "VendorName", "0", ""));
        rsp("2B 0E 01 01 00 00 00",
            F2B MEI0E BASIC " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE
            " | modbus.object_count=0");
        // A stream that starts from 0x00 when another object was asked for: the device restarted.
        rsp("2B 0E 02 02 00 00 01 00 01 41",
            F2B MEI0E REGULAR " | modbus.conformity_level=0x02 Regular identification (stream access only)" NO_MORE
            " | modbus.object_count=1" OBJ("0", "00", "VendorName", "1", "A"), "", "2B 0E 02 04");
    }
    void streamResponse() { checkRow(); }

    void individualResponse_data()
    {
        addColumns();
        rsp("2B 0E 04 81 00 00 01 05 04 4D 2D 31 30",
            F2B MEI0E SINGLE " | modbus.conformity_level=0x81 Basic identification (stream access and individual access)"
            NO_MORE " | modbus.object_count=1" OBJ("0", "05", "ModelName", "4", "M-10"), "", "2B 0E 04 05");
        rsp("2B 0E 04 81 00 00 02 05 01 41 06 01 42",
            F2B MEI0E SINGLE " | modbus.conformity_level=0x81 Basic identification (stream access and individual access)"
            NO_MORE " | modbus.object_count=2 !error" OBJ("0", "05", "ModelName", "1", "A")
            OBJ("1", "06", "UserApplicationName", "1", "B"),
            "individual access (code 04) returns one object, 2 are present");
        rsp("2B 0E 04 81 FF 06 01 05 01 41",
            F2B MEI0E SINGLE " | modbus.conformity_level=0x81 Basic identification (stream access and individual access)"
            " | modbus.more_follows=0xFF More objects follow: ask again from the next object ID !error"
            " | modbus.next_object_id=0x06 UserApplicationName | modbus.object_count=1" OBJ("0", "05", "ModelName", "1", "A"),
            "individual access (code 04) sets more follows to 0x00");
        rsp("2B 0E 04 01 00 00 01 05 01 41",
            F2B MEI0E SINGLE " | modbus.conformity_level=0x01 Basic identification (stream access only) !warning"
            NO_MORE " | modbus.object_count=1" OBJ("0", "05", "ModelName", "1", "A"),
            "the device answered an individual access (code 04) but its conformity level 0x01 says it supports "
            "stream access only");
        rsp("2B 0E 04 81 00 00 01 04 01 41",
            F2B MEI0E SINGLE " | modbus.conformity_level=0x81 Basic identification (stream access and individual access)"
            NO_MORE " | modbus.object_count=1 | modbus.object#0=ProductName | >modbus.object_id=0x04 ProductName !error"
            " | >modbus.object_length=1 | >modbus.object_value=\"A\"",
            "does not match the request: object 0x05 was asked for", "2B 0E 04 05");
    }
    void individualResponse() { checkRow(); }

    void responseProblems_data()
    {
        addColumns();
        rsp("2B 0E 02 01 00 00 00", F2B MEI0E REGULAR " !error"
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE " | modbus.object_count=0",
            "does not match the request: the request's read device ID code is 0x01", "2B 0E 01 00");
        rsp("2B 0D 01 02", F2B " | modbus.mei_type=0x0D CANopen General Reference !error | modbus.data=01 02",
            "does not match the request: the request's MEI type is 0x0E", "2B 0E 01 00");
        for (const char *level : {"00", "04", "80", "84", "FF"}) {
            const QByteArray pdu = QByteArray("2B 0E 01 ") + level + " 00 00 00";
            const QByteArray expected = QByteArray(F2B MEI0E BASIC " | modbus.conformity_level=0x") + level
                + " Undefined conformity level !error" NO_MORE " | modbus.object_count=0";
            rsp(pdu.constData(), expected.constData(), "is not a conformity level: 01-03 (stream access only) or 81-83");
        }
        rsp("2B 0E 01 01 01 00 00", F2B MEI0E BASIC " | modbus.conformity_level=0x01 Basic identification (stream access only)"
            " | modbus.more_follows=0x01 !error | modbus.next_object_id=0x00 | modbus.object_count=0",
            "0x01 is not allowed: more follows is 0x00 (no) or 0xFF (yes)");
        rsp("2B 0E 01 01 00 02 00", F2B MEI0E BASIC " | modbus.conformity_level=0x01 Basic identification (stream access only)"
            " | modbus.more_follows=0x00 No more objects | modbus.next_object_id=0x02 !error | modbus.object_count=0",
            "0x02 is not allowed: the next object ID is 0x00 when more follows is 0x00");
        rsp("2B 0E 01 01 FF 01 01 01 01 41", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)"
            MORE " | modbus.next_object_id=0x01 ProductCode !warning | modbus.object_count=1"
            OBJ("0", "01", "ProductCode", "1", "A"),
            "next object ID 0x01 does not lie beyond the last object returned (0x01)");
        rsp("2B 0E 01 01 00 00 02 01 01 41 00 01 42", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE " | modbus.object_count=2"
            OBJ("0", "01", "ProductCode", "1", "A")
            " | modbus.object#1=VendorName | >modbus.object_id=0x00 VendorName !warning | >modbus.object_length=1"
            " | >modbus.object_value=\"B\"", "objects out of order: 0x00 follows 0x01");
        rsp("2B 0E 01 01 00 00 03 00 01 41 01 01 42", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE
            " | modbus.object_count=3 !error" OBJ("0", "00", "VendorName", "1", "A") OBJ("1", "01", "ProductCode", "1", "B"),
            "number of objects 3 but 2 present");
        rsp("2B 0E 01 01 00 00 01 00 01 41 01 01 42", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE
            " | modbus.object_count=1 !error" OBJ("0", "00", "VendorName", "1", "A") OBJ("1", "01", "ProductCode", "1", "B"),
            "number of objects 1 but 2 present");
        rsp("2B 0E 01 01 00 00 01 00 0A 41 42", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE " | modbus.object_count=1"
            " | modbus.object#0=VendorName | >modbus.object_id=0x00 VendorName | >modbus.object_length=10"
            " | >modbus.object_value=\"AB\" | >modbus.missing= !error",
            "modbus.missing: missing: object length 10 announces 10 data bytes but only 2 are present; expected 8 more bytes");
        rsp("2B 0E 01 01 00 00 01 00 05", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE " | modbus.object_count=1"
            " | modbus.object#0=VendorName | >modbus.object_id=0x00 VendorName | >modbus.object_length=5"
            " | >modbus.missing= !error",
            "modbus.missing: missing: object length 5 announces 5 data bytes but only 0 are present; expected 5 more bytes");
        rsp("2B 0E 01 01 00 00 02 00 01 41 01", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE " | modbus.object_count=2"
            OBJ("0", "00", "VendorName", "1", "A")
            " | modbus.object#1=ProductCode | >modbus.object_id=0x01 ProductCode | >modbus.missing= !error",
            "modbus.missing: missing: object length and object value; expected at least 1 more byte");
        rsp("2B 0E 03 03 00 00 01 10 01 41", F2B MEI0E
            " | modbus.read_device_id_code=0x03 Extended device identification (stream access)"
            " | modbus.conformity_level=0x03 Extended identification (stream access only)" NO_MORE " | modbus.object_count=1"
            " | modbus.object#0=Reserved object | >modbus.object_id=0x10 Reserved object !warning | >modbus.object_length=1"
            " | >modbus.object_value=\"A\"", "0x10 is a reserved object ID (0x07-0x7F)");
        rsp("2B 0E 02 02 00 00 01 05 01 41", F2B MEI0E REGULAR
            " | modbus.conformity_level=0x02 Regular identification (stream access only)" NO_MORE " | modbus.object_count=1"
            " | modbus.object#0=ModelName | >modbus.object_id=0x05 ModelName !warning | >modbus.object_length=1"
            " | >modbus.object_value=\"A\"", "the stream starts at 0x05: the request asked from object 0x04", "2B 0E 02 04");
        rsp("2B 0E 01 01 00 00 02", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)" NO_MORE
            " | modbus.object_count=2 | modbus.missing= !error", "modbus.missing: missing: objects; expected at least 4 more bytes");
        rsp("2B 0E 01 01 00", F2B MEI0E BASIC
            " | modbus.conformity_level=0x01 Basic identification (stream access only)"
            " | modbus.more_follows=0x00 No more objects | modbus.missing= !error",
            "modbus.missing: missing: next object ID, number of objects and objects; expected at least 2 more bytes");
        rsp("2B 0E 01", F2B MEI0E BASIC " | modbus.missing= !error",
            "modbus.missing: missing: conformity level, more follows, next object ID, number of objects and objects; "
            "expected at least 4 more bytes");
    }
    void responseProblems() { checkRow(); }

    void otherMeiTypes_data()
    {
        addColumns();
        req("2B 0D 00 01 02", F2B " | modbus.mei_type=0x0D CANopen General Reference !info | modbus.data=00 01 02",
            "CANopen General Reference: its data follows CiA DS-309 and is shown raw");
        rsp("2B 0D 00 01 02 03", F2B " | modbus.mei_type=0x0D CANopen General Reference !info | modbus.data=00 01 02 03",
            "", "2B 0D 00 01 02");
        req("2B 0D", F2B " | modbus.mei_type=0x0D CANopen General Reference !info");
        req("2B 0C 01 02", F2B " | modbus.mei_type=0x0C Reserved MEI type !warning | modbus.data=01 02",
            "reserved MEI type 0x0C: V1.1b3 defines 0x0D (CANopen) and 0x0E (device identification); the data is shown raw");
        rsp("2B 00 01", F2B " | modbus.mei_type=0x00 Reserved MEI type !warning | modbus.data=01");
        req("2B 0F", F2B " | modbus.mei_type=0x0F Reserved MEI type !warning");
        rsp("2B FF 01 02 03", F2B " | modbus.mei_type=0xFF Reserved MEI type !warning | modbus.data=01 02 03");
    }
    void otherMeiTypes() { checkRow(); }

    // Offsets and lengths of an object list, which the rendering leaves out.
    void objectLayout()
    {
        FieldTree tree;
        dissect(tree, hex("2B 0E 01 01 00 00 02 00 03 41 42 43 01 05 41 42"), Direction::Response);
        const QList<int> groups = tree.indexesOf("modbus.object");
        QCOMPARE(groups.size(), 2);
        QCOMPARE(tree.at(groups[0]).offset, 7);
        QCOMPARE(tree.at(groups[0]).length, 5);
        QCOMPARE(tree.at(groups[1]).offset, 12);
        QCOMPARE(tree.at(groups[1]).length, 4); // truncated: header plus the 2 bytes present
        const QList<int> values = tree.indexesOf("modbus.object_value");
        QCOMPARE(tree.raw(values[0]), QByteArray("ABC"));
        QCOMPARE(tree.raw(values[1]), QByteArray("AB"));
        QCOMPARE(tree.at(values[1]).parent, groups[1]);
        QCOMPARE(tree.name(groups[1]), QStringLiteral("Object 1"));
    }

    void noCrashSweep()
    {
        const QList<QByteArray> pdus = {
            hex("2B 0E 01 00"), hex("2B 0E 04 80"),
            hex("2B 0E 01 01 00 00 03 00 07 43 6F 6D 70 61 6E 79 01 04 50 43 2D 31 02 05 56 32 2E 31 31"),
            hex("2B 0E 04 81 FF 06 01 05 FF 41"), hex("2B 0D 00 01"), hex("2B 01")};
        QVERIFY(sweep(pdus, 0x2B) > 0);
    }
};

QTEST_GUILESS_MAIN(TestPduDeviceId)
#include "tst_pdudeviceid.moc"
