// StreamFramer::takeOutput (issue 3: the engine takes each read's frames into lists it keeps):
// the same frames and skipped runs as takeFrames() and takeSkipped(), whatever the chunking, and
// one heap allocation fewer per frame (the list the framer would otherwise allocate again).
#include "allocationcounter.h"
#include "framertesting.h"

#include "protocol/asciiframer.h"
#include "protocol/mbapframer.h"
#include "protocol/rtuframer.h"

#include <QtTest/QtTest>

using namespace mbscope;

namespace {

std::unique_ptr<StreamFramer> makeFramer(const QString &kind)
{
    if (kind == QLatin1String("rtu"))
        return std::make_unique<RtuFramer>(Direction::Response);
    if (kind == QLatin1String("ascii"))
        return std::make_unique<AsciiFramer>();
    return std::make_unique<MbapFramer>();
}

QStringList describe(const QList<StreamFrame> &frames, const QList<SkippedBytes> &skipped)
{
    QStringList lines;
    for (const StreamFrame &f : frames)
        lines.append(framertesting::frame(f.offset, f.bytes, framertesting::statusToken(f.status)));
    for (const SkippedBytes &s : skipped)
        lines.append(framertesting::skip(s.offset, s.count(), framertesting::reasonToken(s.reason)));
    return lines;
}

} // namespace

class TestFramerTakeOutput : public QObject
{
    Q_OBJECT

private slots:
    void sameAsTakeFrames_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QByteArray>("stream");
        QTest::addColumn<int>("chunk");

        const QByteArray mbap = QByteArray::fromHex("000100000007010304002A002B");
        const QByteArray mbapGarbage = QByteArray::fromHex("FFFF") + mbap + QByteArray::fromHex("0102FF") + mbap;
        const QByteArray arduino = QByteArray::fromHex("0103080045004E00010001791D");
        const QByteArray badCrc = QByteArray::fromHex("0103080045004E00010001791E");
        const QByteArray ascii = QByteArrayLiteral(":0103007900166D\r\n");
        for (const int chunk : {1, 3, 1000}) {
            QTest::addRow("mbap, two frames, chunk %d", chunk) << QStringLiteral("mbap") << mbap + mbap << chunk;
            QTest::addRow("mbap, garbage between, chunk %d", chunk) << QStringLiteral("mbap") << mbapGarbage << chunk;
            QTest::addRow("rtu, answers and a bad crc, chunk %d", chunk) << QStringLiteral("rtu") << arduino + badCrc + arduino << chunk;
            QTest::addRow("ascii, text around, chunk %d", chunk) << QStringLiteral("ascii") << QByteArrayLiteral("xx") + ascii + QByteArrayLiteral("yy") + ascii << chunk;
        }
    }

    void sameAsTakeFrames()
    {
        QFETCH(QString, kind);
        QFETCH(QByteArray, stream);
        QFETCH(int, chunk);

        auto taking = makeFramer(kind);
        auto reusing = makeFramer(kind);
        QStringList taken;
        QStringList reused;
        QList<StreamFrame> frames;
        QList<SkippedBytes> skipped;
        for (qsizetype at = 0; at < stream.size(); at += chunk) {
            const QByteArrayView piece = QByteArrayView(stream).sliced(at, qMin<qsizetype>(chunk, stream.size() - at));
            taking->feed(piece, 1);
            reusing->feed(piece, 1);
            taken += describe(taking->takeFrames(), taking->takeSkipped());
            const bool any = reusing->takeOutput(frames, skipped);
            QCOMPARE(any, !frames.isEmpty() || !skipped.isEmpty());
            reused += describe(frames, skipped);
        }
        taking->flushOnSilence();
        reusing->flushOnSilence();
        taken += describe(taking->takeFrames(), taking->takeSkipped());
        (void)reusing->takeOutput(frames, skipped);
        reused += describe(frames, skipped);
        QVERIFY2(!taken.isEmpty(), "the stream gave nothing: the row tests nothing");
        QCOMPARE(reused, taken);
        // Nothing left: the lists come back empty and the call says so.
        QVERIFY(!reusing->takeOutput(frames, skipped));
        QVERIFY(frames.isEmpty() && skipped.isEmpty());
    }

    void oneAllocationFewerPerFrame()
    {
        if (!allocationcounter::available)
            QSKIP("allocations cannot be counted in this build (a sanitizer owns the allocator, or not glibc)");
        const QByteArray frame = QByteArray::fromHex("000100000007010304002A002B");
        constexpr int kFrames = 100;
        MbapFramer taking;
        MbapFramer reusing;
        QList<StreamFrame> frames;
        QList<SkippedBytes> skipped;
        // Warm up: buffers and lists at their working size.
        for (int i = 0; i < 4; ++i) {
            taking.feed(frame, 1);
            (void)taking.takeFrames();
            reusing.feed(frame, 1);
            (void)reusing.takeOutput(frames, skipped);
        }
        allocationcounter::start();
        for (int i = 0; i < kFrames; ++i) {
            taking.feed(frame, 1);
            const QList<StreamFrame> out = taking.takeFrames();
            QCOMPARE(out.size(), 1);
        }
        const long takenAllocations = allocationcounter::stop();
        allocationcounter::start();
        for (int i = 0; i < kFrames; ++i) {
            reusing.feed(frame, 1);
            QVERIFY(reusing.takeOutput(frames, skipped));
            QCOMPARE(frames.size(), 1);
        }
        const long reusedAllocations = allocationcounter::stop();
        qInfo("%d frames: %ld allocations with takeFrames(), %ld with takeOutput()", kFrames, takenAllocations,
              reusedAllocations);
        // Each frame's bytes are its own (a record keeps them); nothing else is allocated per frame.
        QCOMPARE(reusedAllocations, long(kFrames));
        QVERIFY(takenAllocations >= reusedAllocations + kFrames);
    }
};

QTEST_GUILESS_MAIN(TestFramerTakeOutput)
#include "tst_framertakeoutput.moc"
