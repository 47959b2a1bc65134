#include "protocol/adubuilder.h"
#include "protocol/rtuframer.h"

#include "framertesting.h"

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

using namespace mbscope;
using framertesting::frame;
using framertesting::skip;

Q_DECLARE_METATYPE(mbscope::Direction)

// RTU framing by predicted length and CRC (MODBUS over Serial Line V1.02, 2.5.1). Frames: RosRao,
// Arduino RS485 and the serial tutorial (tests/data, published-frames), and the PDU examples of
// the Application Protocol V1.1b3, section 6, completed with AduBuilder.
class TestRtuFramer : public QObject
{
    Q_OBJECT
private:
    static QByteArray hex(const char *text) { return QByteArray::fromHex(text); }
    static QByteArray rtu(const char *pdu, quint8 unit = 0x11) { return AduBuilder::rtu(hex(pdu), unit); }
    // Every request/response pair of V1.1b3 section 6 (its own examples where it gives them).
    static QList<std::pair<QByteArray, QByteArray>> pairs()
    {
        return {
            {rtu("0100130013"), rtu("0103CD6B05")},
            {rtu("0200C40016"), rtu("0203ACDB35")},
            {rtu("03006B0003"), rtu("0306022B00000064")},
            {rtu("0400080001"), rtu("0402000A")},
            {rtu("0500ACFF00"), rtu("0500ACFF00")},
            {rtu("0600010003"), rtu("0600010003")},
            {rtu("07"), rtu("076D")},
            {rtu("0800010000"), rtu("0800010000")},
            {rtu("08000B0000"), rtu("08000B0123")},
            {rtu("0B"), rtu("0BFFFF0108")},
            {rtu("0C"), rtu("0C08000001080121" "2000")},
            {rtu("0F0013000A02CD01"), rtu("0F0013000A")},
            {rtu("100001000204000A0102"), rtu("1000010002")},
            {rtu("11"), rtu("1103" "01FF00")},
            {rtu("140E0600040001000206000300090002"), rtu("140C05060DFE0020050633CD0040")},
            {rtu("150D0600040007000306AF04BE100D"), rtu("150D0600040007000306AF04BE100D")},
            {rtu("16000400F20025"), rtu("16000400F20025")},
            {rtu("170003000600 0E00030600FF00FF00FF"), rtu("170C00FE0ACD00010003000D00FF")},
            {rtu("1804DE"), rtu("1800060002 01B81284")},
            {rtu("2B0E0100"), rtu("2B0E010100000200044143 4D4501025031")},
            {rtu("0300010001"), rtu("8302")},
            {rtu("2B0E0100"), rtu("AB01")},
            {rtu("1000010002040001 0002"), rtu("9004")},
        };
    }

private slots:
    void timing_data()
    {
        QTest::addColumn<int>("baud");
        QTest::addColumn<qint64>("character");
        QTest::addColumn<qint64>("t15");
        QTest::addColumn<qint64>("t35");
        // 11 bits per character; fixed 750 us / 1750 us above 19200 baud (Serial Line V1.02, 2.5.1.1).
        QTest::newRow("9600") << 9600 << qint64(1145833) << qint64(1718750) << qint64(4010416);
        QTest::newRow("19200 (still computed)") << 19200 << qint64(572916) << qint64(859375) << qint64(2005208);
        QTest::newRow("1200") << 1200 << qint64(9166666) << qint64(13750000) << qint64(32083333);
        QTest::newRow("38400 (fixed)") << 38400 << qint64(286458) << qint64(750000) << qint64(1750000);
        QTest::newRow("115200 (fixed)") << 115200 << qint64(95486) << qint64(750000) << qint64(1750000);
        QTest::newRow("0 (unknown)") << 0 << qint64(0) << qint64(0) << qint64(0);
    }
    void timing()
    {
        QFETCH(int, baud);
        QFETCH(qint64, character);
        QFETCH(qint64, t15);
        QFETCH(qint64, t35);
        QCOMPARE(RtuFramer::characterTimeNs(baud), character);
        QCOMPARE(RtuFramer::t15Ns(baud), t15);
        QCOMPARE(RtuFramer::t35Ns(baud), t35);
    }

    void stream_data()
    {
        QTest::addColumn<Direction>("direction");
        framertesting::streamColumns();
        const Direction Req = Direction::Request;
        const Direction Rsp = Direction::Response;
        const Direction Auto = Direction::Auto;

        const QByteArray rosrao = hex("01030079001615DD");
        const QByteArray arduinoReq = hex("0103000000044409");
        const QByteArray arduinoRsp = hex("01030800450 04E00010001791D");
        const QByteArray tutorialReq = hex("070300C80004C591");
        const QByteArray tutorialRsp = hex("0703080007000600050004645D");
        const QByteArray inputReq = hex("0704012C00037058");
        const QByteArray inputRsp = hex("070406 03E801F4000AEB1E");

        for (Direction d : {Req, Auto}) {
            const char *name = d == Req ? "req" : "auto";
            QTest::addRow("%s 01 03 00 79 00 16 15 DD", name) << d << rosrao << QStringList{frame(0, rosrao)} << false;
            QTest::addRow("%s 01 03 00 00 00 04 44 09", name) << d << arduinoReq << QStringList{frame(0, arduinoReq)} << false;
            QTest::addRow("%s 07 03 00 C8 00 04 C5 91", name) << d << tutorialReq << QStringList{frame(0, tutorialReq)} << false;
            QTest::addRow("%s 07 04 01 2C 00 03 70 58", name) << d << inputReq << QStringList{frame(0, inputReq)} << false;
        }
        for (Direction d : {Rsp, Auto}) {
            const char *name = d == Rsp ? "rsp" : "auto";
            QTest::addRow("%s 01 03 08 00 45 00 4E 00 01 00 01 79 1D", name) << d << arduinoRsp << QStringList{frame(0, arduinoRsp)} << false;
            QTest::addRow("%s 07 03 08 00 07 00 06 00 05 00 04 64 5D", name) << d << tutorialRsp << QStringList{frame(0, tutorialRsp)} << false;
            QTest::addRow("%s 07 04 06 03 E8 01 F4 00 0A EB 1E", name) << d << inputRsp << QStringList{frame(0, inputRsp)} << false;
        }
        QTest::newRow("auto request, response, request, response merged")
            << Auto << tutorialReq + tutorialRsp + inputReq + inputRsp
            << QStringList{frame(0, tutorialReq), frame(8, tutorialRsp), frame(21, inputReq), frame(29, inputRsp)} << false;

        // The RosRao response as printed lost two registers: the byte count announces 44 data bytes,
        // 42 bytes follow. At the silence it comes out Truncated (the dissector then says what is missing).
        const QByteArray rosraoRsp = hex("01 03 2C 04 1A 00 00 00 00 00 00 00 FA 00 01 03 E8 27 10 00 04 00 04 00 50 03 "
                                         "20 1F 40 00 00 00 00 00 00 00 00 00 00 00 00 00 00 15 72");
        QTest::newRow("rsp rosrao response as printed, silence")
            << Rsp << rosraoRsp << QStringList{frame(0, rosraoRsp, " truncated")} << true;
        // Followed by another response without a silence, the predicted 49 bytes have a wrong CRC:
        // the 45 bytes are skipped and the next response found.
        QTest::newRow("rsp rosrao response as printed, then arduino response")
            << Rsp << rosraoRsp + arduinoRsp << QStringList{skip(0, 45, "crc"), frame(45, arduinoRsp)} << false;

        // Garbage before, between, after.
        QTest::newRow("req FF FF before 01 03 00 79 00 16 15 DD")
            << Req << hex("FFFF") + rosrao << QStringList{skip(0, 2, "function"), frame(2, rosrao)} << false;
        QTest::newRow("rsp FF FF before 01 03 08 ... 79 1D")
            << Rsp << hex("FFFF") + arduinoRsp << QStringList{skip(0, 2, "crc"), frame(2, arduinoRsp)} << false;
        QTest::newRow("req 00 (turnaround glitch) before 01 03 00 00 00 04 44 09")
            << Req << hex("00") + arduinoReq << QStringList{skip(0, 1, "crc"), frame(1, arduinoReq)} << false;
        QTest::newRow("req garbage between")
            << Req << rosrao + hex("00 00 00") + arduinoReq
            << QStringList{frame(0, rosrao), skip(8, 3, "function"), frame(11, arduinoReq)} << false;
        QTest::newRow("auto garbage between request and response")
            << Auto << tutorialReq + hex("55AA55") + tutorialRsp
            << QStringList{frame(0, tutorialReq), skip(8, 3, "crc"), frame(11, tutorialRsp)} << false;
        QTest::newRow("req garbage after, then silence")
            << Req << rosrao + hex("FF")
            << QStringList{frame(0, rosrao), skip(8, 1, "incomplete")} << true;
        QTest::newRow("req garbage after, no silence: held")
            << Req << rosrao + hex("FF") << QStringList{frame(0, rosrao)} << false;

        // A lost byte: the damaged frame and what follows it are skipped until a valid frame.
        QTest::newRow("req lost byte in the middle")
            << Req << hex("0103007900 1615DD") .remove(3, 1) + arduinoReq + tutorialReq
            << QStringList{skip(0, 7, "crc"), frame(7, arduinoReq), frame(15, tutorialReq)} << false;
        QTest::newRow("rsp lost byte in the middle")
            << Rsp << tutorialRsp.left(6) + tutorialRsp.mid(7) + arduinoRsp + inputRsp
            << QStringList{skip(0, 12, "crc"), frame(12, arduinoRsp), frame(25, inputRsp)} << false;

        // Wrong CRC: the frame is skipped as a whole run.
        QTest::newRow("req wrong CRC 01 03 00 79 00 16 15 DE")
            << Req << hex("01030079001615DE") + arduinoReq
            << QStringList{skip(0, 8, "crc"), frame(8, arduinoReq)} << false;

        // Codes without a length rule: at a boundary the first valid CRC ends them.
        const QByteArray userDefined = rtu("41010203", 1);
        const QByteArray echo = rtu("08000012345678", 1);
        const QByteArray canopen = rtu("2B0D0001020304", 1);
        QTest::newRow("req user-defined 41 at a boundary") << Req << userDefined + rosrao
                                                           << QStringList{frame(0, userDefined), frame(7, rosrao)} << false;
        QTest::newRow("rsp 08 0000 echo of any length") << Rsp << echo + arduinoRsp
                                                        << QStringList{frame(0, echo), frame(10, arduinoRsp)} << false;
        QTest::newRow("auto 2B 0D at a boundary") << Auto << canopen << QStringList{frame(0, canopen)} << false;
        // After garbage, a code without a length rule cannot be trusted: skipped until a known frame.
        QTest::newRow("req garbage then user-defined 41: skipped")
            << Req << hex("FFFF") + userDefined + rosrao << QStringList{skip(0, 9, "function"), frame(9, rosrao)} << false;
        // With a wrong CRC it ends at the silence and comes out Unverified.
        QTest::newRow("req user-defined with a wrong CRC, silence")
            << Req << hex("4142434445") << QStringList{frame(0, hex("4142434445"), " unverified")} << true;
        QTest::newRow("req silence splits: user-defined wrong CRC, silence handled per row")
            << Req << hex("0141") << QStringList{frame(0, hex("0141"), " unverified")} << true;

        // Impossible function codes in the direction given.
        QTest::newRow("req 01 83 02 C0 F1 (an exception) is impossible as a request")
            << Req << rtu("8302", 1) + rosrao << QStringList{skip(0, 5, "function"), frame(5, rosrao)} << false;
        QTest::newRow("rsp 01 83 02 C0 F1") << Rsp << rtu("8302", 1) << QStringList{frame(0, rtu("8302", 1))} << false;
        QTest::newRow("rsp function code 00") << Rsp << hex("0100") + arduinoRsp
                                              << QStringList{skip(0, 2, "function"), frame(2, arduinoRsp)} << false;

        // A byte count no RTU frame can carry (03 with 255 bytes: 260 bytes).
        QTest::newRow("rsp 01 03 FF: too long")
            << Rsp << hex("0103FF") + arduinoRsp << QStringList{skip(0, 3, "toolong"), frame(3, arduinoRsp)} << false;

        // Pending bytes of a frame that started after garbage are skipped at the silence.
        QTest::newRow("req garbage then half a frame, silence")
            << Req << hex("0000") + rosrao.left(5)
            << QStringList{skip(0, 7, "function")} << true;
        // At a boundary, the same bytes are a frame cut short.
        QTest::newRow("req half a frame, silence")
            << Req << rosrao.left(5) << QStringList{frame(0, rosrao.left(5), " truncated")} << true;
        QTest::newRow("req one byte then silence") << Req << hex("01") << QStringList{skip(0, 1, "incomplete")} << true;
    }
    void stream()
    {
        QFETCH(Direction, direction);
        framertesting::checkStreamRow([direction] { return std::make_unique<RtuFramer>(direction); });
    }

    // Every code's request and response, one after another, in each framer direction.
    void everyCode_data()
    {
        QTest::addColumn<Direction>("direction");
        QTest::newRow("request") << Direction::Request;
        QTest::newRow("response") << Direction::Response;
        QTest::newRow("auto") << Direction::Auto;
    }
    void everyCode()
    {
        QFETCH(Direction, direction);
        QByteArray stream;
        QStringList expected;
        for (const auto &[request, response] : pairs()) {
            if (direction != Direction::Response) {
                expected.append(frame(stream.size(), request));
                stream += request;
            }
            if (direction != Direction::Request) {
                expected.append(frame(stream.size(), response));
                stream += response;
            }
        }
        framertesting::checkAllChunkings([direction] { return std::make_unique<RtuFramer>(direction); }, stream,
                                         expected, false);
    }

    // A slave's framer (setDropsBadFrames, the simulator's endpoints): a request whose CRC fails is
    // dropped whole and the next request read at once, even one of a code without a length rule
    // (08/0000); the search (without it) passes that one over until the silence.
    void dropsBadFrames_data()
    {
        QTest::addColumn<bool>("drops");
        QTest::addColumn<QByteArray>("stream");
        QTest::addColumn<QStringList>("expected");
        QByteArray bad = rtu("0300000003", 0x01);
        bad[6] = char(~quint8(bad.at(6)));
        bad[7] = char(~quint8(bad.at(7)));
        const QByteArray echo = rtu("0800001234", 0x01);
        const QByteArray read = rtu("0300000003", 0x01);
        QTest::newRow("bad CRC, then 08/0000, dropped") << true << bad + echo << QStringList{skip(0, 8, "crc"), frame(8, echo)};
        QTest::newRow("bad CRC, then a read, dropped") << true << bad + read << QStringList{skip(0, 8, "crc"), frame(8, read)};
        QTest::newRow("two bad CRCs, then 08/0000, dropped")
            << true << bad + bad + echo << QStringList{skip(0, 16, "crc"), frame(16, echo)}; // the two dropped: one run
        // The search: the echo's start is passed over (no length rule), the silence ends it all.
        QTest::newRow("bad CRC, then 08/0000, searched") << false << bad + echo << QStringList{skip(0, 16, "crc")};
    }
    void dropsBadFrames()
    {
        QFETCH(bool, drops);
        QFETCH(QByteArray, stream);
        QFETCH(QStringList, expected);
        framertesting::checkAllChunkings(
            [drops] {
                auto framer = std::make_unique<RtuFramer>(Direction::Request);
                framer->setDropsBadFrames(drops);
                return framer;
            },
            stream, expected, true);
    }

    void silenceByTime()
    {
        RtuFramer framer(Direction::Request);
        framer.setBaudRate(9600);
        const qint64 t35 = RtuFramer::t35Ns(9600);
        framer.feed(hex("4142"), 1'000'000);
        QVERIFY(!framer.onSilence(1'000'000 + t35 - 1));
        QCOMPARE(framer.pendingSize(), 2);
        QVERIFY(framer.onSilence(1'000'000 + t35));
        const QList<StreamFrame> frames = framer.takeFrames();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].status, FrameStatus::Unverified);
        QCOMPARE(frames[0].problem,
                 QStringLiteral("function code 0x42 has no length rule: the frame was ended by the silence and no CRC in it is valid"));
        QCOMPARE(frames[0].firstByteNs, 1'000'000);
    }

    void truncatedProblem()
    {
        RtuFramer framer(Direction::Response);
        framer.feed(hex("01032C041A"));
        framer.flushOnSilence();
        const QList<StreamFrame> frames = framer.takeFrames();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].problem,
                 QStringLiteral("the function code and byte count predict 49 bytes but only 5 arrived before the silence"));
    }

    // Random bytes with valid frames mixed in and random silences: no hang, every byte accounted for,
    // pending bytes bounded, the same output whatever the chunking.
    void randomBytes_data()
    {
        QTest::addColumn<Direction>("direction");
        QTest::newRow("request") << Direction::Request;
        QTest::newRow("response") << Direction::Response;
        QTest::newRow("auto") << Direction::Auto;
    }
    void randomBytes()
    {
        QFETCH(Direction, direction);
        QRandomGenerator random(7 + int(direction));
        const auto all = pairs();
        for (int round = 0; round < 10; ++round) {
            QByteArray stream;
            QList<qsizetype> silences;
            while (stream.size() < 8000) {
                const int pick = int(random.bounded(6));
                if (pick == 0) {
                    for (int i = int(random.bounded(1, 30)); i > 0; --i)
                        stream.append(char(random.bounded(256)));
                } else if (pick == 1) {
                    silences.append(stream.size());
                } else {
                    const auto &pair = all.at(random.bounded(all.size()));
                    stream += random.bounded(2) ? pair.first : pair.second;
                }
            }
            auto run = [&](bool oneByOne) {
                RtuFramer framer(direction);
                framertesting::Outcome outcome;
                qsizetype at = 0;
                int nextSilence = 0;
                while (at < stream.size()) {
                    while (nextSilence < silences.size() && silences[nextSilence] <= at) {
                        framer.flushOnSilence();
                        ++nextSilence;
                    }
                    qsizetype end = oneByOne ? at + 1 : qMin<qsizetype>(stream.size(), at + random.bounded(1, 300));
                    if (nextSilence < silences.size() && silences[nextSilence] > at)
                        end = qMin(end, silences[nextSilence]);
                    framer.feed(QByteArrayView(stream).sliced(at, end - at));
                    at = end;
                    if (framer.pendingSize() > RtuFramer::kMaxAduSize + 300)
                        return framertesting::Outcome{};
                    outcome.take(framer);
                }
                framer.flushOnSilence();
                outcome.take(framer);
                return outcome;
            };
            const framertesting::Outcome bytewise = run(true);
            const framertesting::Outcome chunked = run(false);
            QVERIFY(bytewise.accountsFor(stream.size()));
            QVERIFY(chunked.accountsFor(stream.size()));
            QCOMPARE(chunked.describe(), bytewise.describe());
            QVERIFY(!bytewise.frames.isEmpty());
        }
    }

    void pureNoiseIsBounded()
    {
        QRandomGenerator random(99);
        RtuFramer framer(Direction::Auto);
        QByteArray chunk(64, Qt::Uninitialized);
        qint64 fed = 0;
        framertesting::Outcome outcome;
        for (int i = 0; i < 2000; ++i) {
            for (char &c : chunk)
                c = char(random.bounded(256));
            framer.feed(chunk);
            fed += chunk.size();
            QVERIFY(framer.pendingSize() <= RtuFramer::kMaxAduSize + chunk.size());
            outcome.take(framer);
        }
        QVERIFY(outcome.accountsFor(fed));
    }
};

QTEST_GUILESS_MAIN(TestRtuFramer)
#include "tst_rtuframer.moc"
