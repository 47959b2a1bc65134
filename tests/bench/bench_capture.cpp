// Offline analysis of a large capture: mbscope against tshark on the same file, in one run.
//
// Writes a pcapng of N Modbus TCP transactions (default one million: reads of 10 holding
// registers on one connection, latencies spread over 0.2-2.2 ms, an exception every 100th, a
// timeout every 1000th) with mbscope's own writer, then runs, each as a child process with its
// output thrown away:
//   mbscope analyze FILE --json                       (pairs, decodes, statistics, histogram)
//   tshark -r FILE -T fields -e modbus.func_code      (tshark's single pass with its dissectors)
//   bench_capture --floor FILE                        (the floor: capturefloor.cpp, a C loop that
//                                                      only reads the file and pairs by transaction id)
// and prints the wall time and peak resident memory (getrusage/wait4 ru_maxrss) of each, and
// transactions per second, and mbscope's time and memory as a ratio to the floor's. Figures are
// printed, never asserted; mbscope's JSON count and the floor's pairs are checked, so the run also
// proves both saw every transaction.
//
// --compare PATH runs another mbscope build's analyze in the same turns (before and after figures).
//
// Usage: bench_capture [--transactions N] [--keep FILE] [--no-tshark] [--repeat N] [--compare PATH]
#include "capturefloor.h"

#include "capture/capturefilewriter.h"
#include "capture/exchangepcapexporter.h"
#include "protocol/adubuilder.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>

#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <vector>

using namespace mbscope;

namespace {

qint64 nowNs()
{
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return qint64(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

struct Run {
    bool ok = false;
    int exitCode = -1;
    double seconds = 0;
    long maxRssKb = 0;
};

// Runs a program with stdout to a file (or /dev/null) and measures it from fork to exit.
Run runChild(const QString &program, const QStringList &arguments, const QString &stdoutPath)
{
    std::vector<QByteArray> storage;
    storage.push_back(program.toLocal8Bit());
    for (const QString &a : arguments)
        storage.push_back(a.toLocal8Bit());
    std::vector<char *> argv;
    for (QByteArray &s : storage)
        argv.push_back(s.data());
    argv.push_back(nullptr);
    const QByteArray out = stdoutPath.isEmpty() ? QByteArray("/dev/null") : stdoutPath.toLocal8Bit();

    Run run;
    const qint64 start = nowNs();
    const pid_t pid = fork();
    if (pid == 0) {
        const int fd = open(out.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        if (fd >= 0)
            dup2(fd, 1);
        if (null >= 0)
            dup2(null, 2);
        execvp(argv[0], argv.data());
        _exit(127);
    }
    if (pid < 0)
        return run;
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid)
        return run;
    run.seconds = double(nowNs() - start) / 1e9;
    run.maxRssKb = usage.ru_maxrss;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.ok = WIFEXITED(status);
    return run;
}

void printRun(const char *name, const Run &run, qint64 transactions)
{
    std::printf("%-44s %9.2f s %9.1f MiB %12.0f transactions/s  (exit %d)\n", name, run.seconds, double(run.maxRssKb) / 1024.0,
                run.seconds > 0 ? double(transactions) / run.seconds : 0.0, run.exitCode);
}

} // namespace

// The floor's own process (bench_capture --floor FILE): prints "pairs requests packets" and exits.
int runFloor(const char *path)
{
    const CaptureFloorResult r = captureFloorRun(path, 502);
    std::printf("%lld %lld %lld %lld\n", r.pairs, r.requests, r.packets, r.latencyNsSum);
    return r.error;
}

int main(int argc, char *argv[])
{
    if (argc == 3 && std::strcmp(argv[1], "--floor") == 0)
        return runFloor(argv[2]);
    QCoreApplication app(argc, argv);
    qint64 transactions = 1'000'000;
    QString keep;
    bool withTshark = true;
    int repeat = 1;
    QString compare;
    const QStringList args = QCoreApplication::arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args.at(i) == QLatin1String("--transactions") && i + 1 < args.size())
            transactions = args.at(++i).toLongLong();
        else if (args.at(i) == QLatin1String("--keep") && i + 1 < args.size())
            keep = args.at(++i);
        else if (args.at(i) == QLatin1String("--no-tshark"))
            withTshark = false;
        else if (args.at(i) == QLatin1String("--repeat") && i + 1 < args.size())
            repeat = args.at(++i).toInt();
        else if (args.at(i) == QLatin1String("--compare") && i + 1 < args.size())
            compare = args.at(++i);
        else {
            std::fprintf(stderr, "usage: bench_capture [--transactions N] [--keep FILE] [--no-tshark] [--repeat N] [--compare PATH]\n");
            return 2;
        }
    }
    if (transactions <= 0 || repeat <= 0) {
        std::fprintf(stderr, "bench_capture: --transactions and --repeat must be positive numbers\n");
        return 2;
    }
    QTemporaryDir dir;
    const QString path = keep.isEmpty() ? dir.filePath(QStringLiteral("bench.pcapng")) : keep;

    // The capture: one connection, sequential reads, made-up but plausible timing.
    const qint64 generateStart = nowNs();
    CaptureFileWriter writer;
    QString error;
    if (!writer.open(path, TrafficFormat::Pcapng, &error)) {
        std::fprintf(stderr, "bench_capture: %s\n", qPrintable(error));
        return 1;
    }
    ExchangePcapExporter exporter(writer);
    CaptureConversation c;
    c.client.bytes = {192, 168, 1, 5};
    c.server.bytes = {192, 168, 1, 10};
    c.clientPort = 50000;
    c.serverPort = 502;
    exporter.addConversation(c);
    const QByteArray answer = QByteArray::fromHex("0314") + QByteArray(20, '\x11');
    const QByteArray exception = QByteArray::fromHex("8302");
    qint64 t = 1'750'000'000'000'000'000LL;
    quint32 random = 12345;
    for (qint64 i = 0; i < transactions; ++i) {
        random = random * 1664525u + 1013904223u; // a fixed LCG: the same file every run
        const auto tid = quint16(i);
        CaptureExchange e;
        e.transaction.request = AduBuilder::mbap(QByteArray::fromHex("030000000a"), 1, tid);
        e.transaction.sentNs = t;
        if (i % 1000 != 999) {
            e.transaction.response = AduBuilder::mbap(i % 100 == 99 ? exception : answer, 1, tid);
            e.transaction.doneNs = t + 200'000 + qint64(random % 2'000'000);
        }
        exporter.add(e);
        t += i % 1000 == 999 ? 1'500'000'000 : 3'000'000; // a timed-out request waits past the 1 s timeout
    }
    exporter.finish();
    if (!writer.close(&error)) {
        std::fprintf(stderr, "bench_capture: %s\n", qPrintable(error));
        return 1;
    }
    const double generateSeconds = double(nowNs() - generateStart) / 1e9;
    std::printf("capture: %lld transactions, %llu packets, %.1f MiB pcapng, written by mbscope in %.2f s\n",
                static_cast<long long>(transactions), static_cast<unsigned long long>(writer.packets()),
                double(QFileInfo(path).size()) / 1048576.0, generateSeconds);

    // The floor and mbscope take turns (--repeat N: each N times, the fastest of each kept).
    const QString json = dir.filePath(QStringLiteral("analyze.json"));
    const QString floorOut = dir.filePath(QStringLiteral("floor.txt"));
    Run ours;
    Run floorRun;
    Run compared;
    for (int round = 0; round < repeat; ++round) {
        const Run floorTurn = runChild(QCoreApplication::applicationFilePath(), {QStringLiteral("--floor"), path}, floorOut);
        if (round == 0 || floorTurn.seconds < floorRun.seconds)
            floorRun = floorTurn;
        const Run oursTurn = runChild(QStringLiteral(MBSCOPE_EXECUTABLE), {QStringLiteral("analyze"), path, QStringLiteral("--json")}, json);
        if (round == 0 || oursTurn.seconds < ours.seconds)
            ours = oursTurn;
        if (!compare.isEmpty()) {
            const Run comparedTurn = runChild(compare, {QStringLiteral("analyze"), path, QStringLiteral("--json")}, {});
            if (round == 0 || comparedTurn.seconds < compared.seconds)
                compared = comparedTurn;
        }
    }
    printRun("floor: read and pair (capturefloor.cpp)", floorRun, transactions);
    long long floorPairs = -1;
    long long floorRequests = -1;
    if (QFile floorFile(floorOut); floorFile.open(QIODevice::ReadOnly)) {
        const QList<QByteArray> fields = floorFile.readAll().simplified().split(' ');
        if (fields.size() >= 2) {
            floorPairs = fields.at(0).toLongLong();
            floorRequests = fields.at(1).toLongLong();
        }
    }
    std::printf("%-44s %lld requests, %lld paired\n", "  the floor found", floorRequests, floorPairs);
    printRun("mbscope analyze FILE --json", ours, transactions);
    if (floorRun.seconds > 0 && floorRun.maxRssKb > 0)
        std::printf("mbscope takes %.2fx the floor's time and %.2fx its peak memory (%.1f MiB more)\n", ours.seconds / floorRun.seconds,
                    double(ours.maxRssKb) / double(floorRun.maxRssKb), double(ours.maxRssKb - floorRun.maxRssKb) / 1024.0);
    if (!compare.isEmpty()) {
        printRun("compared: PATH analyze FILE --json", compared, transactions);
        if (floorRun.seconds > 0)
            std::printf("the compared build takes %.2fx the floor's time (%.1f MiB peak)\n", compared.seconds / floorRun.seconds,
                        double(compared.maxRssKb) / 1024.0);
    }
    QFile result(json);
    const QJsonObject analysis = result.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(result.readAll()).object() : QJsonObject();
    // A request the capture ends within the timeout of is unanswered at its end, in no figure.
    const qint64 unanswered =
        qint64(analysis.value(QStringLiteral("source")).toObject().value(QStringLiteral("unanswered_at_end")).toDouble());
    const qint64 counted = qint64(analysis.value(QStringLiteral("count")).toDouble()) + unanswered;
    std::printf("%-44s %lld transactions (%lld ok, %lld exceptions, %lld timeouts, %lld unanswered at the end), p50 %.1f us, p99 %.1f us\n",
                "  mbscope found", static_cast<long long>(counted), static_cast<long long>(analysis.value(QStringLiteral("ok")).toDouble()),
                static_cast<long long>(analysis.value(QStringLiteral("exceptions")).toDouble()),
                static_cast<long long>(analysis.value(QStringLiteral("timeouts")).toDouble()), static_cast<long long>(unanswered),
                analysis.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("median")).toDouble(),
                analysis.value(QStringLiteral("latency_us")).toObject().value(QStringLiteral("p99")).toDouble());

    if (withTshark && !QStandardPaths::findExecutable(QStringLiteral("tshark")).isEmpty()) {
        const Run theirs = runChild(QStringLiteral("tshark"),
                                    {QStringLiteral("-r"), path, QStringLiteral("-T"), QStringLiteral("fields"), QStringLiteral("-e"),
                                     QStringLiteral("modbus.func_code")},
                                    {});
        printRun("tshark -r FILE -T fields -e modbus.func_code", theirs, transactions);
        if (theirs.seconds > 0 && ours.seconds > 0)
            std::printf("mbscope takes %.2fx tshark's time and %.2fx its peak memory\n", ours.seconds / theirs.seconds,
                        double(ours.maxRssKb) / double(std::max(1L, theirs.maxRssKb)));
    } else {
        std::printf("tshark: not run (%s)\n", withTshark ? "not installed: apt-get install tshark" : "--no-tshark");
    }
    if (!floorRun.ok || floorRun.exitCode != 0 || floorRequests != transactions) {
        std::fprintf(stderr, "bench_capture: the floor read %lld of %lld requests (exit %d)\n", floorRequests,
                     static_cast<long long>(transactions), floorRun.exitCode);
        return 1;
    }
    if (!ours.ok || counted != transactions) {
        std::fprintf(stderr, "bench_capture: mbscope analyze counted %lld of %lld transactions\n", static_cast<long long>(counted),
                     static_cast<long long>(transactions));
        return 1;
    }
    return 0;
}
