// The simulator's throughput against libmodbus's own server (issue 15, "Also"): the same N
// libmodbus clients (libmodbus_many_clients: one thread and one connection each, Read Holding
// Registers of 10 registers back to back, every answer checked) against, in the same run:
//   - "libmodbus": tests/peers/libmodbus_server tcp --table-size 100, libmodbus's select()-based
//     multi-client server (modbus_tcp_listen, select(), modbus_receive, modbus_reply, as
//     libmodbus's tests/bandwidth-server-many-up.c), tables of 100 items like the profile's;
//   - "simulate": `mbscope simulate --profile conformance --listen tcp://127.0.0.1:0 --quiet`,
//     an ordinary profile (100 holding registers 0-99, the peers' values) with no response delay;
//   - "simulate --record" (with --rows ...,record): the same, journaling every frame to a file.
// Each server is pinned to --server-cpu and the clients to --client-cpu (sched_setaffinity in the
// child, as taskset does; default 0 and 1), both servers the same way. The rows take turns for
// --rounds rounds (the order reversed every other round) and the table gives each row's median
// over the rounds: transactions/s, latency p50/p99 over every transaction of the round, the CPU
// seconds the server process used during the round (utime + stime from /proc/PID/stat) and per
// transaction, and the ratios to libmodbus. Figures only, nothing asserted; exit status 1 when a
// client saw an error (a wrong or missing answer), 2 when something could not start.
//
//   bench_simthroughput [--clients 50] [--requests 1000] [--rounds 5] [--server-cpu 0]
//                       [--client-cpu 1] [--no-pin] [--rows libmodbus,simulate,record]
//                       [--mbscope PATH] [--compare PATH]
//
// --mbscope runs another build of mbscope as the simulator; --compare adds a row "simulate
// (compared)" served by another build (an older one: before and after figures in one run).
// scripts/bench-simthroughput.sh builds Release and runs it; docs/benchmarks.md has figures.
#include "benchprocess.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QRegularExpression>
#include <QtCore/QStringList>
#include <QtCore/QTemporaryDir>

#include <cstdio>
#include <memory>
#include <vector>

#include <unistd.h>

using namespace mbscope::bench;

namespace {

struct Options {
    int clients = 50;
    int requests = 1000;
    int rounds = 5;
    int serverCpu = 0;
    int clientCpu = 1;
    bool pin = true;
    bool libmodbus = true;
    bool simulate = true;
    bool record = false;
    QString mbscope = QStringLiteral(MBSCOPE_EXECUTABLE);
    QString compare; // another mbscope, a row of its own
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
        if (a == QLatin1String("--clients"))
            o->clients = v.toInt(&ok);
        else if (a == QLatin1String("--requests"))
            o->requests = v.toInt(&ok);
        else if (a == QLatin1String("--rounds"))
            o->rounds = v.toInt(&ok);
        else if (a == QLatin1String("--server-cpu"))
            o->serverCpu = v.toInt(&ok);
        else if (a == QLatin1String("--client-cpu"))
            o->clientCpu = v.toInt(&ok);
        else if (a == QLatin1String("--mbscope"))
            o->mbscope = v;
        else if (a == QLatin1String("--compare"))
            o->compare = v;
        else if (a == QLatin1String("--rows")) {
            o->libmodbus = o->simulate = o->record = false;
            for (const QString &row : v.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                if (row == QLatin1String("libmodbus"))
                    o->libmodbus = true;
                else if (row == QLatin1String("simulate"))
                    o->simulate = true;
                else if (row == QLatin1String("record"))
                    o->record = true;
                else
                    return false;
            }
        } else
            return false;
        if (!ok)
            return false;
    }
    return o->clients >= 1 && o->requests >= 1 && o->rounds >= 1 && o->serverCpu >= 0 && o->clientCpu >= 0
           && (o->libmodbus || o->simulate || o->record || !o->compare.isEmpty());
}

// A server under test, with its figures of each round.
struct Server : BenchServer {
    std::vector<double> tps, p50, p99, cpu;
};

// One round of the clients against one server; false on an error.
bool runClients(Server &server, const Options &o, int round)
{
    const double cpuBefore = server.cpuSeconds();
    const ClientFigures f = runManyClients(server.port, o.clients, {QStringLiteral("--requests"), QString::number(o.requests)},
                                           o.pin, o.clientCpu);
    const double cpu = server.cpuSeconds() - cpuBefore;
    if (!f.ok) {
        std::fprintf(stderr, "bench_simthroughput: the clients against %s said: %s\n", qPrintable(server.name), qPrintable(f.said));
        return false;
    }
    server.tps.push_back(f.tps);
    server.p50.push_back(f.p50);
    server.p99.push_back(f.p99);
    server.cpu.push_back(cpu);
    std::printf("round %d  %-20s %10.0f tx/s  p50 %7.1f us  p99 %8.1f us  server CPU %6.2f s (%5.1f us/tx)  errors %lld\n",
                round, qPrintable(server.name), f.tps, f.p50, f.p99, cpu,
                f.transactions > 0 ? cpu * 1e6 / double(f.transactions) : 0.0, f.errors);
    std::fflush(stdout);
    return f.errors == 0 && f.said.isEmpty();
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    Options o;
    if (!parse(app.arguments(), &o)) {
        std::fprintf(stderr, "usage: bench_simthroughput [--clients N] [--requests M] [--rounds R] [--server-cpu C] "
                             "[--client-cpu C] [--no-pin] [--rows libmodbus,simulate,record] [--mbscope PATH] [--compare PATH]\n");
        return 2;
    }
    const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    if (o.pin && (o.serverCpu >= cpus || o.clientCpu >= cpus)) {
        std::fprintf(stderr, "bench_simthroughput: this machine has %ld CPU(s): --server-cpu and --client-cpu go from 0 to %ld\n",
                     cpus, cpus - 1);
        return 2;
    }
    QTemporaryDir dir;
    std::vector<std::unique_ptr<Server>> servers;
    const QRegularExpression libmodbusReady(QStringLiteral("LISTENING 127\\.0\\.0\\.1:(\\d+)"));
    const QRegularExpression simulateReady(QStringLiteral("listening tcp://127\\.0\\.0\\.1:(\\d+)"));
    const QStringList simulateArgs{QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"),
                                   QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")};
    auto add = [&](const QString &name, const QString &program, const QStringList &args, const QRegularExpression &ready) {
        auto server = std::make_unique<Server>();
        server->name = name;
        if (!server->start(program, args, ready, o.pin, o.serverCpu))
            return false;
        servers.push_back(std::move(server));
        return true;
    };
    if (o.libmodbus
        && !add(QStringLiteral("libmodbus"), QStringLiteral(MBSCOPE_LIBMODBUS_SERVER),
                {QStringLiteral("tcp"), QStringLiteral("--table-size"), QStringLiteral("100")}, libmodbusReady))
        return 2;
    if (o.simulate && !add(QStringLiteral("simulate"), o.mbscope, simulateArgs, simulateReady))
        return 2;
    if (!o.compare.isEmpty() && !add(QStringLiteral("simulate (compared)"), o.compare, simulateArgs, simulateReady))
        return 2;
    if (o.record
        && !add(QStringLiteral("simulate --record"), o.mbscope,
                simulateArgs + QStringList{QStringLiteral("--record"), dir.filePath(QStringLiteral("bench.mbjournal"))},
                simulateReady))
        return 2;

    std::printf("%d libmodbus clients x %d Read Holding Registers (10 registers), %d round(s); %s; simulator %s\n", o.clients,
                o.requests, o.rounds,
                o.pin ? qPrintable(QStringLiteral("servers pinned to CPU %1, clients to CPU %2").arg(o.serverCpu).arg(o.clientCpu))
                      : "unpinned",
                qPrintable(o.mbscope));
    bool clean = true;
    for (int round = 1; round <= o.rounds; ++round) {
        for (size_t k = 0; k < servers.size(); ++k) {
            // Every other round the other way round: a busy moment of a shared machine falls on both.
            Server &server = *servers[round % 2 == 1 ? k : servers.size() - 1 - k];
            clean = runClients(server, o, round) && clean;
        }
    }
    for (auto &server : servers)
        server->stop();

    const long long perRound = (long long)o.clients * o.requests;
    std::printf("\nmedians over %d round(s), %lld transactions each\n", o.rounds, perRound);
    std::printf("%-20s %10s %9s %9s %12s %10s %12s %12s\n", "server", "tx/s", "p50 us", "p99 us", "server CPU s",
                "CPU us/tx", "tx/s ratio", "CPU ratio");
    const Server *baseline = o.libmodbus ? servers.front().get() : nullptr;
    for (const auto &server : servers) {
        const double tps = median(server->tps);
        const double cpu = median(server->cpu);
        QString tpsRatio = QStringLiteral("-");
        QString cpuRatio = QStringLiteral("-");
        if (baseline && baseline != server.get()) {
            tpsRatio = QString::number(tps / median(baseline->tps), 'f', 2);
            if (median(baseline->cpu) > 0)
                cpuRatio = QString::number(cpu / median(baseline->cpu), 'f', 2);
        }
        std::printf("%-20s %10.0f %9.1f %9.1f %12.2f %10.1f %12s %12s\n", qPrintable(server->name), tps, median(server->p50),
                    median(server->p99), cpu, cpu * 1e6 / double(perRound), qPrintable(tpsRatio), qPrintable(cpuRatio));
    }
    if (baseline && servers.size() > 1)
        std::printf("ratio mbscope/libmodbus (transactions/s): %.2f\n", median(servers[1]->tps) / median(baseline->tps));
    return clean ? 0 : 1;
}
