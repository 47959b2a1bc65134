#include "protocol/pdusize.h"

#include <QtTest/QtTest>

using namespace mbscope;
using pdusize::Status;

Q_DECLARE_METATYPE(mbscope::Direction)
Q_DECLARE_METATYPE(mbscope::pdusize::Status)

// Size rules from the PDU layouts of MODBUS Application Protocol Specification V1.1b3, section 6.
// Each row gives a PDU (possibly only its first bytes), a direction and the expected answer.
class TestPduSize : public QObject
{
    Q_OBJECT
private:
    static void row(const char *hex, Direction direction, Status status, int size)
    {
        const QByteArray pdu = QByteArray::fromHex(hex);
        const char *dir = direction == Direction::Request ? "req" : direction == Direction::Response ? "rsp" : "auto";
        QTest::addRow("%s %s", dir, pdu.toHex(' ').toUpper().constData()) << pdu << direction << status << size;
    }
    static void req(const char *hex, Status status, int size) { row(hex, Direction::Request, status, size); }
    static void rsp(const char *hex, Status status, int size) { row(hex, Direction::Response, status, size); }

private slots:
    void expected_data()
    {
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<Direction>("direction");
        QTest::addColumn<Status>("status");
        QTest::addColumn<int>("size");

        const Status C = Status::Complete;
        const Status N = Status::NeedMore;
        const Status U = Status::Unknown;

        // Nothing seen yet: the function code is needed first.
        req("", N, 1);
        rsp("", N, 1);

        // 01-04 (6.1-6.4): request start + quantity; response byte count + data.
        for (const char *code : {"01", "02", "03", "04"}) {
            req(code, C, 5);
            rsp(code, N, 2);
        }
        req("0100130013", C, 5);
        rsp("0103CD6B05", C, 5);
        req("0300790016", C, 5);
        rsp("032C", C, 46);        // RosRao response announces 44 bytes
        rsp("0302000A", C, 4);
        rsp("0300", C, 2);
        rsp("03FF", C, 257);       // sizes are reported as announced, even above 253
        rsp("0406", C, 8);
        rsp("0201", C, 3);

        // 05/06 (6.5, 6.6): same size both ways.
        req("05", C, 5);
        rsp("05", C, 5);
        req("06", C, 5);
        rsp("06000100 03", C, 5);

        // 07 (6.7), 0B (6.9), 0C (6.10), 11 (6.13).
        req("07", C, 1);
        rsp("07", C, 2);
        req("0B", C, 1);
        rsp("0B", C, 5);
        req("0C", C, 1);
        rsp("0C", N, 2);
        rsp("0C08", C, 10);
        req("11", C, 1);
        rsp("11", N, 2);
        rsp("1103", C, 5);

        // 08 (6.8): sub-function needed; standard sub-functions have one data word; 00 echoes any length.
        req("08", N, 3);
        req("0800", N, 3);
        rsp("08", N, 3);
        for (const char *sub : {"0001", "0002", "0003", "0004", "000A", "000B", "000C", "000D", "000E",
                                "000F", "0010", "0011", "0012", "0014"}) {
            const QByteArray pdu = "08" + QByteArray(sub);
            req(pdu.constData(), C, 5);
            rsp(pdu.constData(), C, 5);
        }
        req("080000", U, 0);
        rsp("080000A537", U, 0);
        for (const char *sub : {"0005", "0009", "0013", "0015", "0100", "FFFF"}) {
            const QByteArray pdu = "08" + QByteArray(sub);
            req(pdu.constData(), U, 0);
            rsp(pdu.constData(), U, 0);
        }

        // 0F/10 (6.11, 6.12): request byte count at offset 5; response echoes start + quantity.
        req("0F", N, 6);
        req("0F00130009", N, 6);
        req("0F0013000902", C, 8);
        rsp("0F", C, 5);
        req("10", N, 6);
        req("1000010002", N, 6);
        req("100001000204", C, 10);
        rsp("10", C, 5);

        // 14/15 (6.14, 6.15): byte count at offset 1 both ways.
        req("14", N, 2);
        req("140E", C, 16);
        rsp("14", N, 2);
        rsp("140C", C, 14);
        req("15", N, 2);
        req("150D", C, 15);
        rsp("15", N, 2);
        rsp("150D", C, 15);

        // 16 (6.16): address, AND mask, OR mask both ways.
        req("16", C, 7);
        rsp("16", C, 7);

        // 17 (6.17): request byte count at offset 9; response byte count at offset 1.
        req("17", N, 10);
        req("170003000600 0E0003", N, 10);
        req("1700030006000E000306", C, 16);
        rsp("17", N, 2);
        rsp("170C", C, 14);

        // 18 (6.18): request FIFO pointer; response 16-bit byte count at offset 1.
        req("18", C, 3);
        rsp("18", N, 3);
        rsp("1800", N, 3);
        rsp("180006", C, 9);
        rsp("180100", C, 259);

        // 2B/0E (6.21): request 4 bytes; response walked object by object.
        req("2B", N, 2);
        req("2B0E", C, 4);
        rsp("2B", N, 2);
        rsp("2B0E", N, 7);
        rsp("2B0E010100", N, 7);
        rsp("2B0E01010000 00", C, 7);             // no objects
        rsp("2B0E0101000003", N, 9);              // first object header needed
        rsp("2B0E010100000300", N, 9);
        rsp("2B0E01010000030016", N, 33);         // object 0 of 22 bytes, then object 1 header
        rsp("2B0E0101000003" "0016" "436F6D70616E79206964656E74696669636174696F6E"
            "0104" "50726F64", N, 39);
        rsp("2B0E0101000003" "0016" "436F6D70616E79206964656E74696669636174696F6E"
            "0104" "50726F64" "0205" "56322E3131", C, 44);
        rsp("2B0E0101FF0201" "0000", C, 9);       // one empty object
        // Other MEI types (0D CANopen, unassigned) have no length rule.
        req("2B0D", U, 0);
        rsp("2B0D", U, 0);
        req("2B00", U, 0);
        rsp("2BFF", U, 0);

        // Exceptions (7): 2 bytes as a response, impossible as a request.
        for (const char *code : {"81", "83", "90", "AB", "C1", "FF", "80"}) {
            rsp(code, C, 2);
            req(code, U, 0);
        }
        rsp("8302", C, 2);

        // User-defined, reserved and unassigned codes (5.1): no rule.
        for (const char *code : {"00", "09", "0A", "0D", "0E", "12", "13", "19", "29", "2A", "41", "48",
                                 "5A", "5B", "64", "6E", "7D", "7F"}) {
            req(code, U, 0);
            rsp(code, U, 0);
        }

        // Auto: exceptions are responses; agreeing rules are given; disagreeing ones are Unknown.
        row("83", Direction::Auto, C, 2);
        row("05", Direction::Auto, C, 5);
        row("16", Direction::Auto, C, 7);
        row("08", Direction::Auto, N, 3);
        row("080001", Direction::Auto, C, 5);
        row("14", Direction::Auto, N, 2);
        row("03", Direction::Auto, U, 0);
        row("07", Direction::Auto, U, 0);
        row("", Direction::Auto, N, 1);
        row("41", Direction::Auto, U, 0);
    }
    void expected()
    {
        QFETCH(QByteArray, pdu);
        QFETCH(Direction, direction);
        QFETCH(Status, status);
        QFETCH(int, size);
        const pdusize::Expected got = pdusize::expectedPduSize(pdu, direction);
        QCOMPARE(int(got.status), int(status));
        QCOMPARE(got.size, size);
    }

    // A completed rule must hold as more bytes arrive, and NeedMore must grow: feed every public
    // response prefix of a long 2B/0E frame and of a 0F request and check the answers are monotonic.
    void prefixesAreConsistent_data()
    {
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<Direction>("direction");
        QTest::newRow("rsp 2B 0E ... 3 objects") << QByteArray::fromHex(
            "2B0E01010000030016436F6D70616E79206964656E74696669636174696F6E010450726F64020556322E3131")
                                                  << Direction::Response;
        QTest::newRow("req 0F 00 13 00 0A 02 CD 01") << QByteArray::fromHex("0F0013000A02CD01") << Direction::Request;
        QTest::newRow("req 17 ...") << QByteArray::fromHex("1700030006000E00030600FF00FF00FF") << Direction::Request;
        QTest::newRow("rsp 18 00 06 00 02 01 B8 12 84") << QByteArray::fromHex("1800060002 01B81284") << Direction::Response;
    }
    void prefixesAreConsistent()
    {
        QFETCH(QByteArray, pdu);
        QFETCH(Direction, direction);
        int lastNeed = 0;
        for (int length = 0; length <= pdu.size(); ++length) {
            const pdusize::Expected got = pdusize::expectedPduSize(QByteArrayView(pdu).first(length), direction);
            if (got.status == Status::NeedMore) {
                QVERIFY2(got.size > length, "NeedMore must ask for more than is present");
                QVERIFY(got.size >= lastNeed);
                lastNeed = got.size;
            } else {
                QCOMPARE(int(got.status), int(Status::Complete));
                QCOMPARE(got.size, pdu.size());
            }
        }
    }

    // Never reads past the view, never loops: every two-byte prefix of every code, both directions.
    void everyCodeEveryDirectionTerminates()
    {
        QByteArray pdu(300, char(0xFF));
        for (int code = 0; code < 256; ++code) {
            pdu[0] = char(code);
            for (int length = 0; length <= pdu.size(); length += 7)
                for (Direction d : {Direction::Request, Direction::Response, Direction::Auto}) {
                    const pdusize::Expected got = pdusize::expectedPduSize(QByteArrayView(pdu).first(length), d);
                    if (got.status == Status::NeedMore)
                        QVERIFY(got.size > length);
                    QVERIFY(got.size >= 0);
                }
        }
    }
};

QTEST_GUILESS_MAIN(TestPduSize)
#include "tst_pdusize.moc"
