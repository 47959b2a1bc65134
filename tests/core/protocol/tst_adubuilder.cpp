#include "protocol/adubuilder.h"
#include "protocol/framingtraits.h"

#include <QtTest/QtTest>

using namespace mbscope;

Q_DECLARE_METATYPE(mbscope::Framing)

// Frames from tests/data (published-frames): RosRao, Arduino RS485, the serial tutorial and the M221
// lab paper; the ASCII example of MODBUS over Serial Line V1.02, 2.5.2.1 (11 03 00 6B 00 03, LRC 7E).
class TestAduBuilder : public QObject
{
    Q_OBJECT
private slots:
    void rtu_data()
    {
        QTest::addColumn<int>("unit");
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<QByteArray>("adu");
        auto row = [](int unit, const char *pdu, const char *adu) {
            QTest::newRow(adu) << unit << QByteArray::fromHex(pdu) << QByteArray::fromHex(adu);
        };
        row(1, "0300790016", "01030079001615DD");
        row(1, "0300000004", "010300000004" "4409");
        row(1, "030800450 04E00010001", "01030800450 04E00010001791D");
        row(7, "0300C80004", "070300C80004C591");
        row(7, "030800070006000500 04", "0703080007000600050004645D");
        row(7, "04012C0003", "0704012C00037058");
        row(7, "040603E801F4000A", "070406 03E801F4000AEB1E");
    }
    void rtu()
    {
        QFETCH(int, unit);
        QFETCH(QByteArray, pdu);
        QFETCH(QByteArray, adu);
        QCOMPARE(AduBuilder::rtu(pdu, quint8(unit)), adu);
        QCOMPARE(AduBuilder::complete(pdu, {Framing::Rtu, quint8(unit), 0, 0}), adu);

        const AduParts parts = AduBuilder::parseRtu(adu);
        QVERIFY(parts.complete);
        QVERIFY(parts.error.isEmpty());
        QCOMPARE(int(parts.unitId), unit);
        QCOMPARE(parts.pdu, pdu);
        QVERIFY(parts.checksumPresent);
        QVERIFY(parts.checksumValid());
        QCOMPARE(parts.checksum, parts.expectedChecksum);
    }
    void rtuWrongCrcIsReportedNotRepaired()
    {
        const QByteArray wrong = QByteArray::fromHex("010300790016FFFF");
        const AduParts parts = AduBuilder::parseRtu(wrong);
        QVERIFY(parts.complete);
        QVERIFY(!parts.checksumValid());
        QCOMPARE(int(parts.checksum), 0xFFFF);
        QCOMPARE(int(parts.expectedChecksum), 0xDD15);
        // Given as a whole ADU, the bytes go out unchanged, wrong CRC and all.
        QCOMPARE(AduBuilder::outgoing(wrong, Completion::AsGiven, {Framing::Rtu, 1, 0, 0}), wrong);
    }
    void rtuShort_data()
    {
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<QByteArray>("pdu");
        QTest::newRow("empty") << QByteArray() << QByteArray();
        QTest::newRow("01") << QByteArray::fromHex("01") << QByteArray();
        QTest::newRow("01 03") << QByteArray::fromHex("0103") << QByteArray::fromHex("03");
        QTest::newRow("01 03 15") << QByteArray::fromHex("010315") << QByteArray::fromHex("0315");
    }
    void rtuShort()
    {
        QFETCH(QByteArray, adu);
        QFETCH(QByteArray, pdu);
        const AduParts parts = AduBuilder::parseRtu(adu);
        QVERIFY(!parts.complete);
        QVERIFY(!parts.checksumPresent);
        QVERIFY(!parts.error.isEmpty());
        QCOMPARE(parts.pdu, pdu);
    }

    void ascii_data()
    {
        QTest::addColumn<int>("unit");
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<int>("lrc");
        QTest::newRow(":070300C800042A") << 7 << QByteArray::fromHex("0300C80004")
                                         << QByteArray(":070300C800042A\r\n") << 0x2A;
        QTest::newRow(":1103006B00037E") << 0x11 << QByteArray::fromHex("03006B0003")
                                         << QByteArray(":1103006B00037E\r\n") << 0x7E;
        QTest::newRow(":01070 F8 (07 request)") << 1 << QByteArray::fromHex("07")
                                                << QByteArray(":0107F8\r\n") << 0xF8;
    }
    void ascii()
    {
        QFETCH(int, unit);
        QFETCH(QByteArray, pdu);
        QFETCH(QByteArray, adu);
        QFETCH(int, lrc);
        QCOMPARE(AduBuilder::ascii(pdu, quint8(unit)), adu);
        QCOMPARE(AduBuilder::complete(pdu, {Framing::Ascii, quint8(unit), 0, 0}), adu);
        const AduParts parts = AduBuilder::parseAscii(adu);
        QVERIFY2(parts.complete, qPrintable(parts.error));
        QCOMPARE(int(parts.unitId), unit);
        QCOMPARE(parts.pdu, pdu);
        QCOMPARE(int(parts.checksum), lrc);
        QVERIFY(parts.checksumValid());
        // Lower-case digits are read too.
        const AduParts lower = AduBuilder::parseAscii(adu.toLower());
        QVERIFY(lower.complete);
        QCOMPARE(lower.pdu, pdu);
    }
    void asciiMalformed_data()
    {
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<bool>("checksumPresent");
        QTest::addColumn<QString>("error");
        QTest::newRow("no colon") << QByteArray("070300C800042A\r\n") << false << QStringLiteral("an ASCII frame starts with ':'");
        QTest::newRow("no CR LF") << QByteArray(":070300C800042A") << true << QStringLiteral("an ASCII frame ends with CR LF");
        QTest::newRow("odd digits") << QByteArray(":070300C800042\r\n") << false << QStringLiteral("odd number of hex digits (13)");
        QTest::newRow("bad digit") << QByteArray(":0703G0C800042A\r\n") << false
                                   << QStringLiteral("character 5 (0x47) is not a hex digit");
        QTest::newRow("too short") << QByteArray(":0701\r\n") << true
                                   << QStringLiteral("an ASCII frame needs a unit id, a function code and an LRC (6 hex digits), only 4 present");
    }
    void asciiMalformed()
    {
        QFETCH(QByteArray, adu);
        QFETCH(bool, checksumPresent);
        QFETCH(QString, error);
        const AduParts parts = AduBuilder::parseAscii(adu);
        QVERIFY(!parts.complete);
        QCOMPARE(parts.checksumPresent, checksumPresent);
        QCOMPARE(parts.error, error);
    }
    void asciiWrongLrc()
    {
        const AduParts parts = AduBuilder::parseAscii(":070300C8000400\r\n");
        QVERIFY(parts.complete);
        QVERIFY(!parts.checksumValid());
        QCOMPARE(int(parts.expectedChecksum), 0x2A);
    }

    void mbap_data()
    {
        QTest::addColumn<int>("transaction");
        QTest::addColumn<int>("unit");
        QTest::addColumn<QByteArray>("pdu");
        QTest::addColumn<QByteArray>("adu");
        QTest::newRow("00 01 00 00 00 09 00 10 00 00 00 01 02 00 CD (m221)")
            << 1 << 0 << QByteArray::fromHex("1000000001020 0CD") << QByteArray::fromHex("000100000009001000000001020 0CD");
        QTest::newRow("00 01 00 00 00 06 00 10 00 00 00 01 (m221 reply)")
            << 1 << 0 << QByteArray::fromHex("1000000001") << QByteArray::fromHex("000100000006001000000001");
        QTest::newRow("AB CD 00 00 00 06 11 03 00 6B 00 03")
            << 0xABCD << 0x11 << QByteArray::fromHex("03006B0003") << QByteArray::fromHex("ABCD00000006" "1103006B0003");
        QTest::newRow("FF FF 00 00 00 03 FF 83 02")
            << 0xFFFF << 0xFF << QByteArray::fromHex("8302") << QByteArray::fromHex("FFFF00000003FF8302");
    }
    void mbap()
    {
        QFETCH(int, transaction);
        QFETCH(int, unit);
        QFETCH(QByteArray, pdu);
        QFETCH(QByteArray, adu);
        QCOMPARE(AduBuilder::mbap(pdu, quint8(unit), quint16(transaction)), adu);
        QCOMPARE(AduBuilder::complete(pdu, {Framing::Tcp, quint8(unit), quint16(transaction), 0}), adu);
        QCOMPARE(AduBuilder::complete(pdu, {Framing::Udp, quint8(unit), quint16(transaction), 0}), adu);
        const AduParts parts = AduBuilder::parseMbap(adu);
        QVERIFY(parts.complete);
        QVERIFY(parts.error.isEmpty());
        QVERIFY(parts.lengthMatches);
        QCOMPARE(int(parts.transactionId), transaction);
        QCOMPARE(int(parts.protocolId), 0);
        QCOMPARE(int(parts.length), pdu.size() + 1);
        QCOMPARE(int(parts.unitId), unit);
        QCOMPARE(parts.pdu, pdu);
        QVERIFY(!parts.checksumPresent);
    }
    void mbapProtocolIdOnPurpose()
    {
        const QByteArray adu = AduBuilder::mbap(QByteArray::fromHex("0300000001"), 1, 7, 0x1234);
        QCOMPARE(adu, QByteArray::fromHex("00071234000601" "0300000001"));
        QCOMPARE(int(AduBuilder::parseMbap(adu).protocolId), 0x1234);
    }
    void mbapLengthMismatch()
    {
        // Length says 9 but only 8 bytes follow it: the PDU is what is present, the mismatch is said.
        const AduParts parts = AduBuilder::parseMbap(QByteArray::fromHex("000100000009001000000001 0200"));
        QVERIFY(parts.complete);
        QVERIFY(!parts.lengthMatches);
        QCOMPARE(parts.error, QStringLiteral("length field 9 counts 9 bytes after it but 8 are present"));
        QCOMPARE(parts.pdu, QByteArray::fromHex("10000000010200"));
    }
    void mbapShort()
    {
        for (int size = 0; size < 8; ++size) {
            const QByteArray adu = QByteArray::fromHex("0001000000090010").left(size);
            const AduParts parts = AduBuilder::parseMbap(adu);
            QVERIFY(!parts.complete);
            QVERIFY(parts.pdu.isEmpty());
            QVERIFY(!parts.error.isEmpty());
        }
    }

    void outgoing_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<Framing>("framing");
        QTest::addColumn<int>("completion");
        QTest::addColumn<QByteArray>("expected");
        const QByteArray pdu = QByteArray::fromHex("0300790016");
        QTest::newRow("as given rtu") << pdu << Framing::Rtu << int(Completion::AsGiven) << pdu;
        QTest::newRow("as given tcp") << pdu << Framing::Tcp << int(Completion::AsGiven) << pdu;
        QTest::newRow("as given ascii") << pdu << Framing::Ascii << int(Completion::AsGiven) << pdu;
        QTest::newRow("complete rtu") << pdu << Framing::Rtu << int(Completion::CompletePdu)
                                      << QByteArray::fromHex("01030079001615DD");
        QTest::newRow("complete tcp") << pdu << Framing::Tcp << int(Completion::CompletePdu)
                                      << QByteArray::fromHex("002A00000006010300790016");
        QTest::newRow("complete ascii") << pdu << Framing::Ascii << int(Completion::CompletePdu)
                                        << QByteArray(":0103007900166D\r\n");
        QTest::newRow("complete pdu is unchanged") << pdu << Framing::Pdu << int(Completion::CompletePdu) << pdu;
    }
    void outgoing()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(Framing, framing);
        QFETCH(int, completion);
        QFETCH(QByteArray, expected);
        QCOMPARE(AduBuilder::outgoing(bytes, Completion(completion), {framing, 1, 42, 0}), expected);
    }

    // Round trip: build then take apart, for every unit id and a spread of PDU sizes.
    // The framing table (framingtraits.h) against what AduBuilder really adds and the limits the
    // specifications give: V1.1b3 4.1 (PDU 253), Serial Line V1.02 2.5.1.1 (RTU 256) and 2.5.2.1
    // (ASCII 513 characters), TCP/IP V1.0b 4.1 (MBAP 260).
    void framingTraits_data()
    {
        QTest::addColumn<Framing>("framing");
        QTest::addColumn<bool>("serialLine");
        QTest::addColumn<bool>("mbap");
        QTest::addColumn<int>("maxFrame");
        QTest::addColumn<QString>("title");
        QTest::addColumn<QString>("check");
        QTest::newRow("rtu") << Framing::Rtu << true << false << 256 << "RTU" << "CRC";
        QTest::newRow("ascii") << Framing::Ascii << true << false << 513 << "ASCII" << "LRC";
        QTest::newRow("tcp") << Framing::Tcp << false << true << 260 << "Modbus TCP" << QString();
        QTest::newRow("udp") << Framing::Udp << false << true << 260 << "Modbus UDP" << QString();
        QTest::newRow("pdu") << Framing::Pdu << false << false << 253 << "PDU" << QString();
    }
    void framingTraits()
    {
        QFETCH(Framing, framing);
        QFETCH(bool, serialLine);
        QFETCH(bool, mbap);
        QFETCH(int, maxFrame);
        QFETCH(QString, title);
        QFETCH(QString, check);
        const FramingTraits &t = mbscope::framingTraits(framing);
        QCOMPARE(t.serialLine, serialLine);
        QCOMPARE(isSerialLine(framing), serialLine);
        QCOMPARE(t.mbap, mbap);
        QCOMPARE(t.maxFrameBytes, maxFrame);
        QCOMPARE(QLatin1String(t.title), title);
        QCOMPARE(t.checkName ? QString::fromLatin1(t.checkName) : QString(), check);
        QVERIFY(QByteArray(t.maxFrameRule).contains(QByteArray::number(maxFrame)));

        // What the framing adds to a PDU, once decoded, is headerBytes before it and checkBytes after.
        const QByteArray pdu = QByteArray::fromHex("0300790016");
        const QByteArray adu = AduBuilder::complete(pdu, AduOptions{framing, 1, 7, 0});
        const AduParts parts = AduBuilder::parse(adu, framing);
        QCOMPARE(parts.pdu, pdu);
        const qsizetype decoded = framing == Framing::Ascii ? (adu.size() - 3) / 2 : adu.size();
        QCOMPARE(decoded, t.headerBytes + pdu.size() + t.checkBytes);

        // The largest PDU (253 bytes) makes the largest frame.
        const QByteArray largest = AduBuilder::complete(QByteArray(253, '\x03'), AduOptions{framing, 1, 7, 0});
        QCOMPARE(int(largest.size()), maxFrame);
    }

    void roundTrip()
    {
        QByteArray pdu;
        for (int size = 1; size <= 253; size += 12) {
            pdu.resize(size);
            for (int i = 0; i < size; ++i)
                pdu[i] = char((i * 37 + size) & 0xFF);
            for (int unit : {0, 1, 17, 247, 255}) {
                for (Framing framing : {Framing::Rtu, Framing::Ascii, Framing::Tcp, Framing::Udp}) {
                    const QByteArray adu = AduBuilder::complete(pdu, {framing, quint8(unit), quint16(size), 0});
                    const AduParts parts = AduBuilder::parse(adu, framing);
                    QVERIFY(parts.complete);
                    QCOMPARE(parts.framing, framing);
                    QCOMPARE(int(parts.unitId), unit);
                    QCOMPARE(parts.pdu, pdu);
                    if (framing == Framing::Rtu || framing == Framing::Ascii)
                        QVERIFY(parts.checksumValid());
                    else
                        QCOMPARE(int(parts.transactionId), size);
                }
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestAduBuilder)
#include "tst_adubuilder.moc"
