#include "tapserialbench.h"

#include "benchprocess.h"
#include "pacedline.h"
#include "peerprocess.h"

#include "protocol/rtuframer.h"
#include "transport/linkurl.h"
#include "transport/seriallink.h"

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>

#include <algorithm>
#include <cstdio>

namespace mbscope::bench {

namespace {

// Read Holding Registers of 10 registers in RTU: unit, function, address (2), quantity (2), CRC (2);
// the answer: unit, function, byte count, 20 data bytes, CRC (2).
constexpr int kRequestCharacters = 8;
constexpr int kAnswerCharacters = 25;

double percentileUs(std::vector<qint64> v, double p)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const size_t rank = std::min(v.size() - 1, size_t(p / 100.0 * double(v.size())));
    return double(v[rank]) / 1000.0;
}

struct Run {
    bool started = false;
    ClientFigures figures;
    testpeers::PacedLine::Timing timing;
};

// The simulator on deviceEnd, the tap on masterEnd, the masters through the tap.
Run runThrough(const QString &masterEnd, const QString &deviceEnd, int baud, const QStringList &slave, testpeers::PacedLine *line,
               const SerialBenchOptions &o)
{
    Run run;
    const QString options = QStringLiteral("?baud=%1").arg(baud);
    BenchServer sim;
    sim.name = QStringLiteral("simulate (rtu)");
    if (!sim.start(o.mbscope,
                   QStringList{QStringLiteral("simulate"), QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                    QStringLiteral("rtu://") + deviceEnd + options, QStringLiteral("--quiet")} + slave,
                   QRegularExpression(QStringLiteral("listening rtu://(\\S*)")), o.pin, o.serverCpu))
        return run;
    BenchServer tap;
    tap.name = QStringLiteral("tap (rtu target)");
    if (!tap.start(o.mbscope,
                   {QStringLiteral("tap"), QStringLiteral("--listen"), QStringLiteral("tcp://127.0.0.1:0"), QStringLiteral("--target"),
                    QStringLiteral("rtu://") + masterEnd + options, QStringLiteral("--quiet")},
                   QRegularExpression(QStringLiteral("listening tcp://127\\.0\\.0\\.1:(\\d+)")), o.pin, o.serverCpu)) {
        sim.stop();
        return run;
    }
    run.started = true;
    (void)runManyClients(tap.port, 1, {QStringLiteral("--requests"), QStringLiteral("5")}, o.pin, o.clientCpu); // warm-up
    if (line)
        (void)line->take();
    run.figures = runManyClients(tap.port, o.masters, {QStringLiteral("--requests"), QString::number(o.requestsPerMaster)}, o.pin,
                                 o.clientCpu);
    if (line)
        run.timing = line->take();
    const QByteArray tapSaid = tap.stop();
    const QByteArray simSaid = sim.stop();
    if (!run.figures.ok || run.figures.errors > 0) // what the tap and the device made of it
        std::fprintf(stderr, "bench_tap: the tap said:\n%s\nthe simulator said:\n%s\n", tapSaid.right(3000).constData(),
                     simSaid.right(3000).constData());
    return run;
}

} // namespace

int runSerialSection(const SerialBenchOptions &o)
{
    std::printf("\n== Serial target: mbscope tap --listen tcp://127.0.0.1:0 --target rtu://PTY?baud=B in front of mbscope simulate "
                "--profile conformance --listen rtu://PTY?baud=B (8E1, the URL's default); %d masters x %d requests through the tap\n",
                o.masters, o.requestsPerMaster);
    bool clean = true;
    for (const int baud : o.bauds) {
        const LinkUrl::Result url = LinkUrl::parse(QStringLiteral("rtu:///dev/null?baud=%1").arg(baud));
        if (!url.url) {
            std::fprintf(stderr, "bench_tap: baud %d: %s\n", baud, qPrintable(url.error));
            return 2;
        }
        const qint64 characterNs = SerialLink::lineCharacterNs(url.url->serial);
        const qint64 t35Ns = RtuFramer::t35Ns(baud);
        const qint64 charactersNs = qint64(kRequestCharacters + kAnswerCharacters) * characterNs;
        const qint64 periodNs = charactersNs + 2 * t35Ns;
        const double limit = 1e9 / double(periodNs);
        const SerialSettings &line = url.url->serial;
        const int bits = 1 + line.dataBits + (line.parity == 'N' ? 0 : 1) + line.stopBits;
        std::printf("\nbaud %d: a character is %.1f us on the line (%d bits), t3.5 is %.0f us; request %d + answer %d characters = "
                    "%.0f us, + 2 x t3.5 = %.0f us a transaction: the line's limit is %.1f transactions/s (%.1f without the gaps)\n",
                    baud, double(characterNs) / 1000.0, bits, double(t35Ns) / 1000.0, kRequestCharacters, kAnswerCharacters,
                    double(charactersNs) / 1000.0, double(periodNs) / 1000.0, limit, 1e9 / double(charactersNs));

        // A conforming RTU slave takes a request as ended after t3.5 of silence, so its answer
        // starts t3.5 after the request (the simulator frames by length and answers at once: a
        // fault rule delays it by t3.5).
        QTemporaryDir dir;
        const QString faults = dir.filePath(QStringLiteral("t35.json"));
        QFile file(faults);
        if (!file.open(QIODevice::WriteOnly)
            || file.write(QStringLiteral(R"({"rules": [{"kind": "delay", "name": "t3.5", "delay": %1}]})")
                              .arg(double(t35Ns) / 1e6, 0, 'f', 3)
                              .toUtf8())
                   < 0)
            return 2;
        file.close();
        struct Slave {
            const char *what;
            QStringList options;
        };
        const Slave slaves[] = {
            {"slave answering t3.5 after the request (as a conforming RTU slave sees its end)", {QStringLiteral("--faults"), faults}},
            {"slave answering at once (the simulator frames by length)", {}},
        };
        for (const Slave &slave : slaves) {
            testpeers::PacedLine paced;
            QString error;
            if (!paced.start(characterNs, &error)) {
                std::fprintf(stderr, "bench_tap: %s\n", qPrintable(error));
                return 2;
            }
            const Run p = runThrough(paced.masterEnd(), paced.deviceEnd(), baud, slave.options, &paced, o);
            paced.stop();
            if (!p.started)
                return 2;
            if (!p.figures.ok || p.figures.errors > 0) {
                std::fprintf(stderr, "bench_tap: the masters on the paced line said: %s\n", qPrintable(p.figures.said));
                clean = false;
            }
            const auto &gaps = p.timing.masterGapsNs;
            const qint64 shortest = gaps.empty() ? 0 : *std::min_element(gaps.begin(), gaps.end());
            std::printf("  paced line, %s: %.1f transactions/s = %.1f %% of the limit; p50 %.0f us, p99 %.0f us at the masters\n"
                        "    silence the tap left between an answer and its next request: min %.0f us, p50 %.0f us over %zu (t3.5 "
                        "%.0f us: %s); the slave's turnaround p50 %.0f us\n",
                        slave.what, p.figures.tps, 100.0 * p.figures.tps / limit, p.figures.p50, p.figures.p99,
                        double(shortest) / 1000.0, percentileUs(gaps, 50), gaps.size(), double(t35Ns) / 1000.0,
                        !gaps.empty() && shortest >= t35Ns ? "kept" : "NOT kept", percentileUs(p.timing.turnaroundsNs, 50));
            // Where a transaction's time went, at the medians: the line's characters, the slave's
            // turnaround, the tap's silence; the rest is the relay's and the masters' own time.
            const double periodUs = p.figures.tps > 0 ? 1e6 / p.figures.tps : 0;
            const double turnaroundUs = percentileUs(p.timing.turnaroundsNs, 50);
            const double gapUs = percentileUs(gaps, 50);
            std::printf("    a transaction took %.0f us: %.0f on the line, %.0f the slave's turnaround, %.0f the tap's silence (%.0f beyond "
                        "t3.5: %.1f %% of the limit's time), %.0f the rest\n",
                        periodUs, double(charactersNs) / 1000.0, turnaroundUs, gapUs, gapUs - double(t35Ns) / 1000.0,
                        100.0 * (gapUs - double(t35Ns) / 1000.0) / (double(periodNs) / 1000.0),
                        periodUs - double(charactersNs) / 1000.0 - turnaroundUs - gapUs);
        }

        QString why;
        if (!testpeers::socatAvailable(&why)) {
            std::printf("  socat pty pair: skipped (%s)\n", qPrintable(why));
            continue;
        }
        testpeers::PtyPair pair;
        if (!pair.start()) {
            std::fprintf(stderr, "bench_tap: %s\n", qPrintable(pair.error()));
            return 2;
        }
        const Run s = runThrough(pair.ourEnd(), pair.peerEnd(), baud, {}, nullptr, o);
        if (!s.started)
            return 2;
        if (!s.figures.ok || s.figures.errors > 0) {
            std::fprintf(stderr, "bench_tap: the masters on the socat pty pair said: %s\n", qPrintable(s.figures.said));
            clean = false;
        }
        std::printf("  socat pty pair (bytes pass at once: a pty has no baud rate, so no line time): %.1f transactions/s, %.1f x the "
                    "line's limit; p50 %.0f us, p99 %.0f us: the tap's own serial path when the line takes no time (it still keeps t3.5 "
                    "before each request)\n",
                    s.figures.tps, s.figures.tps / limit, s.figures.p50, s.figures.p99);
    }
    return clean ? 0 : 1;
}

} // namespace mbscope::bench
