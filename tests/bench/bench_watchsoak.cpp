// Soak of the watch service: `mbscope watch --metrics` polling `mbscope simulate` as fast as the
// link allows (a watch at interval 0: 10 holding registers over Modbus TCP on loopback), for N
// polls (default one million). The service's own /metrics is read twice a second: the polls
// counted, its resident memory (process_resident_memory_bytes) and CPU seconds. Printed: memory
// after 10,000 polls, at each checkpoint and after N (flat memory is the point), polls per second,
// CPU per poll of the service and of the simulator; beside them, the baseline of a raw socket
// loop (this program, blocking reads) polling the same simulator. Figures only, never asserted.
//
// Usage: bench_watchsoak [--polls N]          (ctest runs --polls 20000)
#include "clitest.h"
#include "servicepeers.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>
#include <QtNetwork/QTcpSocket>

#include <csignal>
#include <cstdio>
#include <unistd.h>

using namespace mbscope::testcli;

namespace {

// CPU seconds (user + system) of a process, from /proc/PID/stat.
double cpuSeconds(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return 0;
    const QByteArray line = f.readAll();
    const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
    return (fields.value(11).toDouble() + fields.value(12).toDouble()) / double(::sysconf(_SC_CLK_TCK));
}

struct Point {
    double polls = 0;
    double rssBytes = 0;
    double cpu = 0;
    double simCpu = 0;
    double seconds = 0;
};

// A blocking request/answer loop on one socket: the floor any poller on this machine sits on.
Point rawBaseline(const QString &hostPort, int count)
{
    Point p;
    QTcpSocket socket;
    socket.connectToHost(hostPort.section(QLatin1Char(':'), 0, 0), quint16(hostPort.section(QLatin1Char(':'), 1).toUInt()));
    if (!socket.waitForConnected(5000))
        return p;
    QElapsedTimer t;
    t.start();
    const double cpu0 = cpuSeconds(QCoreApplication::applicationPid());
    QByteArray request = QByteArray::fromHex("000000000006010300000010");
    for (int i = 0; i < count; ++i) {
        request[0] = char(i >> 8);
        request[1] = char(i);
        socket.write(request);
        socket.waitForBytesWritten(1000);
        qsizetype got = 0;
        while (got < 9 + 20) {
            if (!socket.bytesAvailable() && !socket.waitForReadyRead(1000))
                return p;
            got += socket.read(64).size();
        }
    }
    p.polls = count;
    p.seconds = double(t.nsecsElapsed()) / 1e9;
    p.cpu = cpuSeconds(QCoreApplication::applicationPid()) - cpu0;
    return p;
}

void printPoint(const char *label, const Point &p, const Point &start)
{
    const double polls = p.polls - start.polls;
    const double seconds = p.seconds - start.seconds;
    std::printf("%-22s %10.0f polls %9.1f MiB RSS %9.0f polls/s %8.1f us CPU/poll (service) %8.1f us (simulator)\n", label, p.polls,
                p.rssBytes / 1048576.0, seconds > 0 ? polls / seconds : 0, polls > 0 ? (p.cpu - start.cpu) / polls * 1e6 : 0,
                polls > 0 ? (p.simCpu - start.simCpu) / polls * 1e6 : 0);
    std::fflush(stdout);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    double target = 1000000;
    const QStringList args = app.arguments();
    if (const qsizetype i = args.indexOf(QStringLiteral("--polls")); i >= 0)
        target = args.value(i + 1).toDouble();
    std::signal(SIGPIPE, SIG_IGN);

    Simulator simulator;
    QString error;
    if (!simulator.start(QStringLiteral("conformance"), 0, &error)) {
        std::fprintf(stderr, "bench_watchsoak: %s\n", qPrintable(error));
        return 1;
    }
    const QString hostPort = simulator.url().mid(int(qstrlen("tcp://")));
    QTemporaryDir dir;
    const QString session = dir.filePath(QStringLiteral("soak.mbscope.json"));
    QFile f(session);
    if (!f.open(QIODevice::WriteOnly))
        return 1;
    f.write(QStringLiteral(R"({"format": "mbscope-session", "version": 2, "name": "soak",
  "watches": [{"name": "soak", "target": "%1", "unit": 1, "function": 3, "address": 0, "quantity": 10, "intervalMs": 0,
               "points": [{"address": 0, "name": "first", "unit": "V", "scale": 0.01}]}]})")
                .arg(simulator.url())
                .toUtf8());
    f.close();

    // The simulator prints nothing per request (--quiet), so its CPU is its own work.
    const Point raw = rawBaseline(hostPort, 20000);

    ChildProcess watch;
    if (!watch.start(mbscopePath(), {QStringLiteral("watch"), session, QStringLiteral("--metrics"), QStringLiteral("127.0.0.1:0"),
                                     QStringLiteral("--log-level"), QStringLiteral("notice"), QStringLiteral("--quiet")},
                     &error) ||
        !watch.waitForOutput("/metrics\n", 30000)) {
        std::fprintf(stderr, "bench_watchsoak: %s %s\n", qPrintable(error), watch.output().constData());
        return 1;
    }
    const QByteArray out = watch.output();
    const qsizetype at = out.indexOf("http://");
    const QString url = QString::fromUtf8(out.mid(at, out.indexOf('\n', at) - at));

    std::printf("mbscope watch soak: one watch, 10 holding registers, interval 0, Modbus TCP on loopback, %.0f polls\n", target);
    std::printf("baseline: raw socket loop    %10.0f polls %9s         %9.0f polls/s %8.1f us CPU/poll (client)\n", raw.polls, "",
                raw.seconds > 0 ? raw.polls / raw.seconds : 0, raw.polls > 0 ? raw.cpu / raw.polls * 1e6 : 0);
    QElapsedTimer clock;
    clock.start();
    const auto sample = [&]() {
        Point p;
        const HttpReply reply = httpGet(url, {}, 5000);
        p.polls = metricValue(reply.body, QStringLiteral("mbscope_watch_polls_total")).value_or(0);
        p.rssBytes = metricValue(reply.body, QStringLiteral("process_resident_memory_bytes")).value_or(0);
        p.cpu = metricValue(reply.body, QStringLiteral("process_cpu_seconds_total")).value_or(0);
        p.simCpu = cpuSeconds(simulator.pid());
        p.seconds = double(clock.nsecsElapsed()) / 1e9;
        return p;
    };
    const Point start = sample();
    Point at10k;
    bool have10k = false;
    QList<double> checkpoints{100000, 250000, 500000, 750000};
    Point last = start;
    double lastPolls = -1;
    int stalls = 0;
    while (last.polls < target) {
        QThread::msleep(500);
        last = sample();
        if (!have10k && last.polls >= 10000) {
            at10k = last;
            have10k = true;
            printPoint("after 10k", at10k, start);
        }
        while (!checkpoints.isEmpty() && last.polls >= checkpoints.first() && checkpoints.first() < target) {
            printPoint(qPrintable(QStringLiteral("after %1k").arg(checkpoints.takeFirst() / 1000)), last, start);
        }
        stalls = last.polls == lastPolls ? stalls + 1 : 0;
        lastPolls = last.polls;
        if (stalls > 20 || !watch.isRunning()) {
            std::fprintf(stderr, "bench_watchsoak: the polls stopped at %.0f: %s\n", last.polls, watch.output().constData());
            return 1;
        }
    }
    printPoint(qPrintable(QStringLiteral("after %1").arg(last.polls, 0, 'f', 0)), last, start);
    if (have10k) {
        std::printf("resident memory from 10k to %.0f polls: %+.1f MiB (%.1f -> %.1f MiB); %.1f s in all\n", last.polls,
                    (last.rssBytes - at10k.rssBytes) / 1048576.0, at10k.rssBytes / 1048576.0, last.rssBytes / 1048576.0, last.seconds);
    }
    const int code = watch.stop(SIGTERM);
    simulator.stop();
    return code == 0 ? 0 : 1;
}
