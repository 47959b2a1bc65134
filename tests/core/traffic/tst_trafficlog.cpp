#include "trafficframes.h"

#include "traffic/trafficlog.h"

#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtTest/QtTest>

#include <atomic>
#include <cstdio>
#include <memory>
#include <vector>

#include <unistd.h>

// Counting heap allocations to check that append() makes none once the log cycles: malloc and
// friends are replaced by counting versions forwarding to glibc's (operator new and Qt's
// containers both end in malloc). Not under sanitizers, whose allocators cannot be replaced.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define E3_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define E3_COUNT_ALLOCATIONS 0
#endif
#endif
#if !defined(E3_COUNT_ALLOCATIONS) && defined(__GLIBC__)
#define E3_COUNT_ALLOCATIONS 1
#endif
#ifndef E3_COUNT_ALLOCATIONS
#define E3_COUNT_ALLOCATIONS 0
#endif

#if E3_COUNT_ALLOCATIONS
namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
void countOne()
{
    if (g_counting.load(std::memory_order_relaxed))
        g_allocations.fetch_add(1, std::memory_order_relaxed);
}
} // namespace

extern "C" {
void *__libc_malloc(std::size_t size);
void *__libc_calloc(std::size_t count, std::size_t size);
void *__libc_realloc(void *pointer, std::size_t size);
void *__libc_memalign(std::size_t alignment, std::size_t size);
void *malloc(std::size_t size) { countOne(); return __libc_malloc(size); }
void *calloc(std::size_t count, std::size_t size) { countOne(); return __libc_calloc(count, size); }
void *realloc(void *pointer, std::size_t size) { countOne(); return __libc_realloc(pointer, size); }
void *memalign(std::size_t alignment, std::size_t size) { countOne(); return __libc_memalign(alignment, size); }
void *aligned_alloc(std::size_t alignment, std::size_t size) { countOne(); return __libc_memalign(alignment, size); }
int posix_memalign(void **pointer, std::size_t alignment, std::size_t size)
{
    countOne();
    *pointer = __libc_memalign(alignment, size);
    return *pointer ? 0 : 12; // ENOMEM
}
} // extern "C"
#endif

using namespace mbscope;
using namespace mbscope::testing;

namespace {

// The child of the crash tests: logs 8-byte frames to a journal for ever, printing the number of
// batches written after each one, until the parent kills it.
int crashWriter(const char *path, int batchEntries)
{
    TrafficLog log(TrafficLog::Limits{4096, quint64(1) << 30});
    TrafficJournalWriter::Options options;
    options.batchEntries = batchEntries;
    options.batchNs = qint64(1) << 62;
    QString error;
    if (!log.openJournal(QString::fromLocal8Bit(path), options, false, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 2;
    }
    const quint16 link = log.addLink(QStringLiteral("tcp://127.0.0.1:1502"));
    quint64 batches = 0;
    for (quint64 n = 0;; ++n) {
        appendMade(log, link, n, 8);
        if (log.journal().batchesWritten() != batches) {
            batches = log.journal().batchesWritten();
            std::printf("batch %llu\n", static_cast<unsigned long long>(batches));
            std::fflush(stdout);
            if (batchEntries <= 1000)
                ::usleep(200); // small batches: keep the file to a few MB before the kill lands
        }
    }
}

} // namespace

class TestTrafficLog : public QObject
{
    Q_OBJECT
private slots:
    void verdicts();
    void appendAndRead();
    void boundByCount();
    void boundByBytes();
    void memoryOnlyJournal();
    void memoryPerSmallFrame();
    void noAllocationOnceCycling();
    void killedWriterRecovered_data();
    void killedWriterRecovered();
    void sharedByThreads();
};

void TestTrafficLog::verdicts()
{
    for (int s = 0; s <= int(TransactionStatus::Late); ++s) {
        const auto status = TransactionStatus(s);
        const TrafficVerdict v = trafficVerdict(status);
        QCOMPARE(QString::fromLatin1(trafficVerdictName(v)), transactionStatusName(status));
        QCOMPARE(int(v), s); // the journal stores these numbers
    }
    for (int v = 0; v < kTrafficVerdictCount; ++v) {
        bool known = false;
        QCOMPARE(trafficVerdictFromName(QLatin1String(trafficVerdictName(TrafficVerdict(v))), &known), TrafficVerdict(v));
        QVERIFY(known);
    }
    bool known = true;
    QCOMPARE(trafficVerdictFromName(u"nonsense", &known), TrafficVerdict::Garbage);
    QVERIFY(!known);
    QCOMPARE(QByteArray(trafficVerdictName(TrafficVerdict::Unsolicited)), QByteArray("unsolicited"));
}


void TestTrafficLog::appendAndRead()
{
    TrafficLog log;
    const quint16 a = log.addLink(QStringLiteral("tcp://10.0.0.1:502"));
    const quint16 b = log.addLink(QStringLiteral("rtu:///dev/ttyUSB0"));
    QCOMPARE(log.addLink(QStringLiteral("tcp://10.0.0.1:502")), a);
    QCOMPARE(log.linkName(b), QStringLiteral("rtu:///dev/ttyUSB0"));
    QCOMPARE(log.linkName(9), QString());

    // Sizes 0-36 cycling, several chunks' worth, then one frame larger than a chunk.
    const quint64 n = 10000;
    for (quint64 i = 0; i < n; ++i)
        QCOMPARE(appendMade(log, i % 2 ? b : a, i), i);
    QCOMPARE(appendMade(log, a, n, int(TrafficLog::kChunkBytes) + 100), n);
    QCOMPARE(appendMade(log, a, n + 1), n + 1);
    QCOMPARE(log.size(), n + 2);
    QCOMPARE(log.dropped(), quint64(0));
    for (quint64 i = 0; i < n; ++i) {
        const TrafficEntry e = log.at(i);
        QVERIFY2(matches(e, i), qPrintable(QString::number(i)));
        QCOMPARE(e.link, i % 2 ? b : a);
    }
    QVERIFY(matches(log.at(n), n, int(TrafficLog::kChunkBytes) + 100));
    QVERIFY(matches(log.at(n + 1), n + 1));
    QCOMPARE(log.at(n + 2).bytes.size(), 0);
    QCOMPARE(log.at(n + 2).verdict, TrafficVerdict::Garbage);

    const QList<TrafficFrame> frames = log.copy(9998, 3);
    QCOMPARE(frames.size(), 3);
    QCOMPARE(frames.at(0).sequence, quint64(9998));
    QCOMPARE(frames.at(1).bytes, made(9999).bytes);
    QCOMPARE(frames.at(2).bytes.size(), int(TrafficLog::kChunkBytes) + 100);
    QCOMPARE(log.copy(n + 5, 10).size(), 0);
}

void TestTrafficLog::boundByCount()
{
    TrafficLog log(TrafficLog::Limits{1000, quint64(1) << 30});
    for (quint64 i = 0; i < 5000; ++i)
        appendMade(log, 0, i, 8);
    QCOMPARE(log.size(), quint64(1000));
    QCOMPARE(log.dropped(), quint64(4000));
    QCOMPARE(log.firstSequence(), quint64(4000));
    QCOMPARE(log.appended(), quint64(5000));
    QCOMPARE(log.retainedBytes(), quint64(1000 * 32));
    QCOMPARE(log.at(3999).bytes.size(), 0);
    QVERIFY(matches(log.at(4000), 4000, 8));
    QVERIFY(matches(log.at(4999), 4999, 8));
    // 1,000 frames of 32 bytes span at most two 64 KiB chunks, plus the spare.
    QVERIFY2(log.memoryBytes() < 3 * (TrafficLog::kChunkBytes + 256), qPrintable(QString::number(log.memoryBytes())));
    const QList<TrafficFrame> all = log.copy(0, 5000); // clamped to what is kept
    QCOMPARE(all.size(), 1000);
    QCOMPARE(all.front().sequence, quint64(4000));

    log.setLimits(TrafficLog::Limits{10, quint64(1) << 30});
    QCOMPARE(log.size(), quint64(10));
    QCOMPARE(log.dropped(), quint64(4990));
    QVERIFY(matches(log.at(4990), 4990, 8));
}

void TestTrafficLog::boundByBytes()
{
    TrafficLog log(TrafficLog::Limits{1000000, 100 * 32});
    for (quint64 i = 0; i < 500; ++i)
        appendMade(log, 0, i, 8);
    QCOMPARE(log.size(), quint64(100));
    QCOMPARE(log.retainedBytes(), quint64(3200));
    // Mixed sizes: never over the bound, and the newest frames are the ones kept.
    for (quint64 i = 500; i < 3000; ++i) {
        appendMade(log, 0, i);
        QVERIFY(log.retainedBytes() <= 3200);
        QCOMPARE(log.dropped() + log.size(), i + 1);
    }
    QVERIFY(matches(log.at(2999), 2999));
    // A frame bigger than the whole bound is dropped from memory at once, and counted.
    appendMade(log, 0, 3000, 5000);
    QCOMPARE(log.size(), quint64(0));
    QCOMPARE(log.dropped(), quint64(3001));
    QCOMPARE(log.retainedBytes(), quint64(0));
    appendMade(log, 0, 3001, 8);
    QCOMPARE(log.size(), quint64(1));
    QVERIFY(matches(log.at(3001), 3001, 8));
}

// Nothing kept in memory: every frame still reaches the journal.
void TestTrafficLog::memoryOnlyJournal()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("journal.mbtl"));
    {
        TrafficLog log(TrafficLog::Limits{0, 0});
        QVERIFY(log.openJournal(path));
        for (quint64 i = 0; i < 3000; ++i)
            appendMade(log, 0, i);
        QCOMPARE(log.size(), quint64(0));
        QCOMPARE(log.dropped(), quint64(3000));
    }
    QList<TrafficFrame> frames;
    const TrafficJournalRecovery r = TrafficJournalReader::readAll(path, &frames);
    QVERIFY2(r.isClean(), qPrintable(r.message));
    QCOMPARE(frames.size(), 3000);
    QCOMPARE(frames.at(2999).bytes, made(2999).bytes);
}

// Issue 25: the engines of a watch run or a scan write one journal from threads of their own.
// A shared log takes every frame whole, each writer's in its order, each writer on a link of its
// own though they name the same URL (each numbers its transactions from 1), each noting its
// connection's ends as it goes.
void TestTrafficLog::sharedByThreads()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("shared.mbscope.journal"));
    constexpr int kWriters = 4;
    constexpr quint64 kFrames = 5000;
    {
        TrafficLog log(TrafficLog::Limits{1000, quint64(1) << 20});
        log.setShared(true);
        QVERIFY(log.isShared());
        QVERIFY(log.openJournal(path));
        std::vector<std::unique_ptr<QThread>> writers;
        for (int w = 0; w < kWriters; ++w) {
            writers.push_back(std::unique_ptr<QThread>(QThread::create([&log] {
                const quint16 link = log.addConnection(QStringLiteral("tcp://127.0.0.1:502"));
                for (quint64 id = 1; id <= kFrames; ++id) {
                    const QByteArray bytes(int(id % 40) + 1, char(link));
                    log.append(qint64(id), TrafficDirection::Out, link, TrafficVerdict::Sent, id, bytes);
                    // A link (re)opening notes its ends from its own thread, amid the others'
                    // frames (it took no lock: two links of a watch connecting at once crashed).
                    if (id % 25 == 0)
                        log.setEndpoints(link, qint64(id), 0,
                                         JournalEndpoints{QStringLiteral("127.0.0.1:%1").arg(40000 + id), QStringLiteral("127.0.0.1:502")});
                    if (id % 500 == 0)
                        log.flushIfDue(qint64(id) + 200'000'000);
                }
            })));
        }
        for (auto &t : writers)
            t->start();
        for (auto &t : writers)
            QVERIFY(t->wait(60000));
        QCOMPARE(log.appended(), kWriters * kFrames);
        QCOMPARE(log.links().size(), kWriters);
    }
    QList<TrafficFrame> frames;
    const TrafficJournalRecovery r = TrafficJournalReader::readAll(path, &frames);
    QVERIFY2(r.isClean(), qPrintable(r.message));
    QCOMPARE(r.links, QStringList(kWriters, QStringLiteral("tcp://127.0.0.1:502")));
    QCOMPARE(quint64(frames.size()), kWriters * kFrames);
    std::vector<quint64> last(kWriters, 0);
    for (const TrafficFrame &f : std::as_const(frames)) {
        QVERIFY(f.link < kWriters);
        QCOMPARE(f.transactionId, last[f.link] + 1);
        last[f.link] = f.transactionId;
        QCOMPARE(f.bytes, QByteArray(int(f.transactionId % 40) + 1, char(f.link)));
    }
}

// Issue 3: "Memory per logged small frame: aim under 100 bytes, measured." The heap the log
// holds (capacities, not a clock) for a million 8-byte frames, journal on.
void TestTrafficLog::memoryPerSmallFrame()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    TrafficLog log(TrafficLog::Limits{1000000, quint64(1) << 30});
    QVERIFY(log.openJournal(dir.filePath(QStringLiteral("million.mbtl"))));
    const quint16 link = log.addLink(QStringLiteral("tcp://127.0.0.1:502"));
    const QByteArray frame = QByteArray::fromHex("01030079001615DD");
    for (quint64 i = 0; i < 1000000; ++i)
        log.append(qint64(i), TrafficDirection(i & 1), link, TrafficVerdict::Ok, i / 2, frame);
    QCOMPARE(log.size(), quint64(1000000));
    const double perFrame = double(log.memoryBytes()) / double(log.size());
    qInfo("memory per 8-byte frame: %.2f bytes (%zu bytes for %llu frames)", perFrame, log.memoryBytes(),
          static_cast<unsigned long long>(log.size()));
    QVERIFY2(perFrame < 100.0, qPrintable(QString::number(perFrame)));
    // The layout gives 24 + 8 bytes and a little slack: a regression to, say, a QByteArray per
    // frame (24 + 16 + 32 bytes at least) would show here first.
    QVERIFY2(perFrame < 34.0, qPrintable(QString::number(perFrame)));
    QVERIFY(matches(log.at(0), 0) || log.at(0).bytes == QByteArrayView(frame));
}

void TestTrafficLog::noAllocationOnceCycling()
{
#if !E3_COUNT_ALLOCATIONS
    QSKIP("allocation counting is not possible under a sanitizer or without glibc");
#else
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    TrafficLog log(TrafficLog::Limits{10000, quint64(1) << 30});
    TrafficJournalWriter::Options options;
    options.batchEntries = 256;
    QVERIFY(log.openJournal(dir.filePath(QStringLiteral("cycle.mbtl")), options));
    const quint16 link = log.addLink(QStringLiteral("tcp://127.0.0.1:502"));
    std::vector<QByteArray> frames;
    for (int size : {8, 12, 1, 64, 260})
        frames.push_back(QByteArray(size, '\x5A'));
    // Warm up: the log fills and starts to recycle its chunks; the batch buffer reaches its size.
    for (quint64 i = 0; i < 50000; ++i)
        log.append(qint64(i), TrafficDirection::In, link, TrafficVerdict::Ok, i, frames[i % frames.size()]);
    const quint64 batchesBefore = log.journal().batchesWritten();
    g_allocations = 0;
    g_counting = true;
    for (quint64 i = 50000; i < 150000; ++i) {
        log.append(qint64(i), TrafficDirection::In, link, TrafficVerdict::Ok, i, frames[i % frames.size()]);
        log.flushIfDue(qint64(i));
    }
    g_counting = false;
    QVERIFY(log.journal().batchesWritten() > batchesBefore + 300); // the batches were written meanwhile
    QCOMPARE(g_allocations.load(), 0L);
#endif
}

// The test runs itself as the writer (see main), kills it with SIGKILL while it appends, and
// reads what it left: every complete batch, in order, exactly, and nothing of a torn one.
// Small batches: the kill lands between writes, so the file ends on a whole batch. Huge batches
// (36 MB written in one call): the kill is sent as soon as the first write has begun, and a
// write the kernel stops part way leaves a torn batch to be detected (the kernel may also finish
// the write first; either ending is right, and the message says which).
void TestTrafficLog::killedWriterRecovered_data()
{
    QTest::addColumn<int>("batchEntries");
    QTest::addColumn<int>("batchesBeforeKill");
    QTest::newRow("100-frame batches, killed after 20") << 100 << 20;
    QTest::newRow("1,000,000-frame batches, killed during the first write") << 1000000 << 0;
}

void TestTrafficLog::killedWriterRecovered()
{
    QFETCH(int, batchEntries);
    QFETCH(int, batchesBeforeKill);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("killed.mbtl"));
    QProcess child;
    child.start(QCoreApplication::applicationFilePath(),
                {QStringLiteral("--crash-writer"), path, QString::number(batchEntries)});
    QVERIFY2(child.waitForStarted(10000), qPrintable(child.errorString()));
    QDeadlineTimer deadline(60000);
    int seen = 0;
    if (batchesBeforeKill > 0) {
        QByteArray out;
        while (seen < batchesBeforeKill && !deadline.hasExpired() && child.state() == QProcess::Running) {
            child.waitForReadyRead(100);
            out += child.readAllStandardOutput();
            const qsizetype line = out.lastIndexOf("batch ");
            if (line >= 0 && out.indexOf('\n', line) > 0)
                seen = out.mid(line + 6, out.indexOf('\n', line) - line - 6).toInt();
        }
    } else {
        // Wait until the first batch write has put anything past the 40-byte header.
        while (QFileInfo(path).size() <= 40 && !deadline.hasExpired() && child.state() == QProcess::Running)
            QThread::usleep(200);
    }
    QVERIFY2(child.state() == QProcess::Running, child.readAllStandardError().constData());
    QVERIFY(!deadline.hasExpired());
    child.kill(); // SIGKILL: no destructor, no flush
    QVERIFY(child.waitForFinished(10000));
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);

    quint64 next = 0;
    bool exact = true;
    const TrafficJournalRecovery r = TrafficJournalReader::read(path, [&](const TrafficEntry &e) {
        exact = exact && matches(e, next, 8);
        ++next;
    });
    qInfo("%s", qPrintable(r.message));
    QVERIFY(exact);
    QCOMPARE(next, r.frames);
    QCOMPARE(r.frames, r.batches * quint64(batchEntries));
    QVERIFY(r.batches >= quint64(seen));
    // Killed: never closed, so never clean (no end record), whether or not a batch was being written.
    QVERIFY2(r.ending == TrafficJournalRecovery::Ending::NotClosed || r.ending == TrafficJournalRecovery::Ending::CutShort,
             qPrintable(r.message));
    // The link's name travels in the first batch: known when that batch survived.
    QCOMPARE(r.links, r.batches > 0 ? QStringList{QStringLiteral("tcp://127.0.0.1:1502")} : QStringList{});
    if (r.ending == TrafficJournalRecovery::Ending::CutShort)
        QVERIFY(r.message.contains(QStringLiteral("cut short at byte %1").arg(grouped(r.fileBytes))));
}

// QTEST_GUILESS_MAIN, plus the child mode the crash test starts.
int main(int argc, char **argv)
{
    if (argc == 4 && qstrcmp(argv[1], "--crash-writer") == 0)
        return crashWriter(argv[2], std::atoi(argv[3]));
    QCoreApplication app(argc, argv);
    TestTrafficLog test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_trafficlog.moc"