#include "protocol/checksum.h"

#include <QtTest/QtTest>

using namespace mbscope;

// Vectors: CRC-16/MODBUS check value from the CRC catalogue ("123456789" -> 0x4B37), and RTU
// frames printed in the field publications (tests/data/published-frames.md).
class TestChecksum : public QObject
{
    Q_OBJECT
private slots:
    void crc16_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("crc");
        QTest::newRow("catalogue check 123456789") << QByteArray("123456789") << 0x4B37;
        QTest::newRow("empty is the initial value") << QByteArray() << 0xFFFF;
        QTest::newRow("01 03 00 79 00 16 (rosrao)") << QByteArray::fromHex("010300790016") << 0xDD15;
        QTest::newRow("01 03 00 00 00 04 (arduino)") << QByteArray::fromHex("010300000004") << 0x0944;
        QTest::newRow("01 03 08 00 45 00 4E 00 01 00 01") << QByteArray::fromHex("010308004500" "4E00010001") << 0x1D79;
        QTest::newRow("07 03 00 C8 00 04 (tutorial)") << QByteArray::fromHex("070300C80004") << 0x91C5;
        QTest::newRow("07 04 06 03 E8 01 F4 00 0A") << QByteArray::fromHex("070406" "03E801F4000A") << 0x1EEB;
    }
    void crc16()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(int, crc);
        QCOMPARE(int(checksum::crc16Modbus(bytes)), crc);
    }
    void crcOverFrameWithCrcIsZero()
    {
        // Appending the CRC low byte first makes the CRC over the whole frame zero.
        QCOMPARE(int(checksum::crc16Modbus(QByteArray::fromHex("01030079001615DD"))), 0);
    }
    void lrc_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("lrc");
        QTest::newRow("07 03 00 C8 00 04 (tutorial ascii)") << QByteArray::fromHex("070300C80004") << 0x2A;
        QTest::newRow("serial line spec example 11 03 00 6B 00 03") << QByteArray::fromHex("1103006B0003") << 0x7E;
        QTest::newRow("empty") << QByteArray() << 0x00;
        QTest::newRow("sum wraps: FF 01") << QByteArray::fromHex("FF01") << 0x00;
        QTest::newRow("single 01") << QByteArray::fromHex("01") << 0xFF;
    }
    void lrc()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(int, lrc);
        QCOMPARE(int(checksum::lrc(bytes)), lrc);
    }
};

QTEST_GUILESS_MAIN(TestChecksum)
#include "tst_checksum.moc"
