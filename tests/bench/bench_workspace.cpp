// The Watches tab under load: W watches x R holding registers, each polled every I ms, against
// the simulator (its registers all moving, so every poll changes every value). Two runs, same
// watches, same links: the baseline is the WatchRunner alone (samples counted, nothing shown);
// then the window's WatchWorkspace, shown (offscreen), its tables updated as samples come.
// Printed for each: polls per second, the GUI thread's longest stall (a 5 ms timer's longest
// late tick: goal < 50 ms), CPU use (user + system over wall time, all threads; 100% = one
// core), and resident memory at the end and its growth over the run. Nothing is asserted.
// With --csv the window logs every poll to CSV (a file per watch, in a temporary folder), as
// "Log values to CSV" does: where the rows are written shows in the GUI thread's stall.
// With --soak-polls N (720000: an hour of 20 watches at 100 ms) the same watches are then polled
// at interval 0 until N polls have ended, the runner alone (baseline) and the window (logging as
// --csv says): resident memory at the start, every 10 %, at the end and its peak, side by side.
//
//   build/tests/bench/bench_workspace [--seconds 30] [--watches 20] [--registers 125]
//                                     [--interval 100] [--links 4] [--csv] [--soak-polls 720000]
#include "fleet/watchrunner.h"
#include "profile/profileloader.h"
#include "sim/simulatorhost.h"
#include "watch/watchwindow.h"
#include "watch/watchworkspace.h"

#include <QtCore/QCommandLineParser>
#include <QtCore/QElapsedTimer>
#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtWidgets/QApplication>

#include <sys/resource.h>

#include <cstdio>
#include <functional>

using namespace mbscope;

namespace {

struct Options {
    int seconds = 10;
    int watches = 20;
    int registers = 125;
    int intervalMs = 100;
    int links = 4;
    bool csv = false;
    quint64 soakPolls = 0;
};

double cpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

// VmRSS from /proc/self/status, in KiB.
qint64 residentKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').constFirst().toLongLong();
    }
    return -1;
}

struct Figures {
    double pollsPerSecond = 0;
    double longestStallMs = 0;
    double cpuPercent = 0;
    qint64 rssEndKiB = 0;
    qint64 rssGrowthKiB = 0;
    quint64 failures = 0;
};

// Runs the event loop for seconds, measuring the GUI thread's stalls, CPU and memory; polls()
// tells how many polls have ended so far.
Figures measure(int seconds, const std::function<quint64()> &polls, const std::function<quint64()> &failures)
{
    Figures f;
    QElapsedTimer wall;
    QElapsedTimer tick;
    qint64 longestNs = 0;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    probe.setInterval(5);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 ns = tick.nsecsElapsed();
        tick.restart();
        longestNs = qMax(longestNs, ns);
    });
    // The first second warms up (links open, first answers): measured from then on.
    QTimer::singleShot(1000, [&] {
        wall.start();
        tick.start();
        probe.start();
    });
    QEventLoop loop;
    QTimer::singleShot(1000, [&] {
        const quint64 polls0 = polls();
        const double cpu0 = cpuSeconds();
        const qint64 rss0 = residentKiB();
        QTimer::singleShot(seconds * 1000, [&, polls0, cpu0, rss0] {
            const double elapsed = double(wall.nsecsElapsed()) / 1e9;
            f.pollsPerSecond = double(polls() - polls0) / elapsed;
            f.cpuPercent = 100 * (cpuSeconds() - cpu0) / elapsed;
            f.rssEndKiB = residentKiB();
            f.rssGrowthKiB = f.rssEndKiB - rss0;
            f.failures = failures();
            loop.quit();
        });
    });
    loop.exec();
    f.longestStallMs = qMax(0.0, double(longestNs) / 1e6 - 5);
    return f;
}

SessionWatches makeWatches(const Options &o, const QList<LinkUrl> &urls)
{
    SessionWatches session;
    for (int i = 0; i < o.watches; ++i) {
        WatchDefinition watch;
        watch.name = QStringLiteral("block %1").arg(i + 1);
        watch.target = urls.at(i % urls.size()).toString();
        watch.function = 3;
        watch.address = quint16((i * o.registers) % 8000);
        watch.quantity = quint16(o.registers);
        watch.intervalMs = o.intervalMs;
        // A few named, scaled points and a rule, as a real watch has; the rest unnamed u16.
        for (int p = 0; p < 10 && p < o.registers; ++p) {
            WatchPoint point;
            point.address = quint16(watch.address + p * 2);
            point.name = QStringLiteral("value %1").arg(p);
            point.scale = 0.1;
            point.unit = QStringLiteral("V");
            watch.points.append(point);
        }
        WatchRule rule;
        rule.point = QStringLiteral("value 0");
        rule.condition = WatchRule::Condition::Above;
        rule.high = 3000;
        watch.rules.append(rule);
        session.watches.append(watch);
    }
    return session;
}

// Runs the event loop until polls() reaches total, sampling resident memory at the start and at
// every tenth of the way; the samples in KiB (11 of them, then the most seen at any 20 ms tick)
// and the seconds it took.
QList<qint64> soak(quint64 total, const std::function<quint64()> &polls, double *seconds)
{
    QList<qint64> rss{residentKiB()};
    qint64 peak = rss.first();
    const quint64 start = polls();
    QElapsedTimer wall;
    wall.start();
    QEventLoop loop;
    QTimer probe;
    probe.setInterval(20);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const quint64 done = polls() - start;
        peak = qMax(peak, residentKiB());
        while (rss.size() < 11 && done >= total * quint64(rss.size()) / 10)
            rss.append(residentKiB());
        if (rss.size() == 11)
            loop.quit();
    });
    probe.start();
    loop.exec();
    *seconds = double(wall.nsecsElapsed()) / 1e9;
    rss.append(qMax(peak, rss.constLast()));
    return rss;
}

void print(const char *name, const Figures &f)
{
    std::printf("%-34s %10.0f %12.1f %8.1f %12.1f %12.1f %9llu\n", name, f.pollsPerSecond, f.longestStallMs, f.cpuPercent,
                double(f.rssEndKiB) / 1024, double(f.rssGrowthKiB) / 1024, static_cast<unsigned long long>(f.failures));
}

} // namespace

int main(int argc, char *argv[])
{
    qputenv("QT_QPA_PLATFORM", qgetenv("QT_QPA_PLATFORM").isEmpty() ? QByteArray("offscreen") : qgetenv("QT_QPA_PLATFORM"));
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addHelpOption();
    const QCommandLineOption secondsOption(QStringLiteral("seconds"), QStringLiteral("Measured seconds per run."), QStringLiteral("N"), QStringLiteral("10"));
    const QCommandLineOption watchesOption(QStringLiteral("watches"), QStringLiteral("Watches."), QStringLiteral("N"), QStringLiteral("20"));
    const QCommandLineOption registersOption(QStringLiteral("registers"), QStringLiteral("Registers per watch (1-125)."), QStringLiteral("N"), QStringLiteral("125"));
    const QCommandLineOption intervalOption(QStringLiteral("interval"), QStringLiteral("Poll interval in ms."), QStringLiteral("MS"), QStringLiteral("100"));
    const QCommandLineOption linksOption(QStringLiteral("links"), QStringLiteral("Simulator endpoints the watches share."), QStringLiteral("N"), QStringLiteral("4"));
    const QCommandLineOption csvOption(QStringLiteral("csv"), QStringLiteral("The window logs every poll to CSV (a temporary folder)."));
    const QCommandLineOption soakOption(QStringLiteral("soak-polls"),
                                        QStringLiteral("Then poll at interval 0 until N polls, memory every 10 % (720000: an hour at 100 ms)."),
                                        QStringLiteral("N"), QStringLiteral("0"));
    parser.addOptions({secondsOption, watchesOption, registersOption, intervalOption, linksOption, csvOption, soakOption});
    parser.process(app);
    Options o;
    o.seconds = qMax(1, parser.value(secondsOption).toInt());
    o.watches = qBound(1, parser.value(watchesOption).toInt(), 200);
    o.registers = qBound(1, parser.value(registersOption).toInt(), 125);
    o.intervalMs = qMax(0, parser.value(intervalOption).toInt());
    o.links = qBound(1, parser.value(linksOption).toInt(), 32);
    o.csv = parser.isSet(csvOption);
    o.soakPolls = parser.value(soakOption).toULongLong();

    // 8000 holding registers, every one a random walk stepped every 50 ms.
    const QByteArray profileJson = R"({"name": "bench", "units": [{"id": 1, "tables": {"holding": [
        {"address": 0, "count": 8000, "name": "moving", "value": 1000,
         "generator": {"kind": "randomWalk", "step": 5, "min": 0, "max": 4000, "periodMs": 50}}]}}]})";
    const ProfileLoadResult profile = ProfileLoader::parse(profileJson, QStringLiteral("bench"));
    if (!profile.ok) {
        std::fprintf(stderr, "bench_workspace: %s\n", qPrintable(profile.errorText()));
        return 1;
    }
    SimulatorHost host;
    QString error;
    if (!host.load(profile.profile, &error)) {
        std::fprintf(stderr, "bench_workspace: %s\n", qPrintable(error));
        return 1;
    }
    QList<LinkUrl> urls;
    for (int i = 0; i < o.links; ++i) {
        const std::optional<LinkUrl> url = host.listen(QStringLiteral("tcp://127.0.0.1:0"), &error);
        if (!url) {
            std::fprintf(stderr, "bench_workspace: %s\n", qPrintable(error));
            return 1;
        }
        urls.append(*url);
    }
    host.start();
    SessionWatches watches = makeWatches(o, urls);
    QTemporaryDir csvDir;
    if (o.csv) {
        WatchLogSettings log;
        log.enabled = true;
        log.directory = csvDir.path();
        watches.log = log;
    }

    std::printf("bench_workspace: %d watches x %d registers every %d ms on %d TCP links to the simulator, %d s measured per run%s\n",
                o.watches, o.registers, o.intervalMs, o.links, o.seconds, o.csv ? ", the window logging every poll to CSV" : "");
    std::printf("%-34s %10s %12s %8s %12s %12s %9s\n", "run", "polls/s", "stall ms", "CPU %", "RSS MiB", "RSS +MiB", "failures");

    Figures baseline;
    {
        quint64 polls = 0;
        quint64 failures = 0;
        WatchRunner runner(watches);
        QObject::connect(&runner, &WatchRunner::sampled, [&](const QList<WatchSample> &samples, const QList<WatchCounters> &) {
            for (const WatchSample &s : samples) {
                ++polls;
                failures += s.isOk() ? 0 : 1;
            }
        });
        runner.start();
        baseline = measure(o.seconds, [&] { return polls; }, [&] { return failures; });
        runner.stop();
        QEventLoop settle;
        QTimer::singleShot(300, &settle, &QEventLoop::quit);
        settle.exec();
    }
    print("baseline: WatchRunner alone", baseline);

    Figures shown;
    {
        WatchWorkspace workspace;
        workspace.resize(1400, 900);
        workspace.setTabbed(false);
        workspace.show();
        workspace.setWatches(watches);
        workspace.startAll();
        auto sum = [&workspace](bool failuresOnly) {
            quint64 n = 0;
            for (int i = 0; i < workspace.count(); ++i) {
                const WatchCounters &c = workspace.window(i)->counters();
                n += failuresOnly ? c.polls - c.ok : c.polls;
            }
            return n;
        };
        shown = measure(o.seconds, [&] { return sum(false); }, [&] { return sum(true); });
        workspace.stopAll();
    }
    print("window: WatchWorkspace, tiled", shown);
    std::printf("goal: the GUI thread's longest stall under 50 ms; expected polls/s: %.0f\n",
                o.intervalMs > 0 ? 1000.0 * o.watches / o.intervalMs : 0.0);

    if (o.soakPolls > 0) {
        SessionWatches fast = watches;
        for (WatchDefinition &w : fast.watches)
            w.intervalMs = 0;
        double baselineSeconds = 0;
        QList<qint64> baselineRss;
        {
            quint64 polls = 0;
            WatchRunner runner(fast);
            QObject::connect(&runner, &WatchRunner::sampled, [&](const QList<WatchSample> &samples, const QList<WatchCounters> &) {
                polls += quint64(samples.size());
            });
            runner.start();
            baselineRss = soak(o.soakPolls, [&] { return polls; }, &baselineSeconds);
            runner.stop();
            QEventLoop settle;
            QTimer::singleShot(300, &settle, &QEventLoop::quit);
            settle.exec();
        }
        double windowSeconds = 0;
        QList<qint64> windowRss;
        {
            WatchWorkspace workspace;
            workspace.resize(1400, 900);
            workspace.setTabbed(false);
            workspace.show();
            workspace.setWatches(fast);
            workspace.startAll();
            windowRss = soak(o.soakPolls, [&workspace] {
                quint64 n = 0;
                for (int i = 0; i < workspace.count(); ++i)
                    n += workspace.window(i)->counters().polls;
                return n;
            }, &windowSeconds);
            workspace.stopAll();
        }
        std::printf("\nsoak: %llu polls at interval 0 (%.1f h of %d watches at %d ms): resident memory, MiB\n",
                    static_cast<unsigned long long>(o.soakPolls), o.intervalMs > 0 ? double(o.soakPolls) * o.intervalMs / o.watches / 3.6e6 : 0.0,
                    o.watches, o.intervalMs);
        std::printf("%-10s %22s %22s\n", "polls", "baseline: runner alone", o.csv ? "window, logging CSV" : "window");
        for (int i = 0; i < 11; ++i)
            std::printf("%-10llu %22.1f %22.1f\n", static_cast<unsigned long long>(o.soakPolls * quint64(i) / 10),
                        double(baselineRss.value(i)) / 1024, double(windowRss.value(i)) / 1024);
        std::printf("%-10s %22.1f %22.1f\n", "peak", double(baselineRss.value(11)) / 1024, double(windowRss.value(11)) / 1024);
        std::printf("%-10s %22.1f %22.1f\n", "growth", double(baselineRss.value(10) - baselineRss.constFirst()) / 1024,
                    double(windowRss.value(10) - windowRss.constFirst()) / 1024);
        std::printf("%-10s %22.0f %22.0f\n", "polls/s", double(o.soakPolls) / baselineSeconds, double(o.soakPolls) / windowSeconds);
        if (o.csv) {
            qint64 bytes = 0;
            const QFileInfoList files = QDir(csvDir.path()).entryInfoList(QDir::Files);
            for (const QFileInfo &file : files)
                bytes += file.size();
            std::printf("CSV: %lld files, %.1f MiB\n", static_cast<long long>(files.size()), double(bytes) / (1024 * 1024));
        }
    }
    host.stop();
    return 0;
}
