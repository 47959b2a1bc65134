#include "protocol/delimitedframer.h"

#include "framertesting.h"

#include <QtTest/QtTest>

using namespace mbscope;
using framertesting::frame;
using framertesting::skip;

Q_DECLARE_METATYPE(mbscope::DelimitedFraming)

// Delimited framing (issue 3): frames from a start byte to an end byte, optionally followed by a
// checksum byte. The issue's examples: a Raspberry Pi SCADA's home-made ASCII protocol ('$01R#'
// answered by '$01 293 295 #': start=24, end=23), and LG Master-K style ENQ (05) ... EOT (04) + BCC.
// The BCC values below were computed by hand (python: sum(frame) & 0xFF), not by the framer.
class TestDelimitedFramer : public QObject
{
    Q_OBJECT
private:
    static DelimitedFraming dollarHash() { return DelimitedFraming{true, QByteArray("$"), QByteArray("#"), DelimitedChecksum::None, true}; }
    static DelimitedFraming enqEot(DelimitedChecksum checksum)
    {
        return DelimitedFraming{true, QByteArray("\x05"), QByteArray("\x04"), checksum, true};
    }

private slots:
    void stream_data()
    {
        QTest::addColumn<DelimitedFraming>("framing");
        framertesting::streamColumns();

        const QByteArray request("$01R#");
        const QByteArray answer("$01 293 295 #");
        QTest::newRow("$01R#") << dollarHash() << request << QStringList{frame(0, request)} << false;
        QTest::newRow("$01 293 295 #") << dollarHash() << answer << QStringList{frame(0, answer)} << false;
        QTest::newRow("request and answer merged")
            << dollarHash() << request + answer << QStringList{frame(0, request), frame(5, answer)} << false;
        QTest::newRow("garbage before") << dollarHash() << QByteArray("xx\r\n") + request
                                        << QStringList{skip(0, 4, "noframe"), frame(4, request)} << false;
        QTest::newRow("garbage between") << dollarHash() << request + QByteArray("\r\n") + answer
                                         << QStringList{frame(0, request), skip(5, 2, "noframe"), frame(7, answer)} << false;
        QTest::newRow("garbage after, silence") << dollarHash() << request + QByteArray("zz")
                                                << QStringList{frame(0, request), skip(5, 2, "noframe")} << true;
        QTest::newRow("garbage after, no silence: held") << dollarHash() << request + QByteArray("zz")
                                                         << QStringList{frame(0, request)} << false;
        QTest::newRow("incomplete at silence") << dollarHash() << request + QByteArray("$01 29")
                                               << QStringList{frame(0, request), skip(5, 6, "incomplete")} << true;
        QTest::newRow("incomplete, no silence: held") << dollarHash() << QByteArray("$01 29") << QStringList{} << false;
        // A start byte inside a frame restarts it, as a lost end byte would leave it.
        QTest::newRow("restart by '$'") << dollarHash() << QByteArray("$01R") + answer
                                        << QStringList{skip(0, 4, "abandoned"), frame(4, answer)} << false;
        QTest::newRow("empty frame $#") << dollarHash() << QByteArray("$#") << QStringList{frame(0, QByteArray("$#"))} << false;
        QTest::newRow("end byte without start") << dollarHash() << QByteArray("#") + request
                                                << QStringList{skip(0, 1, "noframe"), frame(1, request)} << false;

        // No start byte: a frame runs from the previous end to the next end.
        const DelimitedFraming lines{true, QByteArray(), QByteArray("\n"), DelimitedChecksum::None, true};
        QTest::newRow("lines: 'abc LF def LF'") << lines << QByteArray("abc\ndef\n")
                                                << QStringList{frame(0, "abc\n"), frame(4, "def\n")} << false;
        QTest::newRow("lines: empty line") << lines << QByteArray("\n\n") << QStringList{frame(0, "\n"), frame(1, "\n")} << false;
        QTest::newRow("lines: tail at silence") << lines << QByteArray("abc\nde")
                                                << QStringList{frame(0, "abc\n"), skip(4, 2, "incomplete")} << true;

        // Start and end bytes the same: the end is tested first.
        const DelimitedFraming pipes{true, QByteArray("|"), QByteArray("|"), DelimitedChecksum::None, true};
        QTest::newRow("|abc||def|") << pipes << QByteArray("|abc||def|") << QStringList{frame(0, "|abc|"), frame(5, "|def|")}
                                    << false;

        // Several start bytes: an LG Master-K answer begins with ACK (06) or NAK (15) and ends with
        // ETX (03), BCC after it no checksum here.
        const DelimitedFraming ackNak{true, QByteArray("\x06\x15"), QByteArray("\x03"), DelimitedChecksum::None, true};
        const QByteArray ack("\x06" "00RSS010201F4" "\x03");
        const QByteArray nak("\x15" "00RSS0004" "\x03");
        QTest::newRow("ACK ... ETX, NAK ... ETX") << ackNak << ack + nak << QStringList{frame(0, ack), frame(ack.size(), nak)} << false;
        QTest::newRow("noise, then NAK") << ackNak << QByteArray("\x05x") + nak
                                         << QStringList{skip(0, 2, "noframe"), frame(2, nak)} << false;
        QTest::newRow("NAK restarts an open ACK frame") << ackNak << QByteArray("\x06" "00R") + nak
                                                        << QStringList{skip(0, 4, "abandoned"), frame(4, nak)} << false;
        // Several end bytes: CR or LF ends a line.
        const DelimitedFraming crOrLf{true, QByteArray(), QByteArray("\r\n"), DelimitedChecksum::None, true};
        QTest::newRow("lines ended by CR or LF") << crOrLf << QByteArray("ab\rcd\n")
                                                 << QStringList{frame(0, "ab\r"), frame(3, "cd\n")} << false;

        // ENQ ... EOT + BCC (8-bit sum from ENQ to EOT): 05 "00RSS0106%MW100" 04 -> 0x82, XOR 0x5A.
        const QByteArray masterK = QByteArray("\x05" "00RSS0106%MW100" "\x04");
        QTest::newRow("ENQ 00RSS0106%MW100 EOT BCC 82")
            << enqEot(DelimitedChecksum::Sum) << masterK + '\x82' << QStringList{frame(0, masterK + '\x82')} << false;
        QTest::newRow("ENQ ... EOT XOR 5A") << enqEot(DelimitedChecksum::Xor) << masterK + '\x5A'
                                            << QStringList{frame(0, masterK + '\x5A')} << false;
        QTest::newRow("ENQ ... EOT BCC wrong: malformed")
            << enqEot(DelimitedChecksum::Sum) << masterK + '\x83' << QStringList{frame(0, masterK + '\x83', " malformed")} << false;
        QTest::newRow("ENQ ... EOT, BCC not yet arrived: held")
            << enqEot(DelimitedChecksum::Sum) << masterK << QStringList{} << false;
        QTest::newRow("ENQ ... EOT, BCC missing at silence")
            << enqEot(DelimitedChecksum::Sum) << masterK << QStringList{skip(0, masterK.size(), "incomplete")} << true;
        QTest::newRow("ENQ ... EOT BCC, twice")
            << enqEot(DelimitedChecksum::Sum) << masterK + '\x82' + masterK + '\x82'
            << QStringList{frame(0, masterK + '\x82'), frame(18, masterK + '\x82')} << false;
        // The checksum byte is taken as it is, even when it equals the start or the end byte:
        // 05 7E 7E 04 sums to 0x105, so its BCC is 05 (ENQ); 05 7D 7E 04 sums to 0x104 -> BCC 04 (EOT).
        QTest::newRow("BCC equal to ENQ")
            << enqEot(DelimitedChecksum::Sum) << QByteArray("\x05~~\x04\x05") + masterK + '\x82'
            << QStringList{frame(0, QByteArray("\x05~~\x04\x05")), frame(5, masterK + '\x82')} << false;
        QTest::newRow("BCC equal to EOT")
            << enqEot(DelimitedChecksum::Sum) << QByteArray("\x05}~\x04\x04") + masterK + '\x82'
            << QStringList{frame(0, QByteArray("\x05}~\x04\x04")), frame(5, masterK + '\x82')} << false;
        QTest::newRow("garbage before ENQ")
            << enqEot(DelimitedChecksum::Sum) << QByteArray("\x06\x03") + masterK + '\x82'
            << QStringList{skip(0, 2, "noframe"), frame(2, masterK + '\x82')} << false;

        // The longest frame is accepted; one byte more without an end is skipped (in runs of at
        // most 256 bytes), and the next frame is found.
        const QByteArray longest = '$' + QByteArray(DelimitedFramer::kMaxFrameSize - 2, 'a') + '#';
        QTest::newRow("longest: 4096 bytes") << dollarHash() << longest << QStringList{frame(0, longest)} << false;
        const QByteArray tooLong = '$' + QByteArray(DelimitedFramer::kMaxFrameSize - 1, 'a') + '#';
        QStringList expected;
        for (int at = 0; at < DelimitedFramer::kMaxFrameSize; at += 256)
            expected.append(skip(at, 256, "toolong"));
        expected.append(skip(DelimitedFramer::kMaxFrameSize, 1, "noframe"));
        expected.append(frame(DelimitedFramer::kMaxFrameSize + 1, request));
        QTest::newRow("too long, then a frame") << dollarHash() << tooLong + request << expected << false;
    }
    void stream()
    {
        QFETCH(DelimitedFraming, framing);
        framertesting::checkStreamRow([framing] { return std::make_unique<DelimitedFramer>(framing); });
    }

    void malformedProblem()
    {
        DelimitedFramer framer(enqEot(DelimitedChecksum::Sum));
        framer.feed(QByteArray("\x05" "00RSS0106%MW100" "\x04\x83"));
        const auto frames = framer.takeFrames();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames.first().status, FrameStatus::Malformed);
        QCOMPARE(frames.first().problem,
                 QStringLiteral("checksum 0x83 does not match 0x82, the 8-bit sum (BCC) of the 17 bytes up to the end byte"));

        DelimitedFramer xorFramer(enqEot(DelimitedChecksum::Xor));
        xorFramer.feed(QByteArray("\x05" "00RSS0106%MW100" "\x04\x00", 18));
        QCOMPARE(xorFramer.takeFrames().first().problem,
                 QStringLiteral("checksum 0x00 does not match 0x5A, the XOR of the 17 bytes up to the end byte"));
    }

    void timestamps()
    {
        DelimitedFramer framer(dollarHash());
        framer.feed(QByteArray("$01 2"), 1000);
        framer.feed(QByteArray("93 295 #$01R#"), 2000);
        const auto frames = framer.takeFrames();
        QCOMPARE(frames.size(), 2);
        QCOMPARE(frames.at(0).firstByteNs, qint64(1000));
        QCOMPARE(frames.at(0).lastByteNs, qint64(2000));
        QCOMPARE(frames.at(1).firstByteNs, qint64(2000));
        QCOMPARE(frames.at(1).lastByteNs, qint64(2000));
    }

    void checksums_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("sum");
        QTest::addColumn<int>("xorValue");
        QTest::newRow("empty") << QByteArray() << 0 << 0;
        QTest::newRow("05 00RSS0106%MW100 04") << QByteArray("\x05" "00RSS0106%MW100" "\x04") << 0x82 << 0x5A;
        QTest::newRow("FF FF: sum wraps") << QByteArray("\xFF\xFF") << 0xFE << 0x00;
        QTest::newRow("$01R#") << QByteArray("$01R#") << 0xFA << 0x54;
    }
    void checksums()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(int, sum);
        QFETCH(int, xorValue);
        QCOMPARE(int(DelimitedFramer::checksum(DelimitedChecksum::Sum, bytes)), sum);
        QCOMPARE(int(DelimitedFramer::checksum(DelimitedChecksum::Xor, bytes)), xorValue);
        QCOMPARE(int(DelimitedFramer::checksum(DelimitedChecksum::None, bytes)), 0);
    }

    void complete()
    {
        QCOMPARE(DelimitedFramer::complete(enqEot(DelimitedChecksum::Sum), QByteArray("\x05" "00RSS0106%MW100" "\x04")),
                 QByteArray("\x05" "00RSS0106%MW100" "\x04\x82"));
        QCOMPARE(DelimitedFramer::complete(dollarHash(), QByteArray("$01R#")), QByteArray("$01R#"));
    }

    void toText_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("text");
        QTest::newRow("$01 293 295 #") << QByteArray("$01 293 295 #") << QStringLiteral("$01 293 295 #");
        QTest::newRow("ENQ 00RSS EOT 82") << QByteArray("\x05" "00RSS" "\x04\x82")
                                          << QStringLiteral("<ENQ>00RSS<EOT>\\x82");
        QTest::newRow("CR LF NUL DEL") << QByteArray("a\r\n\x00\x7F", 5) << QStringLiteral("a<CR><LF><NUL><DEL>");
        QTest::newRow("ACK ETX NAK") << QByteArray("\x06\x03\x15") << QStringLiteral("<ACK><ETX><NAK>");
    }
    void toText()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, text);
        QCOMPARE(DelimitedFramer::toText(bytes), text);
    }
};

QTEST_GUILESS_MAIN(TestDelimitedFramer)
#include "tst_delimitedframer.moc"
