#include "diagtestsupport.h"

#include "protocol/functioncode.h"

using namespace diagtest;

// Exception responses (MODBUS Application Protocol Specification V1.1b3, 7): every exception
// code 01-0B and unknown ones, with their meanings; user-defined function codes (65-72,
// 100-110, V1.1b3 5.1) shown raw with an info; reserved and unassigned codes warned. Ends with
// a sweep of every function code over random tails.
#define EXC(fc, base, name) "modbus.function_code=0x" fc " Exception response | modbus.request_function_code=0x" base " " name

class TestPduExceptions : public QObject
{
    Q_OBJECT
private slots:
    void exceptions_data()
    {
        addColumns();
        struct Code {
            const char *hex;
            const char *meaning;
            const char *severity;
        };
        const Code codes[] = {
            {"01", "Illegal Function: the function code is not supported by the device, or not allowed in its current state", ""},
            {"02", "Illegal Data Address: the address range is not available in the device", ""},
            {"03", "Illegal Data Value: a value in the request is not allowed, such as a quantity or length out of range", ""},
            {"04", "Server Device Failure: an unrecoverable error occurred while the device was performing the action", ""},
            {"05", "Acknowledge: the device accepted the request but needs a long time to process it; poll it later", ""},
            {"06", "Server Device Busy: the device is processing a long-duration command; retry later", ""},
            {"07", "Negative Acknowledge: the device cannot perform the program function (legacy Modicon code)", " !info"},
            {"08", "Memory Parity Error: the device found a parity error in its extended file memory (function 20/21)", " !info"},
            {"09", "Unassigned exception code: 0x09 is not defined by the Modbus specification", " !warning"},
            {"0A", "Gateway Path Unavailable: the gateway could not allocate a path to the target, it is misconfigured or overloaded", ""},
            {"0B", "Gateway Target Device Failed to Respond: the gateway got no answer from the target device", ""},
            {"00", "Unknown exception code: the Modbus specification defines 0x01-0x08, 0x0A and 0x0B", " !warning"},
            {"0C", "Unknown exception code: the Modbus specification defines 0x01-0x08, 0x0A and 0x0B", " !warning"},
            {"80", "Unknown exception code: the Modbus specification defines 0x01-0x08, 0x0A and 0x0B", " !warning"},
            {"FF", "Unknown exception code: the Modbus specification defines 0x01-0x08, 0x0A and 0x0B", " !warning"},
        };
        for (const Code &c : codes) {
            const QByteArray pdu = QByteArray("83 ") + c.hex;
            const QByteArray expected = QByteArray(EXC("83", "03", "Read Holding Registers") " | modbus.exception_code=0x")
                + c.hex + ' ' + c.meaning + c.severity;
            rsp(pdu.constData(), expected.constData(), "", "03 00 00 00 01");
        }
        rsp("83 07", EXC("83", "03", "Read Holding Registers") " | modbus.exception_code=0x07 Negative Acknowledge: the device "
            "cannot perform the program function (legacy Modicon code) !info",
            "0x07 Negative Acknowledge is a legacy Modicon code, not in V1.1b3's table (7)");
        rsp("83 08", EXC("83", "03", "Read Holding Registers") " | modbus.exception_code=0x08 Memory Parity Error: the device "
            "found a parity error in its extended file memory (function 20/21) !info",
            "V1.1b3 (7) defines Memory Parity Error for Read/Write File Record (0x14, 0x15), this exception is for 0x03");
        rsp("94 08", EXC("94", "14", "Read File Record") " | modbus.exception_code=0x08 Memory Parity Error: the device "
            "found a parity error in its extended file memory (function 20/21)");
        rsp("95 08", EXC("95", "15", "Write File Record") " | modbus.exception_code=0x08 Memory Parity Error: the device "
            "found a parity error in its extended file memory (function 20/21)");
        rsp("83 0C", EXC("83", "03", "Read Holding Registers") " | modbus.exception_code=0x0C Unknown exception code: the "
            "Modbus specification defines 0x01-0x08, 0x0A and 0x0B !warning",
            "0x0C is not an exception code the specification defines (0x01-0x08, 0x0A, 0x0B)");
    }
    void exceptions() { checkRow(); }

    void exceptionProblems_data()
    {
        addColumns();
        rsp("83 02 00", EXC("83", "03", "Read Holding Registers") " | modbus.exception_code=0x02 Illegal Data Address: the "
            "address range is not available in the device | modbus.trailing=00 !error",
            "1 byte after the end of the PDU: it should be 2 bytes long, 3 are present");
        rsp("81 02 00 11 22", EXC("81", "01", "Read Coils") " | modbus.exception_code=0x02 Illegal Data Address: the "
            "address range is not available in the device | modbus.trailing=00 11 22 !error",
            "3 bytes after the end of the PDU: it should be 2 bytes long, 5 are present");
        rsp("83", EXC("83", "03", "Read Holding Registers") " | modbus.missing= !error",
            "modbus.missing: missing: exception code; expected 1 more byte");
        req("83 02", "modbus.function_code=0x83 Exception response !error | modbus.request_function_code=0x03 Read Holding "
            "Registers | modbus.exception_code=0x02 Illegal Data Address: the address range is not available in the device",
            "an exception code (0x80 set) can only appear in a response");
        rsp("83 02", "modbus.function_code=0x83 Exception response | modbus.request_function_code=0x03 Read Holding "
            "Registers !error | modbus.exception_code=0x02 Illegal Data Address: the address range is not available in the device",
            "does not match the request: the request's function code is 0x04, the exception is for 0x03", "04 00 00 00 01");
        rsp("88 01", EXC("88", "08", "Diagnostics") " | modbus.exception_code=0x01 Illegal Function: the function code is "
            "not supported by the device, or not allowed in its current state", "", "08 00 00 12 34");
        rsp("AB 02", EXC("AB", "2B", "Encapsulated Interface Transport") " | modbus.exception_code=0x02 Illegal Data Address: "
            "the address range is not available in the device", "", "2B 0E 04 05");
        rsp("C1 01", "modbus.function_code=0xC1 Exception response !info | modbus.request_function_code=0x41 User-defined "
            "function | modbus.exception_code=0x01 Illegal Function: the function code is not supported by the device, or "
            "not allowed in its current state", "exception for user-defined function 0x41 (65-72, 100-110)");
        rsp("EE 04", "modbus.function_code=0xEE Exception response !info | modbus.request_function_code=0x6E User-defined "
            "function | modbus.exception_code=0x04 Server Device Failure: an unrecoverable error occurred while the device "
            "was performing the action", "exception for user-defined function 0x6E");
        rsp("89 01", "modbus.function_code=0x89 Exception response !warning | modbus.request_function_code=0x09 Reserved "
            "function code | modbus.exception_code=0x01 Illegal Function: the function code is not supported by the device, "
            "or not allowed in its current state", "exception for function 0x09, a reserved function code");
        rsp("FF 01", "modbus.function_code=0xFF Exception response !warning | modbus.request_function_code=0x7F Reserved "
            "function code | modbus.exception_code=0x01 Illegal Function: the function code is not supported by the device, "
            "or not allowed in its current state", "exception for function 0x7F, a reserved function code");
        rsp("99 01", "modbus.function_code=0x99 Exception response !warning | modbus.request_function_code=0x19 Unassigned "
            "function code | modbus.exception_code=0x01 Illegal Function: the function code is not supported by the device, "
            "or not allowed in its current state", "exception for function 0x19, which the specification does not assign");
        // V1.1b3, 4.1: valid function codes are 1-255; an exception for code 0 answers no request.
        rsp("80 01", "modbus.function_code=0x80 Exception response !error | modbus.request_function_code=0x00 Invalid "
            "function code | modbus.exception_code=0x01 Illegal Function: the function code is not supported by the device, "
            "or not allowed in its current state", "exception for function 0x00, which is not a valid function code");
    }
    void exceptionProblems() { checkRow(); }

    // Every meaning starts with the exception's name, so the two never disagree.
    void exceptionNamesLeadMeanings()
    {
        for (int code = 0; code < 256; ++code) {
            const QByteArray name = mbscope::exceptionName(quint8(code));
            const QByteArray meaning = mbscope::exceptionMeaning(quint8(code));
            if (code == 0x09)
                QVERIFY(meaning.startsWith("Unassigned exception code"));
            else
                QVERIFY2(meaning.startsWith(name + ':'), meaning.constData());
        }
    }

    void userDefined_data()
    {
        addColumns();
        QList<int> codes;
        for (int c = 65; c <= 72; ++c)
            codes << c;
        for (int c = 100; c <= 110; ++c)
            codes << c;
        for (int c : codes) {
            const QByteArray fc = QByteArray::number(c, 16).toUpper();
            const QByteArray pdu = fc + " 01 02 FF";
            const QByteArray expected = "modbus.function_code=0x" + fc + " User-defined function !info | modbus.data=01 02 FF";
            req(pdu.constData(), expected.constData(), "user-defined function code (65-72, 100-110): its data is shown raw");
            rsp(pdu.constData(), expected.constData(), "user-defined function code (65-72, 100-110): its data is shown raw");
        }
        req("41", "modbus.function_code=0x41 User-defined function !info");
        rsp("6E 00", "modbus.function_code=0x6E User-defined function !info | modbus.data=00", "", "6E 12 34");
    }
    void userDefined() { checkRow(); }

    void reservedAndUnassigned_data()
    {
        addColumns();
        for (const char *fc : {"09", "0A", "0D", "0E", "29", "2A", "5A", "5B", "7D", "7E", "7F"}) {
            const QByteArray pdu = QByteArray(fc) + " 00 01";
            const QByteArray expected = QByteArray("modbus.function_code=0x") + fc
                + " Reserved function code !warning | modbus.data=00 01";
            req(pdu.constData(), expected.constData(), "reserved function code");
            rsp(pdu.constData(), expected.constData(), "reserved function code");
        }
        // V1.1b3, 4.1: "Valid codes are in the range of 1 ... 255 decimal": 0 is an error, not a warning.
        req("00 AA", "modbus.function_code=0x00 Invalid function code !error | modbus.data=AA",
            "function code 0 is not valid: valid codes are 1-255 (MODBUS Application Protocol V1.1b3, 4.1)");
        rsp("00 AA", "modbus.function_code=0x00 Invalid function code !error | modbus.data=AA", "function code 0 is not valid");
        for (const char *fc : {"12", "13", "19", "1A", "28", "2C", "40", "49", "63", "6F", "7C"}) {
            const QByteArray pdu = QByteArray(fc) + " AA";
            const QByteArray expected = QByteArray("modbus.function_code=0x") + fc
                + " Unassigned function code !warning | modbus.data=AA";
            req(pdu.constData(), expected.constData(), "unassigned public function code");
            rsp(pdu.constData(), expected.constData(), "unassigned public function code");
        }
    }
    void reservedAndUnassigned() { checkRow(); }

    // Every first byte, its prefixes, and random tails, in both directions with and without a
    // request: the invariants hold and nothing crashes or hangs.
    void noCrashSweepEveryCode()
    {
        QList<QByteArray> pdus;
        for (int code = 0; code < 256; ++code)
            pdus << QByteArray(1, char(code)) + hex("00 01 02 03 04 05 06");
        QVERIFY(sweep(pdus, 0xE0) > 0);
    }
};

QTEST_GUILESS_MAIN(TestPduExceptions)
#include "tst_pduexceptions.moc"
