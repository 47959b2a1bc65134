// Polling throughput and latency (issue 3, "Tests"): a local libmodbus server polled as fast as
// possible with one fixed Read Holding Registers request, by, in the same run and one after the
// other:
//   - a raw C socket loop (blocking send/recv of a fixed 12-byte request): the floor;
//   - libmodbus's client (modbus_read_registers in a loop): the baseline the issue names;
//   - mbscope's engine, sequential: every frame journaled to a file as `--record` does (row
//     "logged"), logged in memory only ("memory"), and not logged at all ("unlogged"), so that
//     what recording costs reads off one table;
//   - mbscope's engine with N = 4 and 8 requests in flight (Messaging on TCP/IP V1.0b, 4.2).
// Each prints transactions/s and latency percentiles; nothing is asserted (figures, not tests).
// Latency is each client's own: the raw loop and libmodbus time from before send() to after the
// last recv(); the engine's is its record's doneNs - sentNs (from the clock read just before the
// send() of the request to the read of the last answer byte; tests/integration/tst_latency_truth
// compares it with the wire).
// Targets from the issue: sequential at least 90 % of libmodbus's transactions/s while logging
// every frame; pipelined several times libmodbus.
//
// Two servers, one table each (every row of a table against the same server process):
//   - "libmodbus_server tcp": libmodbus's modbus_receive/modbus_reply loop, which reads one
//     request per turn of its select() loop and sends each answer by itself. Pipelined requests
//     are answered one by one, so pipelining gains little over it (on one core each answer wakes
//     the client, which sends one more request, which wakes the server: the exchange stays one
//     at a time).
//   - "libmodbus_server tcp --batch": the same modbus_reply, but every whole request of a read is
//     answered and the answers leave corked together in one segment, as a gateway or PLC that
//     queues requests does. The pipelined figures (and the "vs lmb" column, against libmodbus's
//     client on this server) are the throughput the issue asks about.
//
// Pinning: the process pins itself with sched_setaffinity() to one CPU (--cpu, default 1) before
// it starts any thread or server, so the servers (children: affinity is inherited across fork and
// exec), the engine's thread and every client share that one core. On this two-core machine
// unpinned figures are bimodal (client and server on one core or on two, as the scheduler
// pleases); on one core every client pays the same context switches, so the rows compare.
// --no-pin leaves placement to the scheduler.
//
// Rounds: with --rounds R every client runs R times count/R transactions, the clients taking turns
// (raw, libmodbus, engine rows, raw, libmodbus, ...), and each row adds up its rounds. On a machine
// shared with other work the load then falls on every row alike instead of on whichever row ran
// during a busy second.
//
//   bench_poll [--count N] [--warmup N] [--quantity Q] [--cpu C | --no-pin] [--pipeline 4,8]
//              [--server one|batch|both] [--rounds R] [--rows raw,libmodbus,logged,memory,unlogged]
//
// --rows picks the non-pipelined clients (default: all; --pipeline "" drops the pipelined ones),
// to profile one alone, e.g. instructions per transaction of the engine's thread:
//   valgrind --tool=callgrind --separate-threads=yes bench_poll --server one --pipeline ""
//            --rows logged --count 5000 --warmup 200
// then the engine thread's total (callgrind.out.PID-02) over 5200 transactions.
//
// scripts/bench-poll.sh builds a Release tree and runs it.
//
// Figures (issue 3, sequential polling at 90 % of libmodbus while logging every frame). Instructions
// per transaction in the engine's thread, callgrind (load-independent; --rows logged, 5,200
// transactions, thread 2's total / 5,200; before --rows existed: both sequential rows, / 10,400):
//   9.1k (Qt's QTcpSocket read path and GLib dispatcher, both rows) -> 8.2k (TcpLink reads its own
//   descriptor) -> 6.5k logged / 6.0k both rows (EngineEventDispatcher) -> 6.2k logged (no
//   awake/aboutToBlock/recorded emission without receivers) -> 6.0k logged (DirectSocketNotifier).
// Throughput, bench_poll --cpu 1 --rounds 5, old and new binaries taking turns, 4 runs each on a
// machine at load 14-18 (libmodbus itself 9-24k tx/s instead of ~30k quiet), sequential logged
// as % of libmodbus: one-by-one server 59-90 % (median 78) before, 86-96 % (median 87) after;
// --batch server 69-81 % before, 78-92 % after; pipeline 8 on --batch 245-334 % before,
// 282-310 % after. On a quiet machine before: sequential logged 84-88 %, log off 85-95 %.
#include "enginepoll.h"
#include "peerprocess.h"
#include "pollbaselines.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>

#include <functional>
#include <vector>

#include <sched.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

using namespace mbscope;
using namespace mbscope::bench;

namespace {

struct Options {
    PollPlan plan;
    int cpu = 1;
    bool pin = true;
    QList<int> pipelines{4, 8};
    bool oneByOne = true; // libmodbus_server tcp
    bool batch = true;    // libmodbus_server tcp --batch
    int rounds = 1;
    // --rows: which clients run (profiling one of them: valgrind --tool=callgrind, strace -c)
    bool raw = true;
    bool libmodbus = true;
    bool logged = true;
    bool memory = true;
    bool unlogged = true;
};

bool parse(const QStringList &args, Options *o)
{
    for (qsizetype i = 1; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (a == QLatin1String("--no-pin")) {
            o->pin = false;
            continue;
        }
        if (i + 1 >= args.size())
            return false;
        const QString v = args.at(++i);
        bool ok = true;
        if (a == QLatin1String("--count"))
            o->plan.count = v.toLongLong(&ok);
        else if (a == QLatin1String("--warmup"))
            o->plan.warmup = v.toLongLong(&ok);
        else if (a == QLatin1String("--rounds"))
            o->rounds = v.toInt(&ok);
        else if (a == QLatin1String("--quantity"))
            o->plan.quantity = v.toInt(&ok);
        else if (a == QLatin1String("--server")) {
            ok = v == QLatin1String("one") || v == QLatin1String("batch") || v == QLatin1String("both");
            o->oneByOne = v != QLatin1String("batch");
            o->batch = v != QLatin1String("one");
        } else if (a == QLatin1String("--rows")) {
            o->raw = o->libmodbus = o->logged = o->memory = o->unlogged = false;
            for (const QString &row : v.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                if (row == QLatin1String("raw"))
                    o->raw = true;
                else if (row == QLatin1String("libmodbus"))
                    o->libmodbus = true;
                else if (row == QLatin1String("logged"))
                    o->logged = true;
                else if (row == QLatin1String("memory"))
                    o->memory = true;
                else if (row == QLatin1String("unlogged"))
                    o->unlogged = true;
                else
                    return false;
            }
        } else if (a == QLatin1String("--cpu"))
            o->cpu = v.toInt(&ok);
        else if (a == QLatin1String("--pipeline")) {
            o->pipelines.clear();
            for (const QString &n : v.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                o->pipelines.append(n.toInt(&ok));
                if (!ok || o->pipelines.last() < 1)
                    return false;
            }
        } else
            return false;
        if (!ok)
            return false;
    }
    return o->plan.count > 0 && o->rounds >= 1 && o->rounds <= o->plan.count && o->plan.warmup >= 0 && o->plan.quantity >= 1 && o->plan.quantity <= 125;
}

bool pinTo(int cpu)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return sched_setaffinity(0, sizeof set, &set) == 0;
}

void printRow(PollFigures &f, double libmodbusRate)
{
    const double share = libmodbusRate > 0 ? 100.0 * f.perSecond() / libmodbusRate : 0.0;
    std::printf("%-34s %10.0f %8.1f %8.1f %8.1f %9.1f %7lld %7.0f %%   %s\n", qPrintable(f.client), f.perSecond(),
                f.percentileUs(50), f.percentileUs(90), f.percentileUs(99), f.percentileUs(100), f.errors, share,
                qPrintable(f.note));
    std::fflush(stdout);
}

// One table: a server started with serverArgs, every client against it. Returns false when a
// baseline or the sequential engine had errors (or the server did not start).
bool runTable(const Options &options, const QStringList &serverArgs, const char *serverNote, bool unloggedRow)
{
    testpeers::PeerProcess server;
    if (!server.start(testpeers::libmodbusServerPath(), serverArgs)) {
        std::fprintf(stderr, "bench_poll: %s\n", qPrintable(server.error()));
        return false;
    }
    PollPlan plan = options.plan;
    plan.port = server.port();

    std::printf("\nserver: libmodbus_server %s on %s (%s); Read Holding Registers x %d; %lld transactions per "
                "client in %d round(s), %lld warm-up before each; %s\n",
                qPrintable(serverArgs.join(QLatin1Char(' '))), qPrintable(server.where()), serverNote, plan.quantity,
                plan.count / options.rounds * options.rounds, options.rounds, plan.warmup,
                options.pin ? qPrintable(QStringLiteral("server and clients pinned to CPU %1").arg(options.cpu))
                            : "unpinned");
    std::printf("%-34s %10s %8s %8s %8s %9s %7s %9s   %s\n", "client", "tx/s", "p50 us", "p90 us", "p99 us",
                "max us", "errors", "vs lmb", "note");

    // The rows, in the order they take turns: raw, libmodbus, the engine sequential (logged, then
    // unlogged: what logging every frame costs), then pipelined.
    std::vector<std::function<PollFigures(const PollPlan &)>> clients;
    if (options.raw)
        clients.emplace_back(pollRawSocket);
    const size_t libmodbusRow = clients.size();
    if (options.libmodbus)
        clients.emplace_back(pollLibmodbus);
    using Log = EnginePollSettings::Log;
    auto engineRow = [](Log log, int depth) {
        return [log, depth](const PollPlan &roundPlan) {
            EnginePollSettings engine;
            engine.plan = roundPlan;
            engine.log = log;
            engine.pipelineDepth = depth;
            return pollEngine(engine);
        };
    };
    const size_t sequentialRow = clients.size();
    if (options.logged)
        clients.emplace_back(engineRow(Log::Journal, 1));
    if (unloggedRow && options.memory)
        clients.emplace_back(engineRow(Log::Memory, 1));
    if (unloggedRow && options.unlogged)
        clients.emplace_back(engineRow(Log::Off, 1));
    for (int depth : options.pipelines)
        clients.emplace_back(engineRow(Log::Journal, depth));

    std::vector<PollFigures> rows(clients.size());
    PollPlan roundPlan = plan;
    roundPlan.count = plan.count / options.rounds;
    for (int round = 0; round < options.rounds; ++round) {
        for (size_t i = 0; i < clients.size(); ++i)
            rows[i].absorb(clients[i](roundPlan));
    }
    if (options.rounds > 1)
        std::printf("(notes are the first round's)\n");
    const double baseline = options.libmodbus ? rows[libmodbusRow].perSecond() : 0.0;
    for (PollFigures &row : rows)
        printRow(row, baseline);
    bool ok = true;
    for (size_t i = 0; i < rows.size() && i <= sequentialRow; ++i)
        ok = ok && !rows[i].errors;
    return ok;
}

} // namespace

int main(int argc, char **argv)
{
    Options options;
    {
        QStringList args;
        for (int i = 0; i < argc; ++i)
            args.append(QString::fromLocal8Bit(argv[i]));
        if (!parse(args, &options)) {
            std::fprintf(stderr, "usage: bench_poll [--count N] [--warmup N] [--quantity Q] [--cpu C | --no-pin] "
                                 "[--pipeline 4,8] [--server one|batch|both] [--rounds R] "
                                 "[--rows raw,libmodbus,logged,memory,unlogged]\n");
            return 2;
        }
    }
    // Before QCoreApplication and the server: every thread and child made later inherits it.
    if (options.pin) {
        const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
        if (options.cpu >= cpus)
            options.cpu = int(cpus - 1);
        if (!pinTo(options.cpu)) {
            std::fprintf(stderr, "bench_poll: cannot pin to CPU %d: %s (running unpinned)\n", options.cpu,
                         std::strerror(errno));
            options.pin = false;
        }
    }
    QCoreApplication app(argc, argv);

    QString why;
    if (!testpeers::libmodbusPeersAvailable(&why)) {
        std::fprintf(stderr, "bench_poll: %s\n", qPrintable(why));
        return 2;
    }
    bool ok = true;
    if (options.oneByOne)
        ok = runTable(options, {QStringLiteral("tcp")}, "one request per read, each answer sent alone", true) && ok;
    if (options.batch)
        ok = runTable(options, {QStringLiteral("tcp"), QStringLiteral("--batch")},
                      "every whole request of a read answered, answers sent together", false)
             && ok;
    return ok ? 0 : 1;
}
