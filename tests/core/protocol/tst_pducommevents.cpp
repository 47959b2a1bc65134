#include "diagtestsupport.h"

using namespace diagtest;

// Functions 07 Read Exception Status, 0B Get Comm Event Counter, 0C Get Comm Event Log and
// 11 Report Server ID, both directions (MODBUS Application Protocol Specification V1.1b3, 6.7,
// 6.9, 6.10, 6.13). Rows are bare PDUs named by their hex; the expected text is the whole tree.
#define F07 "modbus.function_code=0x07 Read Exception Status !info"
#define F0B "modbus.function_code=0x0B Get Comm Event Counter !info"
#define F0C "modbus.function_code=0x0C Get Comm Event Log !info"
#define F11 "modbus.function_code=0x11 Report Server ID !info"
#define READY " | modbus.status=0x0000 Ready: no previous command is in progress"
#define BUSY " | modbus.status=0xFFFF Busy: a previous command is still being processed"

class TestPduCommEvents : public QObject
{
    Q_OBJECT
private slots:
    void readExceptionStatus_data()
    {
        addColumns();
        req("07", F07, "serial line only: V1.1b3 6.7 defines Read Exception Status for serial line devices");
        req("07 00", F07 " | modbus.trailing=00 !error",
            "1 byte after the end of the PDU: it should be 1 byte long, 2 are present");
        // 0x6D = 0110 1101: outputs 0, 2, 3, 5 and 6 are ON.
        rsp("07 6D", F07 " | modbus.exception_status=0x6D"
            " | >modbus.exception_status_bit#0=1 ON | >modbus.exception_status_bit#1=0 OFF"
            " | >modbus.exception_status_bit#2=1 ON | >modbus.exception_status_bit#3=1 ON"
            " | >modbus.exception_status_bit#4=0 OFF | >modbus.exception_status_bit#5=1 ON"
            " | >modbus.exception_status_bit#6=1 ON | >modbus.exception_status_bit#7=0 OFF", "", "07");
        rsp("07 80 01", F07 " | modbus.exception_status=0x80"
            " | >modbus.exception_status_bit#0=0 OFF | >modbus.exception_status_bit#1=0 OFF"
            " | >modbus.exception_status_bit#2=0 OFF | >modbus.exception_status_bit#3=0 OFF"
            " | >modbus.exception_status_bit#4=0 OFF | >modbus.exception_status_bit#5=0 OFF"
            " | >modbus.exception_status_bit#6=0 OFF | >modbus.exception_status_bit#7=1 ON | modbus.trailing=01 !error",
            "1 byte after the end of the PDU: it should be 2 bytes long, 3 are present");
        rsp("07", F07 " | modbus.missing= !error", "modbus.missing: missing: exception status; expected 1 more byte");
    }
    void readExceptionStatus() { checkRow(); }

    void commEventCounter_data()
    {
        addColumns();
        req("0B", F0B, "serial line only: V1.1b3 6.9 defines Get Comm Event Counter for serial line devices");
        req("0B 00 00", F0B " | modbus.trailing=00 00 !error",
            "2 bytes after the end of the PDU: it should be 1 byte long, 3 are present");
        rsp("0B 00 00 01 08", F0B READY " | modbus.event_count=264", "", "0B");
        rsp("0B FF FF 00 00", F0B BUSY " | modbus.event_count=0");
        rsp("0B 12 34 00 01", F0B " | modbus.status=0x1234 !error | modbus.event_count=1",
            "0x1234 is not a status: 0x0000 means ready, 0xFFFF busy (V1.1b3 6.9)");
        rsp("0B 00", F0B " | modbus.missing=00 !error", "modbus.missing: missing: status and event count; expected 3 more bytes");
        rsp("0B 00 00 01", F0B READY " | modbus.missing=01 !error",
            "modbus.missing: missing: event count; expected 1 more byte");
        rsp("0B 00 00 01 08 FF", F0B READY " | modbus.event_count=264 | modbus.trailing=FF !error",
            "1 byte after the end of the PDU: it should be 5 bytes long, 6 are present");
    }
    void commEventCounter() { checkRow(); }

    void commEventLog_data()
    {
        addColumns();
        req("0C", F0C, "serial line only: V1.1b3 6.10 defines Get Comm Event Log for serial line devices");
        req("0C 01", F0C " | modbus.trailing=01 !error", "1 byte after the end of the PDU");
        rsp("0C 06 00 00 00 05 00 07", F0C " | modbus.byte_count=6" READY
            " | modbus.event_count=5 | modbus.message_count=7", "", "0C");
        rsp("0C 0B 00 00 01 08 01 21 C2 41 04 00 52", F0C " | modbus.byte_count=11" READY
            " | modbus.event_count=264 | modbus.message_count=289"
            " | modbus.event#0=0xC2 Receive event: communication error, broadcast received"
            " | modbus.event#1=0x41 Send event: read exception sent (codes 01-03)"
            " | modbus.event#2=0x04 Entered listen only mode | modbus.event#3=0x00 Communication restart"
            " | modbus.event#4=0x52 Send event: abort exception sent (code 04), write timeout");
        // The example of V1.1b3 6.10 itself: its event 0x20 sets neither bit 7 nor bit 6, so it
        // matches none of the event types the same section defines.
        rsp("0C 08 00 00 01 08 01 21 20 00", F0C " | modbus.byte_count=8" READY
            " | modbus.event_count=264 | modbus.message_count=289"
            " | modbus.event#0=0x20 Undefined event (bits 7 and 6 clear, neither 0x00 nor 0x04) !warning"
            " | modbus.event#1=0x00 Communication restart", "0x20 is not an event type of V1.1b3 6.10");
        rsp("0C 09 FF FF 00 01 00 02 81 FF B0", F0C " | modbus.byte_count=9" BUSY
            " | modbus.event_count=1 | modbus.message_count=2"
            " | modbus.event#0=0x81 Receive event: unused bits set"
            " | modbus.event#1=0xFF Receive event: communication error, character overrun, in listen only mode, "
            "broadcast received, unused bits set"
            " | modbus.event#2=0xB0 Receive event: character overrun, in listen only mode");
        rsp("0C 08 00 00 00 01 00 01 7F 80", F0C " | modbus.byte_count=8" READY
            " | modbus.event_count=1 | modbus.message_count=1"
            " | modbus.event#0=0x7F Send event: read exception sent (codes 01-03), abort exception sent (code 04), "
            "busy exception sent (codes 05-06), program NAK exception sent (code 07), write timeout, in listen only mode"
            " | modbus.event#1=0x80 Receive event");
        rsp("0C 04 00 00 00 01 00 01", F0C " | modbus.byte_count=4 !error" READY
            " | modbus.event_count=1 | modbus.message_count=1",
            "byte count 4 is too small: status, event count and message count take 6 bytes");
        rsp("0C 04 00 00 00 01", F0C " | modbus.byte_count=4 !error" READY
            " | modbus.event_count=1 | modbus.missing= !error",
            "byte count 4 is too small: status, event count and message count take 6 bytes"
            " | modbus.missing: missing: message count and any events; expected at least 2 more bytes");
        rsp("0C 47 00 00 00 00 00 00", F0C " | modbus.byte_count=71 !error" READY
            " | modbus.event_count=0 | modbus.message_count=0 | modbus.missing= !error",
            "byte count 71 announces 65 events: the log holds at most 64 (byte count 6-70)"
            " | modbus.missing: missing: byte count 71 announces 71 data bytes but only 6 are present; "
            "expected 65 more bytes");
        rsp("0C 0A 00 00 00 03 00 04 C0 40", F0C " | modbus.byte_count=10" READY
            " | modbus.event_count=3 | modbus.message_count=4"
            " | modbus.event#0=0xC0 Receive event: broadcast received | modbus.event#1=0x40 Send event"
            " | modbus.missing= !error",
            "modbus.missing: missing: byte count 10 announces 10 data bytes but only 8 are present; "
            "expected 2 more bytes");
        rsp("0C 06 00 00 00 00 00 00 99", F0C " | modbus.byte_count=6" READY
            " | modbus.event_count=0 | modbus.message_count=0 | modbus.trailing=99 !error",
            "1 byte after the end of the PDU: it should be 8 bytes long, 9 are present");
        rsp("0C 06 00 01 00 00 00 00", F0C " | modbus.byte_count=6 | modbus.status=0x0001 !error"
            " | modbus.event_count=0 | modbus.message_count=0", "0x0001 is not a status");
        rsp("0C", F0C " | modbus.missing= !error",
            "modbus.missing: missing: byte count, status, event count, message count and any events; "
            "expected at least 7 more bytes");
        rsp("0C 06 00", F0C " | modbus.byte_count=6 | modbus.missing=00 !error",
            "modbus.missing: missing: status, event count, message count and any events; expected 5 more bytes");
    }
    void commEventLog() { checkRow(); }

    // The longest log: 64 events, byte count 70, nothing to flag; 65 are one too many.
    void fullEventLog()
    {
        QByteArray pdu = hex("0C 46 00 00 00 40 00 40");
        for (int i = 0; i < 64; ++i)
            pdu += char(0x80 | (i & 0x40));
        FieldTree tree;
        dissect(tree, pdu, Direction::Response);
        QCOMPARE(tree.indexesOf("modbus.event").size(), 64);
        QCOMPARE(tree.worstSeverity(), Severity::Info);
        QCOMPARE(tree.at(tree.indexesOf("modbus.event").last()).address, 63);
        QCOMPARE(tree.at(tree.indexesOf("modbus.event").last()).offset, 71);

        pdu[1] = char(0x47);
        pdu += char(0x80);
        dissect(tree, pdu, Direction::Response);
        QCOMPARE(tree.indexesOf("modbus.event").size(), 65);
        QCOMPARE(tree.at(tree.indexOf("modbus.byte_count")).severity, Severity::Error);
    }

    void reportServerId_data()
    {
        addColumns();
        req("11", F11, "serial line only: V1.1b3 6.13 defines Report Server ID for serial line devices");
        req("11 00", F11 " | modbus.trailing=00 !error", "1 byte after the end of the PDU");
        rsp("11 02 01 FF", F11 " | modbus.byte_count=2 | modbus.server_id=01 | modbus.run_indicator=0xFF ON", "", "11");
        rsp("11 05 2A 00 4C 4D 42", F11 " | modbus.byte_count=5 | modbus.server_id=2A | modbus.run_indicator=0x00 OFF"
            " | modbus.additional_data=4C 4D 42");
        rsp("11 03 01 55 42", F11 " | modbus.byte_count=3 | modbus.server_id=01 | modbus.run_indicator=0x55 !warning"
            " | modbus.additional_data=42",
            "0x55 is not a run indicator status (0x00 OFF, 0xFF ON); if this device's server ID is longer than one "
            "byte, this byte is part of it");
        // pymodbus' layout: the identity text, then the run indicator last.
        rsp("11 03 01 55 00", F11 " | modbus.byte_count=3 | modbus.server_id=01 55 !info | modbus.run_indicator=0x00 OFF",
            "a 2-byte server ID: the run indicator status is read from the last byte");
        rsp("11 05 41 42 43 44 FF", F11 " | modbus.byte_count=5 | modbus.server_id=41 42 43 44 !info"
            " | modbus.run_indicator=0xFF ON",
            "a 4-byte server ID");
        rsp("11 01 01", F11 " | modbus.byte_count=1 !error | modbus.server_id=01 | modbus.missing= !error",
            "byte count 1 is too small: the server ID and the run indicator take at least 2 bytes"
            " | modbus.missing: missing: run indicator status; expected at least 1 more byte");
        rsp("11 06 01 FF 41 42", F11 " | modbus.byte_count=6 | modbus.server_id=01"
            " | modbus.run_indicator=0xFF ON | modbus.additional_data=41 42 | modbus.missing= !error",
            "modbus.missing: missing: byte count 6 announces 6 data bytes but only 4 are present; expected 2 more bytes");
        rsp("11 02 01 FF 00", F11 " | modbus.byte_count=2 | modbus.server_id=01 | modbus.run_indicator=0xFF ON"
            " | modbus.trailing=00 !error", "1 byte after the end of the PDU: it should be 4 bytes long, 5 are present");
        rsp("11", F11 " | modbus.missing= !error",
            "modbus.missing: missing: byte count, server ID and run indicator status; expected at least 3 more bytes");
        rsp("11 00", F11 " | modbus.byte_count=0 !error | modbus.missing= !error",
            "byte count 0 is too small: the server ID and the run indicator take at least 2 bytes"
            " | modbus.missing: missing: server ID and run indicator status; expected at least 2 more bytes");
    }
    void reportServerId() { checkRow(); }

    void noCrashSweep()
    {
        const QList<QByteArray> pdus = {hex("07 6D"), hex("0B 00 00 01 08"), hex("0C 08 00 00 01 08 01 21 20 00"),
                                        hex("0C 46 00 00 00 00 00 00"), hex("11 05 2A 00 4C 4D 42"), hex("11 FF")};
        QVERIFY(sweep(pdus, 0x0C) > 0);
    }
};

QTEST_GUILESS_MAIN(TestPduCommEvents)
#include "tst_pducommevents.moc"
