#include "benchprocess.h"

#include "peerprocess.h"
#include "procstat.h"

#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QThread>
#include <QtNetwork/QTcpServer>
#include <QtNetwork/QTcpSocket>

#include <algorithm>
#include <cstdio>

#include <sched.h>
#include <unistd.h>

namespace mbscope::bench {

void pinChild(QProcess &process, bool pin, int cpu)
{
    if (!pin)
        return;
    process.setChildProcessModifier([cpu] {
        cpu_set_t set;
        CPU_ZERO(&set);
        CPU_SET(cpu, &set);
        sched_setaffinity(0, sizeof set, &set);
    });
}

bool pinRunning(qint64 pid, int cpu)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    for (long c = 0; c < cpus; ++c) {
        if (cpu < 0 || c == cpu)
            CPU_SET(int(c), &set);
    }
    const QStringList threads = QDir(QStringLiteral("/proc/%1/task").arg(pid)).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    bool all = !threads.isEmpty();
    for (const QString &tid : threads)
        all = sched_setaffinity(pid_t(tid.toLongLong()), sizeof set, &set) == 0 && all;
    return all;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

bool BenchServer::start(const QString &program, const QStringList &args, const QRegularExpression &ready, bool pin, int cpu)
{
    process = std::make_unique<QProcess>();
    process->setProcessChannelMode(QProcess::SeparateChannels);
    pinChild(*process, pin, cpu);
    process->start(program, args);
    if (!process->waitForStarted(10000)) {
        std::fprintf(stderr, "cannot start %s: %s\n", qPrintable(program), qPrintable(process->errorString()));
        return false;
    }
    QByteArray out;
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < 20000) {
        const QRegularExpressionMatch m = ready.match(QString::fromUtf8(out));
        if (m.hasMatch()) {
            port = quint16(m.captured(1).toUInt());
            return true;
        }
        if (!process->waitForReadyRead(200) && process->state() == QProcess::NotRunning)
            break;
        out += process->readAllStandardOutput();
    }
    std::fprintf(stderr, "%s did not say where it listens: %s%s\n", qPrintable(name), out.constData(),
                 process->readAllStandardError().constData());
    return false;
}

bool BenchServer::startSilent(const QString &program, const QStringList &args, quint16 listenPort, bool pin, int cpu)
{
    process = std::make_unique<QProcess>();
    pinChild(*process, pin, cpu);
    process->start(program, args);
    if (!process->waitForStarted(10000)) {
        std::fprintf(stderr, "cannot start %s: %s\n", qPrintable(program), qPrintable(process->errorString()));
        return false;
    }
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < 20000 && process->state() == QProcess::Running) {
        QTcpSocket probe;
        probe.connectToHost(QStringLiteral("127.0.0.1"), listenPort);
        if (probe.waitForConnected(1000)) {
            port = listenPort;
            return true;
        }
        QThread::msleep(50);
    }
    std::fprintf(stderr, "%s does not accept connections on port %u: %s\n", qPrintable(name), unsigned(listenPort),
                 process->readAllStandardError().constData());
    return false;
}

double BenchServer::cpuSeconds() const
{
    return process ? testcli::processCpuSeconds(process->processId(), childrenCpu) : -1;
}

QByteArray BenchServer::stop()
{
    if (!process)
        return {};
    process->closeWriteChannel();
    process->terminate();
    if (!process->waitForFinished(10000))
        process->kill();
    process->waitForFinished(2000);
    return process->readAllStandardOutput();
}

ClientFigures runManyClients(quint16 port, int clients, const QStringList &more, bool pin, int cpu, int timeoutMs)
{
    ClientFigures f;
    QProcess client;
    pinChild(client, pin, cpu);
    client.start(testpeers::libmodbusManyClientsPath(), QStringList{QStringLiteral("127.0.0.1"), QString::number(port),
                                                                   QStringLiteral("--clients"), QString::number(clients),
                                                                   QStringLiteral("--check")}
                                                           + more);
    if (!client.waitForFinished(timeoutMs)) {
        client.kill();
        client.waitForFinished(2000);
        f.said = QStringLiteral("did not finish");
        return f;
    }
    const QString line = QString::fromUtf8(client.readAllStandardOutput()).trimmed();
    static const QRegularExpression figures(QStringLiteral(
        "transactions (\\d+) errors (\\d+) seconds (\\S+) tps (\\S+) p50 (\\S+) p90 \\S+ p99 (\\S+) max (\\S+)"));
    const QRegularExpressionMatch m = figures.match(line);
    if (!m.hasMatch()) {
        f.said = line + QLatin1Char(' ') + QString::fromUtf8(client.readAllStandardError());
        return f;
    }
    f.ok = true;
    f.transactions = m.captured(1).toLongLong();
    f.errors = m.captured(2).toLongLong();
    f.seconds = m.captured(3).toDouble();
    f.tps = m.captured(4).toDouble();
    f.p50 = m.captured(5).toDouble();
    f.p99 = m.captured(6).toDouble();
    f.max = m.captured(7).toDouble();
    if (f.errors > 0 || client.exitCode() != 0)
        f.said = QString::fromUtf8(client.readAllStandardError());
    return f;
}

quint16 freePort()
{
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost, 0))
        return 0;
    return server.serverPort();
}

} // namespace mbscope::bench
