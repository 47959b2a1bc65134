// Fault rules observed from the client side, as configured: `mbscope simulate --faults FILE` with a
// fixed seed, a drop rule restricted to an address range and a delay rule with a distribution,
// polled over udp:// (each answer on its own clock, so one request's delay never shifts another's)
// by a client here that sends a few hundred requests and times each answer.
//
// What is checked, never how fast the machine is:
// - drops: only requests touching the rule's addresses are dropped, their proportion within
//   binomial 4-sigma bounds, and the simulator counted the same drops the client missed;
// - delays: no answer comes before the distribution's minimum, and at the distribution's
//   quantiles the share of answers already in is not above the configured CDF plus 4 sigma (the
//   client can only see answers later than the simulator's delay, never earlier); above, a loose
//   bound with generous slack;
// - the seed: the same file gives the same requests dropped, another seed others.
#include "simcli.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QEventLoop>
#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtNetwork/QNetworkDatagram>
#include <QtNetwork/QUdpSocket>
#include <QtTest/QtTest>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace mbscope::simtest;

namespace {

constexpr int kRequests = 500;
constexpr int kPaceMs = 2;         // one request every 2 ms
constexpr int kQuietMs = 2000;     // after the last request: no answer for this long means done
constexpr double kSlackMs = 50.0;  // the loose upper bound: scheduling on a busy machine

// The conformance profile's holding register a is 1000 + 3a.
quint16 holding(int address)
{
    return quint16(1000 + 3 * address);
}

// Even requests read inside the drop rule's addresses (0-49), odd ones outside (50-99).
int addressOf(int index)
{
    return index % 2 == 0 ? (index / 2) % 48 : 50 + (index / 2) % 40;
}

struct Observation {
    QList<bool> answered;  // by request index
    QList<double> latencyMs; // of the answered ones
    int simulatorRequests = -1; // "interrupted: N requests" in the simulator's summary
    int simulatorDropped = -1;  // "N dropped by fault" in it
    QString error;

    [[nodiscard]] int missing() const { return int(answered.count(false)); }
    // Every request reached the simulator and every answer it sent came back: loopback UDP
    // loses datagrams only when a receiver on a very busy machine falls behind.
    [[nodiscard]] bool lossless() const
    {
        return simulatorRequests == int(answered.size()) && simulatorDropped == missing();
    }
};

Observation observe(const QByteArray &faults)
{
    Observation o;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("faults.json"));
    QFile file(path);
    if (!dir.isValid() || !file.open(QIODevice::WriteOnly) || file.write(faults) != faults.size()) {
        o.error = QStringLiteral("cannot write ") + path;
        return o;
    }
    file.close();
    SimCli sim;
    if (!sim.start({QStringLiteral("--profile"), QStringLiteral("conformance"), QStringLiteral("--listen"),
                    QStringLiteral("udp://127.0.0.1:0"), QStringLiteral("--faults"), path, QStringLiteral("--quiet")},
                   1, &o.error))
        return o;
    const quint16 port = sim.port(0);

    QUdpSocket socket;
    if (!socket.bind(QHostAddress::LocalHost, 0)) {
        o.error = socket.errorString();
        return o;
    }
    QList<qint64> sentNs(kRequests, -1);
    o.answered = QList<bool>(kRequests, false);
    QElapsedTimer clock;
    clock.start();
    qint64 lastEventNs = 0;
    QObject::connect(&socket, &QUdpSocket::readyRead, &socket, [&] {
        while (socket.hasPendingDatagrams()) {
            const QByteArray answer = socket.receiveDatagram().data();
            const qint64 now = clock.nsecsElapsed();
            lastEventNs = now;
            const int tid = answer.size() >= 2 ? (quint8(answer[0]) << 8 | quint8(answer[1])) : -1;
            if (tid < 0 || tid >= kRequests || sentNs[tid] < 0 || o.answered[tid]) {
                o.error = QStringLiteral("unexpected answer %1").arg(QString::fromLatin1(answer.toHex(' ')));
                continue;
            }
            QByteArray expected = QByteArray::fromHex("000000000007010304"); // MBAP, unit 1, 03, 4 bytes
            expected[0] = char(tid >> 8);
            expected[1] = char(tid & 0xFF);
            for (int k = 0; k < 2; ++k) {
                expected += char(holding(addressOf(tid) + k) >> 8);
                expected += char(holding(addressOf(tid) + k) & 0xFF);
            }
            if (answer != expected) {
                o.error = QStringLiteral("request %1: answer %2, expected %3")
                              .arg(tid)
                              .arg(QString::fromLatin1(answer.toHex(' ')), QString::fromLatin1(expected.toHex(' ')));
                continue;
            }
            o.answered[tid] = true;
            o.latencyMs.append(double(now - sentNs[tid]) / 1e6);
        }
    });
    int next = 0;
    QTimer pace;
    pace.setTimerType(Qt::PreciseTimer);
    QObject::connect(&pace, &QTimer::timeout, &socket, [&] {
        const int address = addressOf(next);
        const char request[] = {char(next >> 8), char(next & 0xFF), 0, 0, 0, 6, 1, 3, 0, char(address), 0, 2};
        sentNs[next] = clock.nsecsElapsed();
        lastEventNs = sentNs[next];
        socket.writeDatagram(request, sizeof request, QHostAddress::LocalHost, port);
        if (++next == kRequests)
            pace.stop();
    });
    pace.start(kPaceMs);
    // A real event loop (QTest::qWaitFor sleeps 10 ms between turns, which would pace the
    // requests and stamp the answers in 10 ms steps). Bounded: two minutes at most.
    QEventLoop loop;
    QTimer watch;
    QObject::connect(&watch, &QTimer::timeout, &loop, [&] {
        if (next == kRequests && clock.nsecsElapsed() - lastEventNs > qint64(kQuietMs) * 1'000'000)
            loop.quit();
    });
    watch.start(50);
    QTimer::singleShot(120000, &loop, &QEventLoop::quit);
    loop.exec();
    const bool done = next == kRequests && clock.nsecsElapsed() - lastEventNs > qint64(kQuietMs) * 1'000'000;
    if (!done && o.error.isEmpty())
        o.error = QStringLiteral("the client did not finish: %1 of %2 requests sent").arg(next).arg(kRequests);
    if (sim.stop() != 0 && o.error.isEmpty())
        o.error = QStringLiteral("simulate did not stop cleanly: ") + QString::fromUtf8(sim.errors());
    static const QRegularExpression summaryRe(QStringLiteral("interrupted: (\\d+) requests.* (\\d+) dropped by fault"));
    const QRegularExpressionMatch m = summaryRe.match(QString::fromUtf8(sim.output()));
    if (m.hasMatch()) {
        o.simulatorRequests = m.captured(1).toInt();
        o.simulatorDropped = m.captured(2).toInt();
    } else if (o.error.isEmpty()) {
        o.error = QStringLiteral("no summary in: ") + QString::fromUtf8(sim.output());
    }
    return o;
}

// observe(), again (at most three times in all) when a datagram was lost on the way: what is
// compared must be what the fault rules did, not what a busy machine's socket buffers did.
Observation observeLossless(const QByteArray &faults)
{
    Observation o;
    for (int attempt = 1; attempt <= 3; ++attempt) {
        o = observe(faults);
        if (!o.error.isEmpty() || o.lossless())
            break;
        qInfo("attempt %d: %d requests reached the simulator, %d of %d answers missing, %d dropped by fault: again",
              attempt, o.simulatorRequests, o.missing(), kRequests, o.simulatorDropped);
    }
    return o;
}

QByteArray faultsJson(int seed, double dropProbability, const QByteArray &delay)
{
    return QByteArrayLiteral("{\"seed\": ") + QByteArray::number(seed) + QByteArrayLiteral(", \"rules\": [\n")
           + QByteArrayLiteral("  {\"kind\": \"drop\", \"name\": \"lossy link\", \"addresses\": [0, 49], \"probability\": ")
           + QByteArray::number(dropProbability) + QByteArrayLiteral("},\n")
           + QByteArrayLiteral("  {\"kind\": \"delay\", \"name\": \"slow device\", \"delay\": ") + delay
           + QByteArrayLiteral("}\n]}\n");
}

double normalCdf(double z)
{
    return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

// The x at which cdf reaches p (bisection over 0-10 s).
double quantile(const std::function<double(double)> &cdf, double p)
{
    double lo = 0.0;
    double hi = 10000.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = (lo + hi) / 2;
        (cdf(mid) < p ? lo : hi) = mid;
    }
    return hi;
}

using Cdf = std::function<double(double)>;

} // namespace

Q_DECLARE_METATYPE(Cdf)

class tst_SimulateFaults : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void dropsAndDelays_data();
    void dropsAndDelays();
    void sameSeedSameDrops();
};

void tst_SimulateFaults::dropsAndDelays_data()
{
    QTest::addColumn<QByteArray>("delay");
    QTest::addColumn<Cdf>("cdf"); // the configured distribution, clamps included
    QTest::addColumn<double>("minimumMs");
    QTest::addColumn<double>("drop");

    QTest::newRow("uniform 20-60 ms, drop 0.2") << QByteArray(R"({"distribution": "uniform", "minMs": 20, "maxMs": 60})")
                                                << Cdf([](double x) { return std::clamp((x - 20.0) / 40.0, 0.0, 1.0); })
                                                << 20.0 << 0.2;
    QTest::newRow("normal 30 +- 8 ms within 12-70, drop 0.05")
        << QByteArray(R"({"distribution": "normal", "meanMs": 30, "stddevMs": 8, "minMs": 12, "maxMs": 70})")
        << Cdf([](double x) { return x < 12.0 ? 0.0 : (x >= 70.0 ? 1.0 : normalCdf((x - 30.0) / 8.0)); }) << 12.0 << 0.05;
    QTest::newRow("exponential mean 15 ms within 5-120, drop 0.5")
        << QByteArray(R"({"distribution": "exponential", "meanMs": 15, "minMs": 5, "maxMs": 120})")
        << Cdf([](double x) { return x < 5.0 ? 0.0 : (x >= 120.0 ? 1.0 : 1.0 - std::exp(-x / 15.0)); }) << 5.0 << 0.5;
}

void tst_SimulateFaults::dropsAndDelays()
{
    QFETCH(QByteArray, delay);
    QFETCH(Cdf, cdf);
    QFETCH(double, minimumMs);
    QFETCH(double, drop);
    const Observation o = observeLossless(faultsJson(4242, drop, delay));
    QVERIFY2(o.error.isEmpty(), qPrintable(o.error));
    QCOMPARE(o.simulatorRequests, kRequests);

    // Drops: only inside the rule's addresses, in the configured proportion.
    int inside = 0;
    int droppedInside = 0;
    int droppedOutside = 0;
    for (int i = 0; i < kRequests; ++i) {
        if (i % 2 == 0) {
            ++inside;
            droppedInside += o.answered[i] ? 0 : 1;
        } else {
            droppedOutside += o.answered[i] ? 0 : 1;
        }
    }
    QCOMPARE(droppedOutside, 0);
    const double expected = inside * drop;
    const double sigma = std::sqrt(inside * drop * (1 - drop));
    QVERIFY2(std::abs(droppedInside - expected) <= 4 * sigma,
             qPrintable(QStringLiteral("%1 of %2 dropped, expected %3 +- %4 (4 sigma)").arg(droppedInside).arg(inside).arg(expected).arg(4 * sigma)));
    QCOMPARE(o.simulatorDropped, droppedInside);

    // Delays: never before the minimum; at each quantile, no more answers in than the
    // distribution allows (4 sigma); loosely, not much later than it says.
    QList<double> latency = o.latencyMs;
    std::sort(latency.begin(), latency.end());
    const int m = int(latency.size());
    QCOMPARE(m, kRequests - droppedInside);
    QVERIFY2(latency.first() >= minimumMs, qPrintable(QStringLiteral("fastest answer %1 ms, minimum %2 ms").arg(latency.first()).arg(minimumMs)));
    const auto shareBelow = [&](double x) {
        return double(std::upper_bound(latency.begin(), latency.end(), x) - latency.begin()) / m;
    };
    for (double p : {0.1, 0.25, 0.5, 0.75, 0.9}) {
        const double x = quantile(cdf, p);
        const double bound = 4 * std::sqrt(p * (1 - p) / m) + 1.0 / m;
        QVERIFY2(shareBelow(x) <= cdf(x) + bound,
                 qPrintable(QStringLiteral("%1 of the answers within %2 ms, the distribution allows %3 + %4")
                                .arg(shareBelow(x)).arg(x).arg(cdf(x)).arg(bound)));
        QVERIFY2(shareBelow(x + kSlackMs) >= cdf(x) - bound,
                 qPrintable(QStringLiteral("%1 of the answers within %2 + %3 ms, the distribution says %4 - %5")
                                .arg(shareBelow(x + kSlackMs)).arg(x).arg(kSlackMs).arg(cdf(x)).arg(bound)));
    }
    double sum = 0;
    for (double l : latency)
        sum += l;
    qInfo("%s: %d of %d dropped inside the rule's addresses, 0 of %d outside; latency ms min %.2f median %.2f mean %.2f max %.2f",
          QTest::currentDataTag(), droppedInside, inside, kRequests - inside, latency.first(), latency.at(m / 2), sum / m,
          latency.last());
}

// A seed makes faults reproducible: the same file drops the same requests; another seed, others.
void tst_SimulateFaults::sameSeedSameDrops()
{
    const QByteArray delay = R"({"distribution": "uniform", "minMs": 1, "maxMs": 5})";
    const Observation first = observeLossless(faultsJson(7, 0.3, delay));
    QVERIFY2(first.error.isEmpty(), qPrintable(first.error));
    const Observation again = observeLossless(faultsJson(7, 0.3, delay));
    QVERIFY2(again.error.isEmpty(), qPrintable(again.error));
    const Observation other = observeLossless(faultsJson(8, 0.3, delay));
    QVERIFY2(other.error.isEmpty(), qPrintable(other.error));
    QVERIFY(first.lossless() && again.lossless() && other.lossless());
    QVERIFY(first.missing() > 0);
    QCOMPARE(again.answered, first.answered);
    QVERIFY(other.answered != first.answered);
}

QTEST_GUILESS_MAIN(tst_SimulateFaults)
#include "tst_simulate_faults.moc"
