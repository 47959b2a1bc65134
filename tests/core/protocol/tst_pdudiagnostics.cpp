#include "diagtestsupport.h"

using namespace diagtest;

// Function 08 Diagnostics, every sub-function in both directions (MODBUS Application Protocol
// Specification V1.1b3, 6.8 and 6.8.1). Rows are bare PDUs named by their hex; the expected text
// is the whole field tree: key=display, then the severity when the field is flagged.
#define F08 "modbus.function_code=0x08 Diagnostics !info | "
#define SF(code, name) "modbus.subfunction=0x00" code " " name

class TestPduDiagnostics : public QObject
{
    Q_OBJECT
private slots:
    void returnQueryData_data()
    {
        addColumns();
        req("08 00 00 A5 37", F08 SF("00", "Return Query Data") " | modbus.echo_data=A5 37");
        rsp("08 00 00 A5 37", F08 SF("00", "Return Query Data") " | modbus.echo_data=A5 37", "", "08 00 00 A5 37");
        rsp("08 00 00 A5 37", F08 SF("00", "Return Query Data") " | modbus.echo_data=A5 37");
        req("08 00 00 01 02 03 04 05 06 07 08",
            F08 SF("00", "Return Query Data") " | modbus.echo_data=01 02 03 04 05 06 07 08");
        req("08 00 00", F08 SF("00", "Return Query Data"));
        req("08 00 00 12", F08 SF("00", "Return Query Data") " | modbus.echo_data=12 !info",
            "odd length (1 byte): V1.1b3 6.8.1 gives the data as 2-byte words");
        rsp("08 00 00 A5 38", F08 SF("00", "Return Query Data") " | modbus.echo_data=A5 38 !error",
            "does not echo the request: data byte 1 is 0x38, the request sent 0x37", "08 00 00 A5 37");
        rsp("08 00 00 A5 37 00 00", F08 SF("00", "Return Query Data") " | modbus.echo_data=A5 37 00 00 !error",
            "does not echo the request: 4 bytes of data returned, the request sent 2 bytes", "08 00 00 A5 37");
        rsp("08 00 00 A5", F08 SF("00", "Return Query Data") " | modbus.echo_data=A5 !error",
            "does not echo the request: 1 byte of data returned, the request sent 2 bytes", "08 00 00 A5 37");
        rsp("08 00 00", F08 SF("00", "Return Query Data") " | modbus.echo_data= !error",
            "missing: the request sent 2 bytes of data to echo, none came back", "08 00 00 A5 37");
        // A request of another function: the dispatch flags the function code, the echo is not compared.
        rsp("08 00 00 A5 37",
            "modbus.function_code=0x08 Diagnostics !error | " SF("00", "Return Query Data") " | modbus.echo_data=A5 37",
            "the request's function code is 0x03", "03 00 00 A5 37");
    }
    void returnQueryData() { checkRow(); }

    void restartCommunications_data()
    {
        addColumns();
        req("08 00 01 00 00", F08 SF("01", "Restart Communications Option")
            " | modbus.restart_option=0x0000 Restart, keep the communications event log");
        req("08 00 01 FF 00", F08 SF("01", "Restart Communications Option")
            " | modbus.restart_option=0xFF00 Restart and clear the communications event log");
        rsp("08 00 01 FF 00", F08 SF("01", "Restart Communications Option")
            " | modbus.restart_option=0xFF00 Restart and clear the communications event log", "", "08 00 01 FF 00");
        rsp("08 00 01 00 00", F08 SF("01", "Restart Communications Option")
            " | modbus.restart_option=0x0000 Restart, keep the communications event log", "", "08 00 01 00 00");
        req("08 00 01 12 34", F08 SF("01", "Restart Communications Option") " | modbus.restart_option=0x1234 !error",
            "0x1234 is not a restart option: 0x0000 keeps the event log, 0xFF00 clears it");
        rsp("08 00 01 00 00", F08 SF("01", "Restart Communications Option")
            " | modbus.restart_option=0x0000 Restart, keep the communications event log !error",
            "does not echo the request: data byte 0 is 0x00, the request sent 0xFF", "08 00 01 FF 00");
        req("08 00 01 FF", F08 SF("01", "Restart Communications Option") " | modbus.missing=FF !error",
            "modbus.missing: missing: restart option; expected 1 more byte");
        req("08 00 01", F08 SF("01", "Restart Communications Option") " | modbus.missing= !error",
            "modbus.missing: missing: restart option; expected 2 more bytes");
        req("08 00 01 FF 00 00", F08 SF("01", "Restart Communications Option")
            " | modbus.restart_option=0xFF00 Restart and clear the communications event log | modbus.trailing=00 !error",
            "1 byte after the end of the PDU: it should be 5 bytes long, 6 are present");
    }
    void restartCommunications() { checkRow(); }

    void diagnosticRegister_data()
    {
        addColumns();
        req("08 00 02 00 00", F08 SF("02", "Return Diagnostic Register") " | modbus.diagnostic_data=0x0000");
        rsp("08 00 02 01 23", F08 SF("02", "Return Diagnostic Register") " | modbus.diagnostic_register=0x0123");
        rsp("08 00 02 80 00", F08 SF("02", "Return Diagnostic Register") " | modbus.diagnostic_register=0x8000", "",
            "08 00 02 00 00");
        req("08 00 02 00 01", F08 SF("02", "Return Diagnostic Register") " | modbus.diagnostic_data=0x0001 !error",
            "0x0001 is not allowed: Return Diagnostic Register request carries the data 0x0000");
        rsp("08 00 02 01", F08 SF("02", "Return Diagnostic Register") " | modbus.missing=01 !error",
            "modbus.missing: missing: diagnostic register; expected 1 more byte");
        rsp("08 00 02 01 23 45 67", F08 SF("02", "Return Diagnostic Register")
            " | modbus.diagnostic_register=0x0123 | modbus.trailing=45 67 !error",
            "2 bytes after the end of the PDU: it should be 5 bytes long, 7 are present");
    }
    void diagnosticRegister() { checkRow(); }

    void asciiDelimiter_data()
    {
        addColumns();
        req("08 00 03 3B 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x3B ';' | modbus.padding=0x00");
        req("08 00 03 0A 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x0A LF (line feed, the default delimiter) | modbus.padding=0x00");
        rsp("08 00 03 0D 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x0D CR (carriage return) | modbus.padding=0x00", "", "08 00 03 0D 00");
        req("08 00 03 20 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x20 ' ' (space) | modbus.padding=0x00");
        req("08 00 03 7E 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x7E '~' | modbus.padding=0x00");
        req("08 00 03 80 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x80 not an ASCII character | modbus.padding=0x00");
        req("08 00 03 3A 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x3A ':' !warning | modbus.padding=0x00",
            "0x3A as the end delimiter breaks ASCII framing");
        req("08 00 03 41 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x41 'A' !warning | modbus.padding=0x00",
            "0x41 as the end delimiter breaks ASCII framing");
        req("08 00 03 0A 01", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x0A LF (line feed, the default delimiter) | modbus.padding=0x01 !error",
            "0x01 is not allowed: the byte after the delimiter is 0x00");
        rsp("08 00 03 0A 00", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x0A LF (line feed, the default delimiter) !error | modbus.padding=0x00",
            "does not echo the request: data byte 0 is 0x0A, the request sent 0x0D", "08 00 03 0D 00");
        req("08 00 03 0A", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x0A LF (line feed, the default delimiter) | modbus.missing= !error",
            "modbus.missing: missing: padding; expected 1 more byte");
        req("08 00 03 0A 00 0D", F08 SF("03", "Change ASCII Input Delimiter")
            " | modbus.ascii_delimiter=0x0A LF (line feed, the default delimiter) | modbus.padding=0x00"
            " | modbus.trailing=0D !error", "1 byte after the end of the PDU");
    }
    void asciiDelimiter() { checkRow(); }

    void listenOnly_data()
    {
        addColumns();
        req("08 00 04 00 00", F08 SF("04", "Force Listen Only Mode") " | modbus.diagnostic_data=0x0000");
        rsp("08 00 04 00 00", F08 SF("04", "Force Listen Only Mode") " !warning | modbus.diagnostic_data=0x0000",
            "a device returns no response to Force Listen Only Mode");
        req("08 00 04 FF 00", F08 SF("04", "Force Listen Only Mode") " | modbus.diagnostic_data=0xFF00 !error",
            "0xFF00 is not allowed: Force Listen Only Mode request carries the data 0x0000");
    }
    void listenOnly() { checkRow(); }

    void clearing_data()
    {
        addColumns();
        req("08 00 0A 00 00", F08 SF("0A", "Clear Counters and Diagnostic Register") " | modbus.diagnostic_data=0x0000");
        rsp("08 00 0A 00 00", F08 SF("0A", "Clear Counters and Diagnostic Register") " | modbus.diagnostic_data=0x0000",
            "", "08 00 0A 00 00");
        rsp("08 00 0A 00 01", F08 SF("0A", "Clear Counters and Diagnostic Register") " | modbus.diagnostic_data=0x0001 !error",
            "0x0001 is not allowed: Clear Counters and Diagnostic Register echoes the request and carries the data 0x0000");
        req("08 00 14 00 00", F08 SF("14", "Clear Overrun Counter and Flag") " | modbus.diagnostic_data=0x0000");
        rsp("08 00 14 00 00", F08 SF("14", "Clear Overrun Counter and Flag") " | modbus.diagnostic_data=0x0000");
        req("08 00 14 12 34", F08 SF("14", "Clear Overrun Counter and Flag") " | modbus.diagnostic_data=0x1234 !error",
            "0x1234 is not allowed: Clear Overrun Counter and Flag request carries the data 0x0000");
    }
    void clearing() { checkRow(); }

    void counters_data()
    {
        addColumns();
        struct Counter {
            const char *code;
            const char *name;
            const char *request;
            const char *response;
            const char *value;
        };
        const Counter counters[] = {
            {"0B", "Return Bus Message Count", "08 00 0B 00 00", "08 00 0B 01 2C", "300"},
            {"0C", "Return Bus Communication Error Count", "08 00 0C 00 00", "08 00 0C 00 07", "7"},
            {"0D", "Return Bus Exception Error Count", "08 00 0D 00 00", "08 00 0D 00 02", "2"},
            {"0E", "Return Server Message Count", "08 00 0E 00 00", "08 00 0E FF FF", "65535"},
            {"0F", "Return Server No Response Count", "08 00 0F 00 00", "08 00 0F 00 00", "0"},
            {"10", "Return Server NAK Count", "08 00 10 00 00", "08 00 10 00 01", "1"},
            {"11", "Return Server Busy Count", "08 00 11 00 00", "08 00 11 00 0A", "10"},
            {"12", "Return Bus Character Overrun Count", "08 00 12 00 00", "08 00 12 10 00", "4096"},
        };
        for (const Counter &c : counters) {
            const QByteArray sf = QByteArray("modbus.subfunction=0x00") + c.code + ' ' + c.name;
            const QByteArray request = F08 + sf + " | modbus.diagnostic_data=0x0000";
            const QByteArray response = F08 + sf + " | modbus.counter_value=" + c.value;
            req(c.request, request.constData());
            rsp(c.response, response.constData(), "", c.request);
        }
        req("08 00 0B 00 01", F08 SF("0B", "Return Bus Message Count") " | modbus.diagnostic_data=0x0001 !error",
            "0x0001 is not allowed: Return Bus Message Count request carries the data 0x0000");
        req("08 00 0B", F08 SF("0B", "Return Bus Message Count") " | modbus.missing= !error",
            "modbus.missing: missing: data; expected 2 more bytes");
        req("08 00 0B 00 00 00 00", F08 SF("0B", "Return Bus Message Count")
            " | modbus.diagnostic_data=0x0000 | modbus.trailing=00 00 !error",
            "2 bytes after the end of the PDU: it should be 5 bytes long, 7 are present");
        rsp("08 00 0E 00", F08 SF("0E", "Return Server Message Count") " | modbus.missing=00 !error",
            "modbus.missing: missing: counter value; expected 1 more byte");
        rsp("08 00 0E 00 05 00", F08 SF("0E", "Return Server Message Count")
            " | modbus.counter_value=5 | modbus.trailing=00 !error", "1 byte after the end of the PDU");
        rsp("08 00 0B 00 05", F08 SF("0B", "Return Bus Message Count") " !error | modbus.counter_value=5",
            "does not match the request: the request's sub-function is 0x000C", "08 00 0C 00 00");
    }
    void counters() { checkRow(); }

    void reserved_data()
    {
        addColumns();
        for (const char *code : {"05", "06", "07", "08", "09"}) {
            const QByteArray pdu = QByteArray("08 00 ") + code + " 00 00";
            const QByteArray expected = QByteArray(F08 "modbus.subfunction=0x00") + code
                + " Reserved sub-function !warning | modbus.diagnostic_data=00 00";
            req(pdu.constData(), expected.constData(), "reserved sub-function");
            rsp(pdu.constData(), expected.constData(), "its data is shown raw");
        }
        req("08 00 13 00 00", F08 SF("13", "Reserved (legacy Modicon: Return IOP Overrun Count)")
            " !warning | modbus.diagnostic_data=00 00", "reserved sub-function 0x0013");
        rsp("08 00 15 00 03 01 02", F08 SF("15", "Reserved (legacy Modicon: Get/Clear Modbus Plus Statistics)")
            " !warning | modbus.diagnostic_data=00 03 01 02", "reserved sub-function 0x0015");
        req("08 00 16 12 34", F08 SF("16", "Reserved sub-function") " !warning | modbus.diagnostic_data=12 34");
        req("08 FF FF", F08 "modbus.subfunction=0xFFFF Reserved sub-function !warning",
            "reserved sub-function 0xFFFF: V1.1b3 6.8.1 defines 0x0000-0x0004, 0x000A-0x0012 and 0x0014");
        req("08 01 00 00 00", F08 "modbus.subfunction=0x0100 Reserved sub-function !warning | modbus.diagnostic_data=00 00");
    }
    void reserved() { checkRow(); }

    void truncated_data()
    {
        addColumns();
        req("08", F08 "modbus.missing= !error", "modbus.missing: missing: sub-function and data; expected at least 2 more bytes");
        rsp("08", F08 "modbus.missing= !error", "modbus.missing: missing: sub-function and data; expected at least 2 more bytes");
        req("08 00", F08 "modbus.missing=00 !error",
            "modbus.missing: missing: sub-function and data; expected at least 1 more byte");
        rsp("08 00", F08 "modbus.missing=00 !error",
            "modbus.missing: missing: sub-function and data; expected at least 1 more byte", "08 00 00 12 34");
    }
    void truncated() { checkRow(); }

    // Field offsets and lengths, which the rendering leaves out.
    void layout()
    {
        FieldTree tree;
        dissect(tree, hex("08 00 03 0A 00 FF"), Direction::Request);
        const int s = tree.indexOf("modbus.subfunction");
        const int d = tree.indexOf("modbus.ascii_delimiter");
        const int p = tree.indexOf("modbus.padding");
        const int t = tree.indexOf("modbus.trailing");
        QVERIFY(s > 0 && d > s && p > d && t > p);
        QCOMPARE(tree.at(s).offset, 1);
        QCOMPARE(tree.at(s).length, 2);
        QCOMPARE(tree.at(d).offset, 3);
        QCOMPARE(tree.at(d).length, 1);
        QCOMPARE(tree.at(p).offset, 4);
        QCOMPARE(tree.at(t).offset, 5);
        QCOMPARE(tree.at(t).length, 1);
        QCOMPARE(tree.name(tree.indexOf("modbus.subfunction")), QStringLiteral("Sub-function"));

        dissect(tree, hex("08 00 0B 01 2C"), Direction::Response);
        const int c = tree.indexOf("modbus.counter_value");
        QCOMPARE(tree.name(c), QStringLiteral("Bus message count"));
        QCOMPARE(tree.at(c).value, quint64(300));
        QCOMPARE(tree.raw(c), hex("01 2C"));
    }

    // A valid frame leaves no message but the serial-line note, and nothing above info.
    void validFramesAreClean_data()
    {
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<int>("direction");
        for (const char *h : {"08 00 00 12 34", "08 00 01 FF 00", "08 00 02 00 00", "08 00 03 0D 00", "08 00 04 00 00",
                              "08 00 0A 00 00", "08 00 0B 00 00", "08 00 12 00 00", "08 00 14 00 00"}) {
            QTest::newRow((QByteArray(h) + " request").constData()) << hex(h) << int(Direction::Request);
        }
        for (const char *h : {"08 00 00 12 34", "08 00 01 00 00", "08 00 02 12 34", "08 00 03 0D 00",
                              "08 00 0A 00 00", "08 00 0C 00 09", "08 00 11 00 09", "08 00 14 00 00"}) {
            QTest::newRow((QByteArray(h) + " response").constData()) << hex(h) << int(Direction::Response);
        }
    }
    void validFramesAreClean()
    {
        QFETCH(QByteArray, pdu);
        QFETCH(int, direction);
        FieldTree tree;
        dissect(tree, pdu, Direction(direction), pdu);
        QCOMPARE(tree.worstSeverity(), Severity::Info);
        QCOMPARE(tree.count(Severity::Info), 1);
        QCOMPARE(messages(tree), QStringLiteral("modbus.function_code: serial line only: V1.1b3 6.8 defines Diagnostics "
                                                "for serial line devices"));
    }

    void noCrashSweep()
    {
        QList<QByteArray> pdus;
        for (int sub = 0; sub <= 0x16; ++sub)
            pdus << hex("08 00") + char(sub) + hex("00 00");
        pdus << hex("08 00 00 01 02 03 04 05 06") << hex("08 00 03 3A 00") << hex("08 FF FF FF FF");
        const int runs = sweep(pdus, 0x08);
        QVERIFY(runs > 0);
    }
};

QTEST_GUILESS_MAIN(TestPduDiagnostics)
#include "tst_pdudiagnostics.moc"
