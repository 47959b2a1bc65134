#include "protocol/adubuilder.h"
#include "protocol/mbapframer.h"

#include "framertesting.h"

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

using namespace mbscope;

// MBAP framing by the length field (MODBUS Messaging on TCP/IP V1.0b, 3.1.3). Frames: the M221
// lab paper (tests/data, published-frames) and frames built with AduBuilder.
class TestMbapFramer : public QObject
{
    Q_OBJECT
private:
    static std::unique_ptr<StreamFramer> make() { return std::make_unique<MbapFramer>(); }
    static QByteArray hex(const char *text) { return QByteArray::fromHex(text); }

private slots:
    void stream_data()
    {
        framertesting::streamColumns();

        const QByteArray m221Request = hex("000100000009001000000001020" "0CD");
        const QByteArray m221Reply = hex("000100000006001000000001");
        const QByteArray exception = AduBuilder::mbap(hex("9002"), 0, 2);
        const QByteArray longest = AduBuilder::mbap(QByteArray(253, char(0x03)), 1, 3);

        QTest::newRow("00 01 00 00 00 09 00 10 00 00 00 01 02 00 CD")
            << m221Request << QStringList{QStringLiteral("frame @0 000100000009001000000001020" "0CD")} << false;
        QTest::newRow("request + reply merged")
            << m221Request + m221Reply
            << QStringList{QStringLiteral("frame @0 0001000000090010000000010200CD"),
                           QStringLiteral("frame @15 000100000006001000000001")}
            << false;
        QTest::newRow("exception 00 02 00 00 00 03 00 90 02")
            << exception << QStringList{QStringLiteral("frame @0 000200000003009002")} << false;
        QTest::newRow("largest: length 254") << longest
                                             << QStringList{QStringLiteral("frame @0 %1").arg(QString::fromLatin1(longest.toHex().toUpper()))}
                                             << false;
        QTest::newRow("smallest: length 2 (unit + function code)")
            << hex("00050000000201 07") << QStringList{QStringLiteral("frame @0 00050000000201" "07")} << false;
        // FF FF FF: the protocol id seen at each start is not 0 until the real header.
        QTest::newRow("garbage before")
            << hex("FFFFFF") + m221Reply
            << QStringList{QStringLiteral("skip @0 3 header"), QStringLiteral("frame @3 000100000006001000000001")}
            << false;
        QTest::newRow("garbage between")
            << m221Request + hex("AA55") + m221Reply
            << QStringList{QStringLiteral("frame @0 0001000000090010000000010200CD"), QStringLiteral("skip @15 2 header"),
                           QStringLiteral("frame @17 000100000006001000000001")}
            << false;
        // Trailing bytes: the run is reported when the connection goes quiet.
        QTest::newRow("garbage after, then silence")
            << m221Reply + hex("0102")
            << QStringList{QStringLiteral("frame @0 000100000006001000000001"), QStringLiteral("skip @12 2 incomplete")}
            << true;
        QTest::newRow("incomplete frame at silence")
            << m221Reply + m221Request.left(10)
            << QStringList{QStringLiteral("frame @0 000100000006001000000001"), QStringLiteral("skip @12 10 incomplete")}
            << true;
        // Protocol id 0 but length 0, 1 or 255: each start is skipped in turn.
        QTest::newRow("length 1 is invalid")
            << hex("000700000001") + m221Reply
            << QStringList{QStringLiteral("skip @0 6 header"), QStringLiteral("frame @6 000100000006001000000001")}
            << false;
        QTest::newRow("length 255 is invalid")
            << hex("0007000000FF") + m221Reply
            << QStringList{QStringLiteral("skip @0 6 header"), QStringLiteral("frame @6 000100000006001000000001")}
            << false;
        QTest::newRow("protocol id 1 is invalid")
            << hex("000700010006") + m221Reply
            << QStringList{QStringLiteral("skip @0 6 header"), QStringLiteral("frame @6 000100000006001000000001")}
            << false;
        // A byte lost from the first header's length: no start inside the damaged frame has protocol
        // id 0 and a length of 2..254, so all 14 bytes are skipped and the next frames are found.
        QTest::newRow("lost byte in the first header")
            << hex("00010000" "09" "001000000001020" "0CD") + m221Reply + m221Reply
            << QStringList{QStringLiteral("skip @0 14 header"), QStringLiteral("frame @14 000100000006001000000001"),
                           QStringLiteral("frame @26 000100000006001000000001")}
            << false;
        // A byte lost from the PDU: the length still claims 9, so the frame swallows the next
        // frame's first byte; the rest of that frame is skipped and the one after is found.
        QTest::newRow("lost byte in the first PDU")
            << hex("000100000009" "0010000000010200") + m221Reply + m221Reply
            << QStringList{QStringLiteral("frame @0 000100000009001000000001020000"),
                           QStringLiteral("skip @15 11 header"), QStringLiteral("frame @26 000100000006001000000001")}
            << false;
    }
    void stream() { framertesting::checkStreamRow(&make); }

    void timestamps()
    {
        MbapFramer framer;
        const QByteArray reply = hex("000100000006001000000001");
        framer.feed(QByteArrayView(reply).first(5), 1000);
        framer.feed(QByteArrayView(reply).sliced(5, 5), 2000);
        QVERIFY(!framer.hasFrames());
        framer.feed(QByteArrayView(reply).sliced(10), 3000);
        framer.feed(reply, 4000);
        const QList<StreamFrame> frames = framer.takeFrames();
        QCOMPARE(frames.size(), 2);
        QCOMPARE(frames[0].firstByteNs, 1000);
        QCOMPARE(frames[0].lastByteNs, 3000);
        QCOMPARE(frames[1].offset, 12);
        QCOMPARE(frames[1].firstByteNs, 4000);
        QCOMPARE(frames[1].lastByteNs, 4000);
        QCOMPARE(framer.lastFeedNs(), 4000);
    }

    void resetStartsAgain()
    {
        MbapFramer framer;
        framer.feed(hex("0001000000060010"));
        framer.reset();
        QCOMPARE(framer.pendingSize(), 0);
        framer.feed(hex("000100000006001000000001"));
        const QList<StreamFrame> frames = framer.takeFrames();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].offset, 0);
        QVERIFY(framer.takeSkipped().isEmpty());
    }

    // Random bytes in random chunks, with valid frames mixed in: no hang, every byte accounted for,
    // bounded pending bytes, and the same result whatever the chunking.
    void randomBytes()
    {
        QRandomGenerator random(20240611);
        for (int round = 0; round < 20; ++round) {
            QByteArray stream;
            while (stream.size() < 20000) {
                if (random.bounded(4) == 0) {
                    QByteArray pdu(int(random.bounded(1, 254)), Qt::Uninitialized);
                    for (char &c : pdu)
                        c = char(random.bounded(256));
                    stream += AduBuilder::mbap(pdu, quint8(random.bounded(256)), quint16(random.bounded(65536)));
                } else {
                    for (int i = int(random.bounded(1, 40)); i > 0; --i)
                        stream.append(char(random.bounded(256)));
                }
            }
            framertesting::checkRandomChunks(make, stream, random, 600, 6 + MbapFramer::kMaxLength, false);
            if (QTest::currentTestFailed())
                return;
        }
    }
};

QTEST_GUILESS_MAIN(TestMbapFramer)
#include "tst_mbapframer.moc"
