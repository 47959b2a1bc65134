// "No per-field heap allocation on the hot path" (issue 2): once a Dissection has been used, a
// dissection with explicit framing and direction of a valid frame must not allocate at all
// (allocations counted by allocationcounter.h; skipped where they cannot be).
#include "allocationcounter.h"
#include "protocol/adubuilder.h"
#include "protocol/dissector.h"

#include <QtTest/QtTest>

using namespace mbscope;

class TestAllocations : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        if (!allocationcounter::available)
            QSKIP("allocations cannot be counted in this build (a sanitizer owns the allocator, or not glibc)");
        // The counter must see allocations: a test that cannot fail proves nothing.
        allocationcounter::start();
        QByteArray probe(100, 'x');
        probe.append("more, to be sure it reallocates or allocates");
        QVERIFY(allocationcounter::stop() > 0);
    }

    void dissectAllocatesNothing_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<int>("framing");
        QTest::addColumn<int>("direction");

        auto row = [](const char *name, const QByteArray &frame, Framing framing, Direction direction) {
            QTest::newRow(name) << frame << int(framing) << int(direction);
        };
        // Published frames (tests/data/published-frames.json).
        row("rtu 01 03 00 79 00 16 15 DD (rosrao request)", QByteArray::fromHex("01030079001615DD"), Framing::Rtu,
            Direction::Request);
        row("rtu 01 03 08 00 45 00 4E 00 01 00 01 79 1D (arduino response)",
            QByteArray::fromHex("010308004500" "4E00010001791D"), Framing::Rtu, Direction::Response);
        row("tcp 00 01 00 00 00 09 00 10 00 00 00 01 02 00 CD (m221 request)",
            QByteArray::fromHex("000100000009001000000001" "0200CD"), Framing::Tcp, Direction::Request);
        row("udp 00 01 00 00 00 06 00 10 00 00 00 01 (m221 reply)", QByteArray::fromHex("000100000006001000000001"),
            Framing::Udp, Direction::Response);
        row("pdu 0F 00 00 00 01 01 01 (m221 write bits)", QByteArray::fromHex("0F000000010101"), Framing::Pdu,
            Direction::Request);
        // The largest read response: 125 registers, 255 bytes in RTU (V1.1b3 6.3).
        QByteArray pdu = QByteArray::fromHex("03FA");
        for (int i = 0; i < 125; ++i)
            pdu.append(char(i >> 8)).append(char(i & 0xFF));
        row("rtu 01 03 FA ... (125 registers, 255 bytes)", AduBuilder::rtu(pdu, 1), Framing::Rtu, Direction::Response);
        row("tcp 00 07 00 00 00 FE 01 03 FA ... (125 registers)", AduBuilder::mbap(pdu, 1, 7), Framing::Tcp,
            Direction::Response);
        // Spec examples (V1.1b3 6.1, 6.8, 6.14, 6.21): bits, sub-functions, groups, objects.
        row("rtu 01 01 03 CD 6B 05 (6.1 response)", AduBuilder::rtu(QByteArray::fromHex("0103CD6B05"), 1), Framing::Rtu,
            Direction::Response);
        row("rtu 01 08 00 00 A5 37 (6.8 request)", AduBuilder::rtu(QByteArray::fromHex("08" "0000A537"), 1), Framing::Rtu,
            Direction::Request);
        row("rtu 01 14 0C 05 06 0D FE ... (6.14 response)",
            AduBuilder::rtu(QByteArray::fromHex("140C05060DFE0020050633CD0040"), 1), Framing::Rtu, Direction::Response);
        row("rtu 01 2B 0E 01 01 00 00 01 00 03 41 42 43 (6.21 response)",
            AduBuilder::rtu(QByteArray::fromHex("2B0E010100000100" "03414243"), 1), Framing::Rtu, Direction::Response);
        row("rtu 01 83 02 (exception)", AduBuilder::rtu(QByteArray::fromHex("8302"), 1), Framing::Rtu,
            Direction::Response);
    }

    void dissectAllocatesNothing()
    {
        QFETCH(QByteArray, frame);
        QFETCH(int, framing);
        QFETCH(int, direction);
        const DissectOptions options{Framing(framing), Direction(direction), {}};

        Dissection out;
        Dissector::dissect(frame, options, out); // warm up: the tree grows to the frame's size once
        QVERIFY2(out.isValid(), "the frame must be valid: problem messages are allowed to allocate");

        allocationcounter::start();
        for (int i = 0; i < 1000; ++i)
            Dissector::dissect(frame, options, out);
        QCOMPARE(allocationcounter::stop(), 0L);
        QVERIFY(out.isValid());
    }
};

QTEST_GUILESS_MAIN(TestAllocations)
#include "tst_allocations.moc"
