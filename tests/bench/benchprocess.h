#pragma once

#include <QtCore/QProcess>
#include <QtCore/QRegularExpression>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <memory>
#include <vector>

// What the benchmarks that run real processes share (bench_simthroughput, bench_tap): CPU pinning,
// servers started and stopped, libmodbus_many_clients rounds and their figures.
namespace mbscope::bench {

// The process pinned to one CPU from before exec, as taskset would (nothing when pin is false).
void pinChild(QProcess &process, bool pin, int cpu);

// A running process moved to one CPU (cpu < 0: any CPU), every thread of it (/proc/PID/task): what a process forks
// afterwards (socat's child per connection) inherits it. False when a thread could not be moved.
bool pinRunning(qint64 pid, int cpu);

// The median of the values (0 for none).
[[nodiscard]] double median(std::vector<double> values);

// A server under test (a simulator, a proxy, a tap): started, where it listens read from its
// standard output with a regular expression whose first group is the port, stopped at the end.
struct BenchServer {
    QString name;
    std::unique_ptr<QProcess> process;
    quint16 port = 0;
    bool childrenCpu = false; // its CPU includes its children's (socat forks one per connection)

    // Reads its output until ready matches (20 s at most); false with a message on stderr.
    bool start(const QString &program, const QStringList &args, const QRegularExpression &ready, bool pin, int cpu);
    // A program that says nothing: ready once a TCP connection to port is accepted.
    bool startSilent(const QString &program, const QStringList &args, quint16 listenPort, bool pin, int cpu);
    [[nodiscard]] qint64 pid() const { return process ? process->processId() : 0; }
    [[nodiscard]] double cpuSeconds() const;
    // Stopped with SIGTERM (and its stdin closed: libmodbus_server leaves then); standard output left.
    QByteArray stop();
};

// One line of libmodbus_many_clients (tests/peers/libmodbus_many_clients.c).
struct ClientFigures {
    bool ok = false;      // it ran and printed its line
    QString said;         // its output and errors when not
    long long transactions = 0;
    long long errors = 0;
    double seconds = 0;
    double tps = 0;
    double p50 = 0; // microseconds
    double p99 = 0;
    double max = 0;
};

// Runs libmodbus_many_clients against 127.0.0.1:port (pinned), with --check, and waits for it.
[[nodiscard]] ClientFigures runManyClients(quint16 port, int clients, const QStringList &more, bool pin, int cpu,
                                           int timeoutMs = 600000);

// A TCP port of 127.0.0.1 nobody listens on now (bound by the system's choice, then released).
[[nodiscard]] quint16 freePort();

} // namespace mbscope::bench
