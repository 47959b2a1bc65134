// BusFramer: both directions of a serial line as one stream (a monitor's tap), cut into frames
// that know which way they went, whatever the chunking; damaged frames counted. The frames are
// the Serial Line V1.02 examples' shapes: 03 reads (a request of 8 bytes, an answer of 5 + 2n),
// 06 writes (the answer echoes the request), exceptions, a broadcast.
#include "monitor/busframer.h"

#include "protocol/checksum.h"

#include <QtTest/QTest>

using namespace mbscope;

namespace {

QByteArray rtu(const char *hex)
{
    QByteArray frame = QByteArray::fromHex(hex);
    const quint16 crc = checksum::crc16Modbus(frame);
    frame.append(char(crc & 0xff));
    frame.append(char(crc >> 8));
    return frame;
}

QByteArray ascii(const char *hex)
{
    const QByteArray binary = QByteArray::fromHex(hex);
    QByteArray frame = ":" + binary.toHex().toUpper();
    frame += QByteArray(1, char(checksum::lrc(binary))).toHex().toUpper();
    return frame + "\r\n";
}

struct Seen {
    QList<CapturedFrame> frames;
    QString directions() const
    {
        QString text;
        for (const CapturedFrame &f : frames)
            text += f.undelimited ? QLatin1Char('x') : f.direction == Direction::Request ? QLatin1Char('q') : QLatin1Char('a');
        return text;
    }
};

constexpr qint64 kSecond = 1'000'000'000;

// Feeds the line in chunks of chunkSize (0: all at once), a silence after each burst.
Seen run(Framing framing, const QList<QByteArray> &bursts, int chunkSize, BusCounters *counters = nullptr)
{
    Seen seen;
    BusFramer framer(framing, kSecond, [&seen](const CapturedFrame &f) { seen.frames.append(f); });
    qint64 t = 1000;
    for (const QByteArray &burst : bursts) {
        const int step = chunkSize > 0 ? chunkSize : int(burst.size());
        for (qsizetype at = 0; at < burst.size(); at += step)
            framer.feed(QByteArrayView(burst).sliced(at, qMin<qsizetype>(step, burst.size() - at)), t += 1000);
        framer.silence();
        t += 5'000'000;
    }
    if (counters)
        *counters = framer.counters();
    return seen;
}

} // namespace

class TestBusFramer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void directions_data();
    void directions();
    void crcErrorIsCountedAndOffered();
    void truncatedAnswer();
    void asciiLine();
    void asciiLrcError();
};

void TestBusFramer::directions_data()
{
    QTest::addColumn<QList<QByteArray>>("bursts");
    QTest::addColumn<QString>("expected");
    const QByteArray read = rtu("010300000002");
    const QByteArray answer = rtu("01030400450046");
    QTest::newRow("read, answer") << QList<QByteArray>{read, answer} << QStringLiteral("qa");
    QTest::newRow("read, answer, read, answer") << QList<QByteArray>{read, answer, read, answer} << QStringLiteral("qaqa");
    // The second read is not the first one's answer, although unit and function match.
    QTest::newRow("unanswered read, read, answer") << QList<QByteArray>{read, read, answer} << QStringLiteral("qqa");
    const QByteArray write = rtu("010600030001");
    QTest::newRow("write, echo, write, echo") << QList<QByteArray>{write, write, write, write} << QStringLiteral("qaqa");
    QTest::newRow("exception") << QList<QByteArray>{read, rtu("018302")} << QStringLiteral("qa");
    // Unit 0 is a broadcast: no answer expected, so an identical write after it is a request.
    const QByteArray broadcast = rtu("000600030001");
    QTest::newRow("broadcast twice") << QList<QByteArray>{broadcast, broadcast} << QStringLiteral("qq");
    QTest::newRow("answer of another unit") << QList<QByteArray>{read, rtu("02030400450046")} << QStringLiteral("qq");
    QTest::newRow("both in one burst") << QList<QByteArray>{read + answer} << QStringLiteral("qa");
}

void TestBusFramer::directions()
{
    QFETCH(QList<QByteArray>, bursts);
    QFETCH(QString, expected);
    for (int chunk : {0, 1, 3}) {
        const Seen seen = run(Framing::Rtu, bursts, chunk);
        QCOMPARE(seen.directions(), expected);
    }
}

void TestBusFramer::crcErrorIsCountedAndOffered()
{
    QByteArray damaged = rtu("01030400450046");
    damaged[damaged.size() - 3] = char(damaged[damaged.size() - 3] ^ 0x01);
    for (int chunk : {0, 1, 4}) {
        BusCounters counters;
        const Seen seen = run(Framing::Rtu, {rtu("010300000002"), damaged, rtu("010300000002"), rtu("01030400450046")}, chunk, &counters);
        QCOMPARE(seen.directions(), QStringLiteral("qxqa"));
        QCOMPARE(seen.frames.at(1).bytes, damaged);
        QCOMPARE(counters.crcErrors, quint64(1));
        // The damaged answer is an answer the line carried (tryout 8, item 5), not skipped bytes.
        QCOMPARE(counters.frames, quint64(4));
        QCOMPARE(counters.requests, quint64(2));
        QCOMPARE(counters.responses, quint64(2));
        QCOMPARE(counters.skippedBytes, qint64(0));
    }
}

void TestBusFramer::truncatedAnswer()
{
    const QByteArray answer = rtu("01030400450046");
    BusCounters counters;
    const Seen seen = run(Framing::Rtu, {rtu("010300000002"), answer.left(answer.size() - 1), rtu("010300000002")}, 1, &counters);
    QCOMPARE(seen.directions(), QStringLiteral("qaq"));
    QCOMPARE(seen.frames.at(1).status, FrameStatus::Truncated);
    QCOMPARE(counters.truncated, quint64(1));
    QCOMPARE(counters.crcErrors, quint64(0));
}

void TestBusFramer::asciiLine()
{
    for (int chunk : {0, 1, 5}) {
        BusCounters counters;
        const Seen seen = run(Framing::Ascii, {ascii("010300000002"), ascii("01030400450046"), ascii("010600030001"), ascii("010600030001")},
                              chunk, &counters);
        QCOMPARE(seen.directions(), QStringLiteral("qaqa"));
        QCOMPARE(seen.frames.at(0).framing, Framing::Ascii);
        QCOMPARE(counters.crcErrors, quint64(0));
    }
}

void TestBusFramer::asciiLrcError()
{
    QByteArray damaged = ascii("01030400450046");
    damaged[damaged.size() - 3] = damaged[damaged.size() - 3] == '0' ? '1' : '0'; // the LRC's last digit
    BusCounters counters;
    const Seen seen = run(Framing::Ascii, {ascii("010300000002"), damaged}, 1, &counters);
    QCOMPARE(seen.directions(), QStringLiteral("qa"));
    QCOMPARE(counters.crcErrors, quint64(1));
    QCOMPARE(counters.malformed, quint64(0));
}

QTEST_GUILESS_MAIN(TestBusFramer)
#include "tst_busframer.moc"
