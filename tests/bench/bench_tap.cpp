// The inline tap's speed (issue 27, "How fast, how solid"): `mbscope tap` in front of `mbscope
// simulate --profile conformance --listen tcp://127.0.0.1:0 --quiet` (no response delay), beside
// the same masters talking to the simulator directly and through a plain byte proxy, in one run:
//   - "direct": the masters connect to the simulator;
//   - "socat": `socat TCP-LISTEN:P,fork,reuseaddr TCP:127.0.0.1:SIM` in between (a process per
//     connection, bytes copied, nothing decoded);
//   - "tap": `mbscope tap --listen tcp://127.0.0.1:0 --target tcp://127.0.0.1:SIM --quiet` in
//     between (every request framed, checked, routed and its answer framed anew);
//   - "tap --pipeline N": the same with N requests in flight to the simulator (the masters'
//     requests share the tap's one connection to its target).
// The masters are libmodbus_many_clients (tests/peers): N libmodbus masters as threads, Read
// Holding Registers of 10 registers back to back, every answer checked. The simulator, socat and
// the taps are pinned to --server-cpu, the masters to --client-cpu (as bench_simthroughput pins);
// the rows take turns for --rounds rounds, the order reversed every other round, and the tables
// give each row's median over the rounds.
//
// 1. Added latency: one master, --requests requests per round; p50 and p99 of each row, and what
//    socat and the tap add to the direct path (the target for the tap: p50 under 50 us and
//    p99 under 200 us above direct). With --cpu C the section runs twice in the same run: pinned as
//    above, then with every process of the comparison (masters, simulator, socat and its children,
//    the tap) on CPU C, as `taskset -c C` would run them. Two processes on different CPUs wake each
//    other through an inter-processor interrupt and a CPU coming out of idle; on one CPU a wake-up
//    is a context switch. The extra process in the middle pays that hop twice a transaction, so the
//    one-CPU figures show what the tap itself adds, and the split ones what a deployment across
//    CPUs pays. A summary gives both pinnings side by side.
// 2. Throughput with --masters masters (1, 4 and 16), --per-master requests each: transactions/s,
//    p99, and the CPU the process in the middle used per transaction (the simulator's for direct;
//    socat's with its forks).
// 3. A serial target (tapserialbench.h): an RTU slave behind the tap at each of --bauds, on a
//    socat pty pair and on a paced line, beside the line's limit.
//
//   bench_tap [--requests 20000] [--per-master 2000] [--masters 1,4,16] [--rounds 5]
//             [--pipeline 16] [--serial-requests 200] [--serial-masters 4] [--bauds 115200,19200]
//             [--sections latency,throughput,serial] [--server-cpu 0] [--client-cpu 1] [--cpu C]
//             [--no-pin] [--mbscope PATH]
//
// Figures only, nothing asserted: exit status 1 when a master saw an error (a wrong or missing
// answer), 2 when something could not start. scripts/bench-tap.sh builds Release and runs it;
// docs/benchmarks.md ("The tap") has figures.
#include "benchprocess.h"
#include "tapserialbench.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QRegularExpression>
#include <QtCore/QStringList>
#include <QtCore/QThread>

#include <cstdio>
#include <memory>
#include <vector>

#include <unistd.h>

using namespace mbscope::bench;

namespace {

struct Options {
    int requests = 20000;
    int perMaster = 2000;
    QList<int> masters{1, 4, 16};
    int rounds = 5;
    int pipeline = 16; // 0: no pipelined row
    bool latency = true;
    bool throughput = true;
    bool serial = true;
    SerialBenchOptions serialOptions;
    int serverCpu = 0;
    int clientCpu = 1;
    int oneCpu = -1; // --cpu: the latency section again with every process on this CPU
    bool pin = true;
    QString mbscope = QStringLiteral(MBSCOPE_EXECUTABLE);
};

QList<int> numbers(const QString &text, bool *ok)
{
    QList<int> out;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const int n = part.toInt(ok);
        if (!*ok || n < 1) {
            *ok = false;
            return {};
        }
        out.append(n);
    }
    *ok = !out.isEmpty();
    return out;
}

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
        if (a == QLatin1String("--requests"))
            o->requests = v.toInt(&ok);
        else if (a == QLatin1String("--per-master"))
            o->perMaster = v.toInt(&ok);
        else if (a == QLatin1String("--masters"))
            o->masters = numbers(v, &ok);
        else if (a == QLatin1String("--rounds"))
            o->rounds = v.toInt(&ok);
        else if (a == QLatin1String("--pipeline"))
            o->pipeline = v.toInt(&ok);
        else if (a == QLatin1String("--serial-requests"))
            o->serialOptions.requestsPerMaster = v.toInt(&ok);
        else if (a == QLatin1String("--serial-masters"))
            o->serialOptions.masters = v.toInt(&ok);
        else if (a == QLatin1String("--bauds"))
            o->serialOptions.bauds = numbers(v, &ok);
        else if (a == QLatin1String("--server-cpu"))
            o->serverCpu = v.toInt(&ok);
        else if (a == QLatin1String("--client-cpu"))
            o->clientCpu = v.toInt(&ok);
        else if (a == QLatin1String("--cpu")) {
            o->oneCpu = v.toInt(&ok);
            ok = ok && o->oneCpu >= 0;
        }
        else if (a == QLatin1String("--mbscope"))
            o->mbscope = v;
        else if (a == QLatin1String("--sections")) {
            o->latency = o->throughput = o->serial = false;
            for (const QString &section : v.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                if (section == QLatin1String("latency"))
                    o->latency = true;
                else if (section == QLatin1String("throughput"))
                    o->throughput = true;
                else if (section == QLatin1String("serial"))
                    o->serial = true;
                else
                    return false;
            }
        } else
            return false;
        if (!ok)
            return false;
    }
    return o->requests >= 1 && o->perMaster >= 1 && o->rounds >= 1 && o->pipeline >= 0 && o->pipeline <= 64
           && o->serialOptions.requestsPerMaster >= 1 && o->serialOptions.masters >= 1 && o->serverCpu >= 0 && o->clientCpu >= 0
           && (o->latency || o->throughput || o->serial);
}

// Where the processes of a comparison run: the process in the middle and the simulator on one
// CPU, the masters on another (or unpinned); or every one of them on the same CPU.
struct Pinning {
    QString label;
    bool pin = true;
    int serverCpu = 0;
    int masterCpu = 1;
};

Pinning splitPinning(const Options &o)
{
    return {o.pin ? QStringLiteral("simulator, socat, tap on CPU %1; masters on CPU %2").arg(o.serverCpu).arg(o.clientCpu)
                  : QStringLiteral("unpinned"),
            o.pin, o.serverCpu, o.clientCpu};
}

Pinning onePinning(const Options &o)
{
    return {QStringLiteral("every process on CPU %1").arg(o.oneCpu), true, o.oneCpu, o.oneCpu};
}

// The servers (and their threads) moved to the pinning's server CPU (any CPU when unpinned).
bool applyPinning(const std::vector<BenchServer *> &servers, const Pinning &pinning)
{
    bool all = true;
    for (const BenchServer *server : servers) {
        if (server->pid() > 0 && !pinRunning(server->pid(), pinning.pin ? pinning.serverCpu : -1)) {
            std::fprintf(stderr, "bench_tap: cannot move %s to CPU %d\n", qPrintable(server->name), pinning.serverCpu);
            all = false;
        }
    }
    return all;
}

// A way from the masters to the simulator, with its figures per round.
struct Row {
    QString name;
    BenchServer *middle = nullptr; // the process in between; nullptr: direct (the simulator's CPU is counted)
    quint16 port = 0;
    // Per masters count (index into Options::masters; latency: one entry), per round.
    std::vector<std::vector<double>> tps, p50, p99, cpuPerTx;
};

// One round of masters through a row; false on an error.
bool runRound(Row &row, BenchServer &sim, int masters, int requests, size_t slot, int round, const Pinning &pinning)
{
    BenchServer &measured = row.middle ? *row.middle : sim;
    const double cpuBefore = measured.cpuSeconds();
    const ClientFigures f = runManyClients(row.port, masters, {QStringLiteral("--requests"), QString::number(requests)}, pinning.pin,
                                           pinning.masterCpu);
    if (row.middle && row.middle->childrenCpu)
        QThread::msleep(100); // socat's children are counted once it has waited for them
    const double cpu = measured.cpuSeconds() - cpuBefore;
    if (!f.ok) {
        std::fprintf(stderr, "bench_tap: the masters through %s said: %s\n", qPrintable(row.name), qPrintable(f.said));
        return false;
    }
    const double perTx = f.transactions > 0 ? cpu * 1e6 / double(f.transactions) : 0.0;
    row.tps[slot].push_back(f.tps);
    row.p50[slot].push_back(f.p50);
    row.p99[slot].push_back(f.p99);
    row.cpuPerTx[slot].push_back(perTx);
    std::printf("round %d  %2d master(s)  %-18s %9.0f tx/s  p50 %7.1f us  p99 %8.1f us  CPU %5.1f us/tx  errors %lld\n", round,
                masters, qPrintable(row.name), f.tps, f.p50, f.p99, perTx, f.errors);
    std::fflush(stdout);
    return f.errors == 0 && f.said.isEmpty();
}

// Every row for `rounds` rounds, taking turns (reversed every other round).
bool runRows(std::vector<Row> &rows, BenchServer &sim, int masters, int requests, size_t slot, const Options &o, const Pinning &pinning)
{
    bool clean = true;
    for (int round = 1; round <= o.rounds; ++round) {
        for (size_t k = 0; k < rows.size(); ++k)
            clean = runRound(rows[round % 2 == 1 ? k : rows.size() - 1 - k], sim, masters, requests, slot, round, pinning) && clean;
    }
    return clean;
}

void resize(std::vector<Row> &rows, size_t count)
{
    for (Row &row : rows) {
        for (std::vector<std::vector<double>> *v : {&row.tps, &row.p50, &row.p99, &row.cpuPerTx}) {
            v->clear();
            v->resize(count);
        }
    }
}

// One pinning's medians: p50 and p99 of each row (in the rows' order).
struct LatencyFigures {
    QString pinning;
    std::vector<std::pair<double, double>> rows;
};

bool latencySection(std::vector<Row> &rows, BenchServer &sim, const Options &o, const Pinning &pinning, LatencyFigures *figures)
{
    std::printf("\n== Added latency: 1 master, %d requests a round, %d round(s); %s\n", o.requests, o.rounds, qPrintable(pinning.label));
    resize(rows, 1);
    const bool clean = runRows(rows, sim, 1, o.requests, 0, o, pinning);
    figures->pinning = pinning.label;
    for (const Row &row : rows)
        figures->rows.emplace_back(median(row.p50[0]), median(row.p99[0]));
    const Row &direct = rows.front();
    const double p50 = median(direct.p50[0]);
    const double p99 = median(direct.p99[0]);
    std::printf("\nmedians over %d round(s)\n%-18s %9s %9s %12s %12s %10s\n", o.rounds, "row", "p50 us", "p99 us", "added p50",
                "added p99", "CPU us/tx");
    for (const Row &row : rows) {
        const double r50 = median(row.p50[0]);
        const double r99 = median(row.p99[0]);
        const bool isDirect = &row == &direct;
        std::printf("%-18s %9.1f %9.1f %12s %12s %10.1f\n", qPrintable(row.name), r50, r99,
                    isDirect ? "-" : qPrintable(QStringLiteral("%1 us").arg(r50 - p50, 0, 'f', 1)),
                    isDirect ? "-" : qPrintable(QStringLiteral("%1 us").arg(r99 - p99, 0, 'f', 1)), median(row.cpuPerTx[0]));
    }
    for (const Row &row : rows) {
        if (!row.name.startsWith(QLatin1String("tap")))
            continue;
        const double added50 = median(row.p50[0]) - p50;
        const double added99 = median(row.p99[0]) - p99;
        std::printf("%s adds %.1f us at p50 (target: under 50: %s) and %.1f us at p99 (target: under 200: %s)\n",
                    qPrintable(row.name), added50, added50 < 50 ? "met" : "NOT met", added99, added99 < 200 ? "met" : "NOT met");
    }
    return clean;
}

// Both pinnings side by side: each row's p50 and p99, and what it adds to the direct path.
void latencySummary(const std::vector<Row> &rows, const std::vector<LatencyFigures> &pinnings, int rounds)
{
    std::printf("\n== Added latency by pinning (medians over %d round(s), one run)\n", rounds);
    for (const LatencyFigures &f : pinnings) {
        std::printf("%s:\n", qPrintable(f.pinning));
        const auto [d50, d99] = f.rows.front();
        for (size_t k = 0; k < rows.size(); ++k) {
            const auto [p50, p99] = f.rows.at(k);
            if (k == 0)
                std::printf("  %-8s p50 %7.1f us  p99 %8.1f us\n", qPrintable(rows.at(k).name), p50, p99);
            else
                std::printf("  %-8s p50 %7.1f us  p99 %8.1f us  adds %+7.1f us at p50, %+8.1f us at p99\n", qPrintable(rows.at(k).name), p50,
                            p99, p50 - d50, p99 - d99);
        }
    }
}

bool throughputSection(std::vector<Row> &rows, BenchServer &sim, const Options &o)
{
    std::printf("\n== Throughput: %d requests per master, %d round(s) per master count\n", o.perMaster, o.rounds);
    resize(rows, size_t(o.masters.size()));
    bool clean = true;
    for (qsizetype m = 0; m < o.masters.size(); ++m)
        clean = runRows(rows, sim, o.masters.at(m), o.perMaster, size_t(m), o, splitPinning(o)) && clean;
    std::printf("\nmedians over %d round(s): transactions/s (p99 us; CPU us/tx of the process in the middle)\n%-8s", o.rounds,
                "masters");
    for (const Row &row : rows)
        std::printf(" %32s", qPrintable(row.name));
    std::printf(" %12s\n", "tap/socat");
    for (qsizetype m = 0; m < o.masters.size(); ++m) {
        std::printf("%-8d", o.masters.at(m));
        double socat = 0;
        double tap = 0;
        for (const Row &row : rows) {
            const double tps = median(row.tps[size_t(m)]);
            if (row.name == QLatin1String("socat"))
                socat = tps;
            if (row.name.startsWith(QLatin1String("tap")))
                tap = std::max(tap, tps);
            std::printf(" %32s", qPrintable(QStringLiteral("%1 (%2; %3)")
                                                .arg(tps, 0, 'f', 0)
                                                .arg(median(row.p99[size_t(m)]), 0, 'f', 0)
                                                .arg(median(row.cpuPerTx[size_t(m)]), 0, 'f', 1)));
        }
        std::printf(" %12s\n", socat > 0 ? qPrintable(QString::number(tap / socat, 'f', 2)) : "-");
    }
    std::printf("tap/socat: the better tap row over socat (the issue: the tap must beat a plain byte proxy)\n");
    return clean;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    Options o;
    if (!parse(app.arguments(), &o)) {
        std::fprintf(stderr, "usage: bench_tap [--requests N] [--per-master N] [--masters 1,4,16] [--rounds R] [--pipeline N] "
                             "[--serial-requests N] [--serial-masters N] [--bauds 115200,19200] "
                             "[--sections latency,throughput,serial] [--server-cpu C] [--client-cpu C] [--cpu C] [--no-pin] "
                             "[--mbscope PATH]\n");
        return 2;
    }
    const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    if ((o.pin && (o.serverCpu >= cpus || o.clientCpu >= cpus)) || o.oneCpu >= cpus) {
        std::fprintf(stderr, "bench_tap: this machine has %ld CPU(s): --server-cpu, --client-cpu and --cpu go from 0 to %ld\n", cpus,
                     cpus - 1);
        return 2;
    }
    std::printf("bench_tap: libmodbus masters (Read Holding Registers, 10 registers, every answer checked); %s; mbscope %s\n",
                o.pin ? qPrintable(QStringLiteral("simulator, socat and taps pinned to CPU %1, masters to CPU %2").arg(o.serverCpu).arg(o.clientCpu))
                      : "unpinned",
                qPrintable(o.mbscope));
    bool clean = true;
    if (o.latency || o.throughput) {
        BenchServer sim;
        sim.name = QStringLiteral("simulate");
        if (!sim.start(o.mbscope,
                       {QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                        QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--quiet")},
                       QRegularExpression(QStringLiteral("listening tcp://127\\.0\\.0\\.1:(\\d+)")), o.pin, o.serverCpu))
            return 2;
        const QString target = QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port);
        BenchServer socat;
        socat.name = QStringLiteral("socat");
        socat.childrenCpu = true;
        const quint16 socatPort = freePort();
        if (!socat.startSilent(QStringLiteral("socat"),
                               {QStringLiteral("TCP-LISTEN:%1,fork,reuseaddr,bind=127.0.0.1").arg(socatPort),
                                QStringLiteral("TCP:127.0.0.1:%1").arg(sim.port)},
                               socatPort, o.pin, o.serverCpu))
            return 2;
        const QRegularExpression tapReady(QStringLiteral("listening tcp://127\\.0\\.0\\.1:(\\d+)"));
        const QStringList tapArgs{QStringLiteral("tap"), QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"),
                                  QStringLiteral("--target"), target, QStringLiteral("--quiet")};
        BenchServer tap;
        tap.name = QStringLiteral("tap");
        if (!tap.start(o.mbscope, tapArgs, tapReady, o.pin, o.serverCpu))
            return 2;
        BenchServer pipelined;
        pipelined.name = QStringLiteral("tap --pipeline %1").arg(o.pipeline);
        if (o.pipeline > 0
            && !pipelined.start(o.mbscope, tapArgs + QStringList{QStringLiteral("--pipeline"), QString::number(o.pipeline)}, tapReady,
                                o.pin, o.serverCpu))
            return 2;
        std::printf("simulator: mbscope simulate --profile conformance --listen %s --quiet (no response delay)\n", qPrintable(target));
        std::printf("socat: socat TCP-LISTEN:%u,fork,reuseaddr,bind=127.0.0.1 TCP:127.0.0.1:%u\n", unsigned(socatPort), unsigned(sim.port));
        std::printf("tap: mbscope tap --listen tcp://127.0.0.1:0 --target %s --quiet%s\n", qPrintable(target),
                    o.pipeline > 0 ? qPrintable(QStringLiteral(" (and the same with --pipeline %1)").arg(o.pipeline)) : "");
        std::vector<Row> rows(3);
        rows[0].name = QStringLiteral("direct");
        rows[0].port = sim.port;
        rows[1].name = socat.name;
        rows[1].middle = &socat;
        rows[1].port = socat.port;
        rows[2].name = tap.name;
        rows[2].middle = &tap;
        rows[2].port = tap.port;
        // Every way warmed up once (connections, the tap's link to its target, caches).
        resize(rows, 1);
        for (Row &row : rows)
            (void)runManyClients(row.port, 4, {QStringLiteral("--requests"), QStringLiteral("200")}, o.pin, o.clientCpu);
        if (o.latency) {
            std::vector<Pinning> pinnings{splitPinning(o)};
            if (o.oneCpu >= 0)
                pinnings.push_back(onePinning(o));
            std::vector<LatencyFigures> figures;
            for (const Pinning &pinning : pinnings) {
                if (!applyPinning({&sim, &socat, &tap}, pinning))
                    return 2;
                figures.emplace_back();
                clean = latencySection(rows, sim, o, pinning, &figures.back()) && clean;
            }
            if (!applyPinning({&sim, &socat, &tap}, splitPinning(o)))
                return 2;
            latencySummary(rows, figures, o.rounds);
        }
        if (o.pipeline > 0) {
            Row row;
            row.name = pipelined.name;
            row.middle = &pipelined;
            row.port = pipelined.port;
            (void)runManyClients(row.port, 4, {QStringLiteral("--requests"), QStringLiteral("200")}, o.pin, o.clientCpu);
            rows.push_back(row);
        }
        if (o.throughput)
            clean = throughputSection(rows, sim, o) && clean;
        for (BenchServer *server : {&pipelined, &tap, &socat, &sim})
            server->stop();
    }
    if (o.serial) {
        o.serialOptions.mbscope = o.mbscope;
        o.serialOptions.pin = o.pin;
        o.serialOptions.serverCpu = o.serverCpu;
        o.serialOptions.clientCpu = o.clientCpu;
        const int status = runSerialSection(o.serialOptions);
        if (status == 2)
            return 2;
        clean = status == 0 && clean;
    }
    return clean ? 0 : 1;
}
