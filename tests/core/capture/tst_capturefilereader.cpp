// CaptureFileReader over small files built here byte by byte (capturebytes.h): every pcap and
// pcapng variant a capture tool writes, and damaged files, each with the message it must give
// and the packets it must still deliver.
#include "capturebytes.h"

#include "capture/capturefilereader.h"

#include <QtCore/QTemporaryFile>
#include <QtTest/QTest>

using namespace mbscope;
using namespace capturebytes;

namespace {

struct Seen {
    quint64 number = 0;
    qint64 offset = 0;
    qint64 timeNs = 0;
    quint32 linkType = 0;
    QByteArray data;
};

QList<Seen> readAll(const QByteArray &file, CaptureFileReader::Result *result)
{
    QList<Seen> seen;
    *result = CaptureFileReader::readBytes(file, [&seen](const CapturePacket &p) {
        seen.append(Seen{p.number, p.fileOffset, p.timeNs, p.linkType, p.data.toByteArray()});
    });
    return seen;
}

const QByteArray kFirst = QByteArray::fromHex("00112233445566778899aabbccddeeff0001");
const QByteArray kSecond = QByteArray::fromHex("0102030405");

} // namespace

class TestCaptureFileReader : public QObject
{
    Q_OBJECT

private slots:
    void variants_data();
    void variants();
    void damaged_data();
    void damaged();
    void fromFileInSmallReads();
};

void TestCaptureFileReader::variants_data()
{
    QTest::addColumn<QByteArray>("file");
    QTest::addColumn<int>("format");
    QTest::addColumn<qint64>("firstNs");
    QTest::addColumn<qint64>("secondNs");
    QTest::addColumn<quint32>("linkType");

    for (const bool big : {false, true}) {
        const QString order = big ? QStringLiteral("big-endian") : QStringLiteral("little-endian");
        QTest::addRow("pcap %s microseconds", qPrintable(order))
            << pcapHeader(big, false, 1) + pcapRecord(big, 1700000000, 123456, kFirst) + pcapRecord(big, 1700000001, 999999, kSecond)
            << int(TrafficFormat::Pcap) << 1700000000123456000LL << 1700000001999999000LL << 1u;
        QTest::addRow("pcap %s nanoseconds", qPrintable(order))
            << pcapHeader(big, true, 113) + pcapRecord(big, 1700000000, 123456789, kFirst) + pcapRecord(big, 1700000001, 5, kSecond)
            << int(TrafficFormat::Pcap) << 1700000000123456789LL << 1700000001000000005LL << 113u;
        QTest::addRow("pcapng %s default microseconds", qPrintable(order))
            << sectionHeader(big) + interfaceDescription(big, 1) + enhancedPacket(big, 0, 1700000000123456ULL, kFirst)
                   + enhancedPacket(big, 0, 1700000001000001ULL, kSecond)
            << int(TrafficFormat::Pcapng) << 1700000000123456000LL << 1700000001000001000LL << 1u;
        QTest::addRow("pcapng %s nanoseconds, name block between", qPrintable(order))
            << sectionHeader(big) + interfaceDescription(big, 276, 9) + block(big, 4, QByteArray(8, '\0'))
                   + enhancedPacket(big, 0, 1700000000123456789ULL, kFirst) + enhancedPacket(big, 0, 1700000001000000001ULL, kSecond)
            << int(TrafficFormat::Pcapng) << 1700000000123456789LL << 1700000001000000001LL << 276u;
        QTest::addRow("pcapng %s 2^-10 s and an offset", qPrintable(order))
            << sectionHeader(big) + interfaceDescription(big, 0, 0x80 | 10, 100) + enhancedPacket(big, 0, 1024 + 512, kFirst)
                   + enhancedPacket(big, 0, 2048 + 1, kSecond)
            << int(TrafficFormat::Pcapng) << 101500000000LL << 102000976563LL << 0u;
        QTest::addRow("pcapng %s obsolete packet blocks", qPrintable(order))
            << sectionHeader(big) + interfaceDescription(big, 1) + obsoletePacket(big, 0, 1700000000123456ULL, kFirst)
                   + obsoletePacket(big, 0, 1700000001000001ULL, kSecond)
            << int(TrafficFormat::Pcapng) << 1700000000123456000LL << 1700000001000001000LL << 1u;
    }
    // Two sections, the second with its own interfaces: interface 0 is a new one there.
    QTest::newRow("pcapng two sections")
        << sectionHeader(false) + interfaceDescription(false, 1, 9) + enhancedPacket(false, 0, 1000, kFirst) + sectionHeader(true)
               + interfaceDescription(true, 101, 6) + enhancedPacket(true, 0, 2000, kSecond)
        << int(TrafficFormat::Pcapng) << 1000LL << 2000000LL << 101u;
}

void TestCaptureFileReader::variants()
{
    QFETCH(QByteArray, file);
    QFETCH(int, format);
    QFETCH(qint64, firstNs);
    QFETCH(qint64, secondNs);
    QFETCH(quint32, linkType);
    CaptureFileReader::Result result;
    const QList<Seen> seen = readAll(file, &result);
    QVERIFY2(result.isComplete(), qPrintable(result.error));
    QCOMPARE(int(result.format), format);
    QCOMPARE(result.packets, quint64(2));
    QCOMPARE(result.goodBytes, qint64(file.size()));
    QCOMPARE(seen.size(), 2);
    QCOMPARE(seen.at(0).number, quint64(1));
    QCOMPARE(seen.at(1).number, quint64(2));
    QCOMPARE(seen.at(0).data, kFirst);
    QCOMPARE(seen.at(1).data, kSecond);
    QCOMPARE(seen.at(0).timeNs, firstNs);
    QCOMPARE(seen.at(1).timeNs, secondNs);
    QCOMPARE(seen.at(1).linkType, linkType);
}

void TestCaptureFileReader::damaged_data()
{
    QTest::addColumn<QByteArray>("file");
    QTest::addColumn<QString>("message");
    QTest::addColumn<qint64>("offset");
    QTest::addColumn<int>("packets");

    const QByteArray pcap = pcapHeader(false, false, 1) + pcapRecord(false, 1, 0, kFirst); // 24 + 16 + 18 = 58 bytes
    const QByteArray ng = sectionHeader(false) + interfaceDescription(false, 1); // 28 + 24 = 52 bytes
    const QByteArray ngFirst = ng + enhancedPacket(false, 0, 1, kFirst);       // + 52 = 104 bytes

    QTest::newRow("empty") << QByteArray() << QStringLiteral("the file is empty: not a capture") << 0LL << 0;
    QTest::newRow("html") << QByteArray("<!DOCTYPE html>")
                          << QStringLiteral("not a capture file: it starts with 3C 21 44 4F, where a pcap file starts with") << 0LL << 0;
    QTest::newRow("three bytes") << QByteArray("\xd4\xc3\xb2", 3) << QStringLiteral("not a capture file: it starts with D4 C3 B2,") << 0LL << 0;
    QTest::newRow("pcap header cut")
        << pcap.left(10) << QStringLiteral("at byte 0: the pcap file header is cut short: it needs 24 bytes, the file has 10") << 0LL << 0;
    QTest::newRow("pcap version 3")
        << pcapHeader(false, false, 1, 262144, 3) << QStringLiteral("at byte 4: pcap version 3.4 is not 2.4") << 4LL << 0;
    QTest::newRow("pcap record header cut")
        << pcap + QByteArray(5, '\1')
        << QStringLiteral("at byte 58: packet 2 is cut short: its record header needs 16 bytes, the file has 5") << 58LL << 1;
    QTest::newRow("pcap record body cut")
        << pcap + pcapRecord(false, 2, 0, kFirst).left(16 + 7)
        << QStringLiteral("at byte 58: packet 2 is cut short: its record says 18 captured bytes, the file ends 7 bytes after its header")
        << 58LL << 1;
    QTest::newRow("pcap impossible length")
        << pcap + pcapRecord(false, 2, 0, kFirst, 4000000000LL)
        << QStringLiteral("at byte 58: packet 2 claims 4000000000 captured bytes, more than the snap length of 262144") << 58LL << 1;
    QTest::newRow("pcap microseconds past a second")
        << pcap + pcapRecord(false, 2, 1000000, kFirst)
        << QStringLiteral("at byte 58: packet 2 has 1000000 microseconds in its time stamp") << 58LL << 1;
    QTest::newRow("pcapng block cut")
        << ngFirst + enhancedPacket(false, 0, 2, kSecond).left(30)
        << QStringLiteral("at byte 104: the block of type 0x00000006 is cut short: it says 40 bytes, the file has 30") << 104LL << 1;
    QTest::newRow("pcapng header cut")
        << ngFirst + QByteArray("\x06\0\0", 3)
        << QStringLiteral("at byte 104: a block is cut short: its header needs 8 bytes (12 for a section header), the file has 3")
        << 104LL << 1;
    {
        QByteArray odd = ngFirst;
        put32(odd, 6, false);
        put32(odd, 13, false);
        odd.append(QByteArray(8, '\0'));
        QTest::newRow("pcapng length not a multiple of 4")
            << odd << QStringLiteral("at byte 104: the block of type 0x00000006 says it is 13 bytes long, not a multiple of 4") << 104LL << 1;
    }
    QTest::newRow("pcapng trailing length differs")
        << ngFirst + block(false, 6, enhancedPacket(false, 0, 2, kSecond).mid(8, 28), 999)
        << QStringLiteral("at byte 140: the block of type 0x00000006 that starts at byte 104 ends with a length of 999 where it began with 40")
        << 140LL << 1;
    QTest::newRow("pcapng unknown interface")
        << ngFirst + enhancedPacket(false, 3, 2, kSecond)
        << QStringLiteral("at byte 104: packet 2 is on interface 3, but its section describes 1 interface(s)") << 104LL << 1;
    QTest::newRow("obsolete packet on an unknown interface")
        << ngFirst + obsoletePacket(false, 2, 2, kSecond)
        << QStringLiteral("at byte 104: packet 2 is on interface 2, but its section describes 1 interface(s)") << 104LL << 1;
    QTest::newRow("obsolete packet's captured length past its block")
        << ngFirst + obsoletePacket(false, 0, 2, kSecond, 400)
        << QStringLiteral("at byte 104: packet 2 says 400 captured bytes, more than its block of 40 bytes holds") << 104LL << 1;
    QTest::newRow("pcapng captured length past its block")
        << ngFirst + enhancedPacket(false, 0, 2, kSecond, 400)
        << QStringLiteral("at byte 104: packet 2 says 400 captured bytes, more than its block of 40 bytes holds") << 104LL << 1;
    {
        QByteArray badMagic = sectionHeader(false);
        badMagic[8] = 'X';
        QTest::newRow("pcapng byte-order magic")
            << badMagic << QStringLiteral("at byte 8: the section header's byte-order magic is 1A2B3C58, not 1A2B3C4D") << 8LL << 0;
    }
}

void TestCaptureFileReader::damaged()
{
    QFETCH(QByteArray, file);
    QFETCH(QString, message);
    QFETCH(qint64, offset);
    QFETCH(int, packets);
    CaptureFileReader::Result result;
    const QList<Seen> seen = readAll(file, &result);
    QVERIFY(!result.isComplete());
    QVERIFY2(result.error.startsWith(message), qPrintable(QStringLiteral("got: ") + result.error));
    QCOMPARE(result.errorOffset, offset);
    QCOMPARE(seen.size(), packets);
    QCOMPARE(result.packets, quint64(packets));
    if (packets > 0)
        QCOMPARE(seen.constFirst().data, kFirst);
}

// A file larger than the reader's buffer, read from disk: records straddle its refills.
void TestCaptureFileReader::fromFileInSmallReads()
{
    QByteArray file = pcapHeader(false, true, 1);
    const int count = 30000;
    for (int i = 0; i < count; ++i)
        file += pcapRecord(false, quint32(i), quint32(i), QByteArray(1 + i % 97, char(i)));
    QTemporaryFile temp;
    QVERIFY(temp.open());
    QCOMPARE(temp.write(file), qint64(file.size()));
    temp.close();
    int seen = 0;
    bool same = true;
    const CaptureFileReader::Result result = CaptureFileReader::readFile(temp.fileName(), [&](const CapturePacket &p) {
        same = same && p.data == QByteArray(1 + seen % 97, char(seen)) && p.timeNs == qint64(seen) * 1000000000LL + seen;
        ++seen;
    });
    QVERIFY2(result.isComplete(), qPrintable(result.error));
    QCOMPARE(seen, count);
    QVERIFY(same);
    QCOMPARE(result.fileBytes, qint64(file.size()));
}

QTEST_GUILESS_MAIN(TestCaptureFileReader)
#include "tst_capturefilereader.moc"
