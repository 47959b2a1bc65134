#include "protocol/adubuilder.h"
#include "protocol/asciiframer.h"

#include "framertesting.h"

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

using namespace mbscope;
using framertesting::frame;
using framertesting::skip;

// ASCII framing by ':' and CR LF (MODBUS over Serial Line V1.02, 2.5.2). Frames: the serial
// tutorial's ":070300C800042A" (tests/data, published-frames) and the spec's example
// 11 03 00 6B 00 03 (LRC 7E), completed with AduBuilder.
class TestAsciiFramer : public QObject
{
    Q_OBJECT
private:
    static std::unique_ptr<StreamFramer> make() { return std::make_unique<AsciiFramer>(); }

private slots:
    void stream_data()
    {
        framertesting::streamColumns();

        const QByteArray tutorial(":070300C800042A\r\n");
        const QByteArray spec(":1103006B00037E\r\n");
        const QByteArray exception = AduBuilder::ascii(QByteArray::fromHex("8302"), 0x11);
        const QByteArray longest = AduBuilder::ascii(QByteArray(253, char(0x10)), 0xF7);

        QTest::newRow(":070300C800042A CR LF") << tutorial << QStringList{frame(0, tutorial)} << false;
        QTest::newRow("two merged") << tutorial + spec << QStringList{frame(0, tutorial), frame(17, spec)} << false;
        QTest::newRow("exception :118302 6A") << exception << QStringList{frame(0, exception)} << false;
        QTest::newRow("longest: 513 characters") << longest << QStringList{frame(0, longest)} << false;
        QTest::newRow("lower-case digits") << QByteArray(":070300c800042a\r\n")
                                           << QStringList{frame(0, QByteArray(":070300c800042a\r\n"))} << false;

        QTest::newRow("garbage before") << QByteArray("xy\r\n") + tutorial
                                        << QStringList{skip(0, 4, "noframe"), frame(4, tutorial)} << false;
        QTest::newRow("garbage between") << tutorial + QByteArray("\n\n?") + spec
                                         << QStringList{frame(0, tutorial), skip(17, 3, "noframe"), frame(20, spec)} << false;
        // Bytes outside a frame are reported when the next frame starts or at a silence.
        QTest::newRow("garbage after, silence") << tutorial + QByteArray("zz")
                                                << QStringList{frame(0, tutorial), skip(17, 2, "noframe")} << true;
        QTest::newRow("garbage after, no silence: held") << tutorial + QByteArray("zz") << QStringList{frame(0, tutorial)} << false;
        QTest::newRow("incomplete frame at silence") << tutorial + spec.left(9)
                                                     << QStringList{frame(0, tutorial), skip(17, 9, "incomplete")} << true;

        // A ':' restarts the frame: the abandoned part is skipped (as a lost CR LF would leave it).
        QTest::newRow("restart by ':'") << QByteArray(":0703") + tutorial
                                        << QStringList{skip(0, 5, "abandoned"), frame(5, tutorial)} << false;
        QTest::newRow("lost CR LF") << tutorial.left(15) + spec
                                    << QStringList{skip(0, 15, "abandoned"), frame(15, spec)} << false;
        QTest::newRow("lost byte in the middle")
            << tutorial + QByteArray(":1103006B0037E\r\n") + tutorial
            << QStringList{frame(0, tutorial), frame(17, QByteArray(":1103006B0037E\r\n"), " malformed"), frame(33, tutorial)}
            << false;

        // Delimited but wrong: emitted, Malformed.
        QTest::newRow("wrong LRC") << QByteArray(":070300C8000400\r\n")
                                   << QStringList{frame(0, QByteArray(":070300C8000400\r\n"), " malformed")} << false;
        QTest::newRow("non-hex digit") << QByteArray(":0703G0C800042A\r\n")
                                       << QStringList{frame(0, QByteArray(":0703G0C800042A\r\n"), " malformed")} << false;
        QTest::newRow("LF without CR") << QByteArray(":070300C800042A\n")
                                       << QStringList{frame(0, QByteArray(":070300C800042A\n"), " malformed")} << false;
        QTest::newRow("too short") << QByteArray(":07F9\r\n") << QStringList{frame(0, QByteArray(":07F9\r\n"), " malformed")} << false;
        QTest::newRow("empty frame") << QByteArray(":\r\n") << QStringList{frame(0, QByteArray(":\r\n"), " malformed")} << false;

        // 513 characters without the end: abandoned (reported in runs of at most 256 bytes), then
        // the next frame is found.
        const QByteArray runaway = ':' + QByteArray(600, '0');
        QTest::newRow("too long") << runaway + tutorial
                                  << QStringList{skip(0, 256, "toolong"), skip(256, 256, "toolong"), skip(512, 1, "toolong"),
                                                 skip(513, 88, "noframe"), frame(601, tutorial)}
                                  << false;
    }
    void stream() { framertesting::checkStreamRow(&make); }

    void problems_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<QString>("problem");
        QTest::newRow(":070300C800042A") << QByteArray(":070300C800042A\r\n") << QString();
        QTest::newRow(":070300C8000400") << QByteArray(":070300C8000400\r\n")
                                         << QStringLiteral("LRC 0x00 does not match 0x2A computed over the unit id and PDU");
        QTest::newRow(":0703G0C800042A") << QByteArray(":0703G0C800042A\r\n")
                                         << QStringLiteral("character 5 (0x47) is not a hex digit");
        QTest::newRow(":070300C800042A LF") << QByteArray(":070300C800042A\n")
                                            << QStringLiteral("no CR before the end character");
        QTest::newRow(":070300C800042") << QByteArray(":070300C800042\r\n") << QStringLiteral("odd number of hex digits (13)");
        QTest::newRow(":07F9") << QByteArray(":07F9\r\n")
                               << QStringLiteral("4 hex digits: a frame needs at least 6 (unit id, function code, LRC)");
    }
    void problems()
    {
        QFETCH(QByteArray, frame);
        QFETCH(QString, problem);
        AsciiFramer framer;
        framer.feed(frame);
        const QList<StreamFrame> frames = framer.takeFrames();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].problem, problem);
        QCOMPARE(frames[0].status, problem.isEmpty() ? FrameStatus::Valid : FrameStatus::Malformed);
    }

    void otherEndCharacter()
    {
        // Diagnostics 08/0003 changes the LF to another character.
        AsciiFramer framer('!');
        framer.feed(QByteArray(":070300C800042A\r!:070300C800042A\r\n"));
        const QList<StreamFrame> frames = framer.takeFrames();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].bytes, QByteArray(":070300C800042A\r!"));
        QCOMPARE(frames[0].status, FrameStatus::Valid);
        QCOMPARE(framer.pendingSize(), 17);
    }

    void timestamps()
    {
        AsciiFramer framer;
        framer.feed("xx:0703", 10);
        framer.feed("00C80004", 20);
        framer.feed("2A\r\n", 30);
        const QList<StreamFrame> frames = framer.takeFrames();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].offset, 2);
        QCOMPARE(frames[0].firstByteNs, 10);
        QCOMPARE(frames[0].lastByteNs, 30);
    }

    void randomBytes()
    {
        QRandomGenerator random(513);
        const char alphabet[] = "0123456789ABCDEF:\r\nxZ";
        for (int round = 0; round < 10; ++round) {
            QByteArray stream;
            while (stream.size() < 20000) {
                if (random.bounded(3) == 0) {
                    QByteArray pdu(int(random.bounded(1, 254)), Qt::Uninitialized);
                    for (char &c : pdu)
                        c = char(random.bounded(256));
                    stream += AduBuilder::ascii(pdu, quint8(random.bounded(256)));
                } else {
                    for (int i = int(random.bounded(1, 60)); i > 0; --i)
                        stream.append(random.bounded(2) ? alphabet[random.bounded(int(sizeof alphabet) - 1)]
                                                        : char(random.bounded(256)));
                }
            }
            framertesting::checkRandomChunks(make, stream, random, 100, AsciiFramer::kMaxFrameSize + 100, true);
            if (QTest::currentTestFailed())
                return;
        }
    }
};

QTEST_GUILESS_MAIN(TestAsciiFramer)
#include "tst_asciiframer.moc"
