// Soak of the window (issue 31): `mbscope --screenshot-poll 100000000 --poll-interval 0`, the
// window offscreen polling its first-run simulator back to back, as anyone can repeat it, for
// --minutes (MBSCOPE_QUIT_AFTER_MS closes it then, as a quit does). Its resident memory
// (VmRSS of /proc/PID/status) is read every --every seconds, beside the bytes its recording
// journals hold; at the end the journals are read back to count the transactions. Printed: the
// samples, then resident memory at the end of the first minute and of the last, and the
// transactions per second. With it, how fast the window answers meanwhile: every --probe-ms
// (default 1000; 0: not at all) it opens a menu or moves its traffic list to a random row, and
// says, as it quits, how long each took to paint (ResponsivenessProbe). Figures only, never
// asserted.
//
// Usage: bench_windowsoak [--minutes M] [--every S] [--probe-ms MS]   (ctest runs --minutes 0.25 --every 2)
#include "traffic/trafficjournal.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QDir>
#include <QtCore/QDirIterator>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtCore/QThread>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

// VmRSS of a process, in KiB; -1 when it is gone.
qint64 residentKiB(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/status").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : f.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    }
    return -1;
}

QStringList journals(const QString &root)
{
    QStringList paths;
    for (QDirIterator it(root, {QStringLiteral("*.mbscope.journal")}, QDir::Files, QDirIterator::Subdirectories); it.hasNext();)
        paths << it.next();
    return paths;
}

qint64 journalBytes(const QString &root)
{
    qint64 bytes = 0;
    for (const QString &path : journals(root))
        bytes += QFileInfo(path).size();
    return bytes;
}

struct Sample {
    double seconds = 0;
    qint64 rssKiB = 0;
    qint64 journalBytes = 0;
};

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    double minutes = 30;
    double every = 10;
    int probeMs = 1000;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args.at(i) == QLatin1String("--minutes") && i + 1 < args.size())
            minutes = args.at(++i).toDouble();
        else if (args.at(i) == QLatin1String("--every") && i + 1 < args.size())
            every = args.at(++i).toDouble();
        else if (args.at(i) == QLatin1String("--probe-ms") && i + 1 < args.size())
            probeMs = args.at(++i).toInt();
        else {
            std::fprintf(stderr, "usage: bench_windowsoak [--minutes M] [--every SECONDS] [--probe-ms MS]\n");
            return 2;
        }
    }
    if (minutes <= 0 || every <= 0) {
        std::fprintf(stderr, "bench_windowsoak: --minutes and --every must be above 0\n");
        return 2;
    }

    QTemporaryDir home;
    QProcess window;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    for (const char *name : {"XDG_DATA_HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME", "XDG_RUNTIME_DIR"}) {
        const QString dir = home.filePath(QLatin1String(name));
        QDir().mkpath(dir);
        QFile::setPermissions(dir, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        env.insert(QLatin1String(name), dir);
    }
    const qint64 runMs = qint64(minutes * 60'000);
    env.insert(QStringLiteral("MBSCOPE_QUIT_AFTER_MS"), QString::number(runMs));
    // Every probeMs the window opens a menu or moves its traffic list to a random row, timing
    // each to its paint; it prints the figures ("responsiveness: menus: ...") as it quits.
    if (probeMs > 0)
        env.insert(QStringLiteral("MBSCOPE_RESPONSIVENESS_MS"), QString::number(probeMs));
    window.setProcessEnvironment(env);
    window.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    const QStringList windowArgs{QStringLiteral("--screenshot"), home.filePath(QStringLiteral("soak.png")),
                                 QStringLiteral("--screenshot-poll"), QStringLiteral("100000000"),
                                 QStringLiteral("--poll-interval"), QStringLiteral("0")};
    std::printf("window soak: mbscope %s, offscreen, for %.2f min; resident memory every %.0f s\n",
                qPrintable(windowArgs.join(QLatin1Char(' '))), minutes, every);
    QElapsedTimer clock;
    clock.start();
    window.start(QStringLiteral(MBSCOPE_EXECUTABLE), windowArgs);
    if (!window.waitForStarted(10000)) {
        std::fprintf(stderr, "bench_windowsoak: cannot start %s: %s\n", MBSCOPE_EXECUTABLE, qPrintable(window.errorString()));
        return 1;
    }
    const qint64 pid = window.processId();
    const QString data = home.filePath(QStringLiteral("XDG_DATA_HOME"));
    std::vector<Sample> samples;
    std::printf("%10s %12s %14s\n", "seconds", "RSS MiB", "journal MiB");
    for (int k = 1;; ++k) {
        const qint64 dueMs = qint64(k * every * 1000);
        // No sample in the last second: the window is closing then, its memory going.
        if (dueMs > runMs - 1000)
            break;
        if (window.waitForFinished(int(std::max<qint64>(1, dueMs - clock.elapsed()))))
            break;
        Sample s{double(clock.elapsed()) / 1000.0, residentKiB(pid), journalBytes(data)};
        if (s.rssKiB < 0)
            break;
        samples.push_back(s);
        std::printf("%10.1f %12.1f %14.1f\n", s.seconds, double(s.rssKiB) / 1024.0, double(s.journalBytes) / 1048576.0);
        std::fflush(stdout);
    }
    window.waitForFinished(int(runMs - clock.elapsed()) + 60000);
    if (window.exitStatus() != QProcess::NormalExit || window.exitCode() != 0) {
        std::fprintf(stderr, "bench_windowsoak: the window ended with status %d\n", window.exitCode());
        return 1;
    }
    if (samples.empty()) {
        std::fprintf(stderr, "bench_windowsoak: no sample taken (a run shorter than --every?)\n");
        return 1;
    }
    quint64 frames = 0;
    for (const QString &path : journals(data))
        frames += mbscope::TrafficJournalReader::read(path, {}).frames;
    const double seconds = double(runMs) / 1000.0;
    // The first minute's last sample and the last one; a run under two minutes: first and last.
    const Sample *first = &samples.front();
    for (const Sample &s : samples) {
        if (s.seconds <= 60.0 + every / 2)
            first = &s;
    }
    const Sample &last = samples.back();
    std::printf("\nresident memory at %.0f s: %.1f MiB; at %.0f s: %.1f MiB (%+.1f MiB); peak %.1f MiB\n", first->seconds,
                double(first->rssKiB) / 1024.0, last.seconds, double(last.rssKiB) / 1024.0,
                double(last.rssKiB - first->rssKiB) / 1024.0,
                double(std::max_element(samples.begin(), samples.end(), [](const Sample &a, const Sample &b) {
                           return a.rssKiB < b.rssKiB;
                       })->rssKiB) / 1024.0);
    std::printf("transactions: about %llu in %.0f s (%llu frames in the recording journals), %.0f per second\n",
                static_cast<unsigned long long>(frames / 2), seconds, static_cast<unsigned long long>(frames),
                double(frames / 2) / seconds);
    if (last.seconds > first->seconds && frames > 0) {
        const double transactionsBetween = double(frames / 2) * double(last.journalBytes - first->journalBytes) / double(last.journalBytes);
        if (transactionsBetween > 0)
            std::printf("growth between them: %.3f KiB per 1,000 transactions\n",
                        double(last.rssKiB - first->rssKiB) / transactionsBetween * 1000.0);
    }
    return 0;
}
