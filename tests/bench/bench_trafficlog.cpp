// The traffic log (issue 3: "every frame in and out ... Memory per logged small frame: aim under
// 100 bytes, measured"). Figures printed, never asserted (tst_trafficlog bounds the memory):
// - MemoryPerSmallFrame: a million 8-byte frames, bytes per frame as the log counts its own
//   heap (capacities) and as malloc sees it (mallinfo2, allocator overhead included), beside a
//   plain QList<TrafficFrame>, the obvious way to keep frames.
// - Append: appends per second on one thread, memory only, journaled to /dev/null (serialising,
//   CRC-32 and one write(2) per batch, no disk) and journaled to a file (with its size on disk
//   per frame: disk_bytes_per_frame).
// - Recover: reading a journal back, frames per second.
// Frame: the RosRao request 01 03 00 79 00 16 15 DD (tests/data/published-frames.json).
#include "traffic/trafficlog.h"

#include <QtCore/QFileInfo>
#include <QtCore/QTemporaryDir>

#include <benchmark/benchmark.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

using namespace mbscope;

namespace {

const QByteArray &smallFrame()
{
    static const QByteArray frame = QByteArray::fromHex("01030079001615DD");
    return frame;
}

constexpr quint64 kMillion = 1000000;

double heapInUse()
{
#if defined(__GLIBC__)
    // Small blocks from the heap, plus blocks big enough to get their own mapping (QList's one
    // array of a million frames).
    const struct mallinfo2 info = mallinfo2();
    return double(info.uordblks + info.hblkhd);
#else
    return 0;
#endif
}

void MemoryPerSmallFrame(benchmark::State &state)
{
    double computed = 0, measured = 0;
    for (auto _ : state) {
        const double before = heapInUse();
        auto log = std::make_unique<TrafficLog>(TrafficLog::Limits{kMillion, quint64(1) << 30});
        const quint16 link = log->addLink(QStringLiteral("tcp://127.0.0.1:502"));
        for (quint64 i = 0; i < kMillion; ++i)
            log->append(qint64(i), TrafficDirection(i & 1), link, TrafficVerdict::Ok, i / 2, smallFrame());
        measured = (heapInUse() - before) / double(kMillion);
        computed = double(log->memoryBytes()) / double(log->size());
        benchmark::DoNotOptimize(log.get());
    }
    state.SetItemsProcessed(state.iterations() * qint64(kMillion));
    state.counters["bytes_per_frame"] = computed;
    state.counters["malloc_bytes_per_frame"] = measured;
}
BENCHMARK(MemoryPerSmallFrame)->Iterations(3)->Unit(benchmark::kMillisecond);

// The baseline: one owning value per frame, its bytes in a QByteArray of their own.
void MemoryPerSmallFrameQList(benchmark::State &state)
{
    double measured = 0;
    for (auto _ : state) {
        const double before = heapInUse();
        QList<TrafficFrame> frames;
        for (quint64 i = 0; i < kMillion; ++i) {
            QByteArray bytes = smallFrame();
            bytes.detach();
            frames.append(TrafficFrame{i, qint64(i), i / 2, 0, TrafficDirection(i & 1), TrafficVerdict::Ok, bytes});
        }
        measured = (heapInUse() - before) / double(kMillion);
        benchmark::DoNotOptimize(frames.data());
    }
    state.SetItemsProcessed(state.iterations() * qint64(kMillion));
    state.counters["malloc_bytes_per_frame"] = measured;
}
BENCHMARK(MemoryPerSmallFrameQList)->Iterations(3)->Unit(benchmark::kMillisecond);

enum class Journal { None, DevNull, File };

void appendLoop(benchmark::State &state, Journal journal)
{
    QTemporaryDir dir;
    TrafficLog log(TrafficLog::Limits{kMillion, quint64(1) << 30});
    if (journal != Journal::None) {
        const QString path = journal == Journal::DevNull ? QStringLiteral("/dev/null") : dir.filePath(QStringLiteral("bench.mbtl"));
        QString error;
        if (!log.openJournal(path, {}, journal == Journal::DevNull, &error)) {
            state.SkipWithError(qPrintable(error));
            return;
        }
    }
    const quint16 link = log.addLink(QStringLiteral("tcp://127.0.0.1:502"));
    quint64 i = 0;
    for (auto _ : state) {
        log.append(qint64(i), TrafficDirection(i & 1), link, TrafficVerdict::Ok, i / 2, smallFrame());
        ++i;
    }
    log.closeJournal();
    state.SetItemsProcessed(qint64(i));
    state.counters["batches"] = double(log.journal().batchesWritten());
    // The journal's size per 8-byte frame (28-byte record header + the bytes + a 32-byte batch
    // header per 1,024 frames + the 40-byte file header).
    if (journal == Journal::File && i > 0)
        state.counters["disk_bytes_per_frame"] = double(QFileInfo(dir.filePath(QStringLiteral("bench.mbtl"))).size()) / double(i);
}

void AppendMemoryOnly(benchmark::State &state) { appendLoop(state, Journal::None); }
void AppendJournalDevNull(benchmark::State &state) { appendLoop(state, Journal::DevNull); }
void AppendJournalFile(benchmark::State &state) { appendLoop(state, Journal::File); }
BENCHMARK(AppendMemoryOnly);
BENCHMARK(AppendJournalDevNull);
// A fixed count keeps the file to 36 MB whatever the machine's speed.
BENCHMARK(AppendJournalFile)->Iterations(qint64(kMillion));

void Recover(benchmark::State &state)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("recover.mbtl"));
    {
        TrafficLog log(TrafficLog::Limits{0, 0});
        if (!log.openJournal(path)) {
            state.SkipWithError("cannot write the journal");
            return;
        }
        for (quint64 i = 0; i < kMillion; ++i)
            log.append(qint64(i), TrafficDirection(i & 1), 0, TrafficVerdict::Ok, i / 2, smallFrame());
    }
    quint64 frames = 0;
    for (auto _ : state) {
        qint64 sum = 0;
        const TrafficJournalRecovery r = TrafficJournalReader::read(path, [&sum](const TrafficEntry &e) { sum += e.tNs; });
        benchmark::DoNotOptimize(sum);
        frames += r.frames;
    }
    state.SetItemsProcessed(qint64(frames));
}
BENCHMARK(Recover)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
