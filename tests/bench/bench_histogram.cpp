// The latency histogram with a million samples: what it costs to count them and to redraw.
//
// Makes N transactions (default one million; latencies log-normal around 5 ms with a tail to
// about a second, a timeout every 1000th), then times, each repeated and reported as the median
// (and the fastest) of the repeats:
//   - adding them to Statistics (automatic bins, every latency kept for exact percentiles), and
//     the latencies to a Histogram of fixed and of logarithmic bins (O(1) each);
//   - what a redraw of the Latency histogram tab costs: rebinning the stored latencies (linear
//     and logarithmic), drawing the bars and markers and QCustomPlot::replot into a 900 x 500
//     pixmap, and the whole panel redraw (rebin, statistics table, plot) the same way;
// beside two baselines in the same run: QCustomPlot drawing the N latencies as raw points (what
// a plot without binning would redraw), and a naive re-binning that scans the bin edges for
// every sample. Each figure is the median of the repeats, in CPU time of the thread and in wall
// time. Figures are printed, never asserted.
//
// Usage: bench_histogram [--samples N] [--repeat R]
#include "common/histogramchart.h"
#include "analysis/latencybinning.h"
#include "analysis/latencyhistogrampanel.h"
#include "analysis/latencyruns.h"

#include "exchange/histogram.h"
#include "exchange/statistics.h"

#include <QtCore/QElapsedTimer>
#include <QtWidgets/QApplication>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <vector>

using namespace mbscope;

namespace {

struct Timing {
    double cpuMs = 0;  // median CPU time of this thread
    double wallMs = 0; // median wall time
};

double threadCpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// Runs work repeat times (after prepare, not timed) and returns the medians. CPU time is the
// figure to read on a shared machine: wall time there includes waiting for a core.
Timing measure(int repeat, const std::function<void()> &work, const std::function<void()> &prepare = {})
{
    std::vector<double> cpu;
    std::vector<double> wall;
    for (int i = 0; i < repeat; ++i) {
        if (prepare)
            prepare();
        QElapsedTimer timer;
        const double cpuStart = threadCpuMs();
        timer.start();
        work();
        wall.push_back(double(timer.nsecsElapsed()) / 1e6);
        cpu.push_back(threadCpuMs() - cpuStart);
    }
    std::sort(cpu.begin(), cpu.end());
    std::sort(wall.begin(), wall.end());
    return {cpu[cpu.size() / 2], wall[wall.size() / 2]};
}

void printRow(const char *what, const Timing &t, qint64 samples)
{
    std::printf("  %-58s %10.2f ms %10.2f ms %9.1f ns\n", what, t.cpuMs, t.wallMs, t.cpuMs * 1e6 / double(samples));
}

QList<Transaction> makeTransactions(qint64 n)
{
    std::mt19937_64 random(42);
    std::lognormal_distribution<double> latencyMs(std::log(5.0), 0.6);
    QList<Transaction> list;
    list.reserve(n);
    qint64 at = 1000000;
    for (qint64 i = 0; i < n; ++i) {
        Transaction t;
        t.id = quint64(i + 1);
        t.item = int(i % 2);
        t.sentNs = at;
        if (i % 1000 == 999) {
            t.status = TransactionStatus::Timeout;
        } else {
            t.status = TransactionStatus::Ok;
            t.doneNs = at + qint64(std::min(latencyMs(random), 1000.0) * 1e6);
        }
        at += 10000000;
        list.append(t);
    }
    return list;
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
    QApplication app(argc, argv);
    qint64 samples = 1000000;
    int repeat = 5;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--samples") == 0 && i + 1 < argc)
            samples = std::max<qint64>(2, std::atoll(argv[++i]));
        else if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "bench_histogram: unknown argument '%s'\nUsage: bench_histogram [--samples N] [--repeat R]\n", argv[i]);
            return 2;
        }
    }

    const QList<Transaction> transactions = makeTransactions(samples);
    Statistics statistics;
    std::vector<qint64> latencies;
    for (const Transaction &t : transactions) {
        if (t.doneNs > 0)
            latencies.push_back(t.latencyNs());
    }
    const auto [lowest, highest] = std::minmax_element(latencies.begin(), latencies.end());

    std::printf("bench_histogram: %lld transactions, %zu latencies (%.3f ms to %.3f ms), median of %d runs\n",
                static_cast<long long>(samples), latencies.size(), double(*lowest) / 1e6, double(*highest) / 1e6, repeat);
    std::printf("  %-58s %13s %13s %12s\n", "", "CPU", "wall", "CPU/sample");

    std::printf("counting\n");
    printRow("Statistics::add (auto bins, every latency kept)",
             measure(repeat, [&] { for (const Transaction &t : transactions) statistics.add(t); }, [&] { statistics.clear(); }),
             samples);
    Histogram fixed = Histogram::fixed(100000, 0, 1001000000);
    printRow("Histogram::add, fixed 100 us bins",
             measure(repeat, [&] { for (const qint64 v : latencies) fixed.add(v); }, [&] { fixed.clear(); }), samples);
    Histogram log = Histogram::logarithmic(20, 100000, 2000000000);
    printRow("Histogram::add, logarithmic 20 bins a decade",
             measure(repeat, [&] { for (const qint64 v : latencies) log.add(v); }, [&] { log.clear(); }), samples);

    std::printf("redrawing the histogram (900 x 500 pixmap)\n");
    QCustomPlot plot;
    plot.resize(900, 500);
    const LatencySamples &stored = statistics.latency();
    (void)stored.sorted(); // sorted once, as after the first redraw of a poll
    for (const LatencyBinning::Scale scale : {LatencyBinning::Scale::Linear, LatencyBinning::Scale::Logarithmic}) {
        const bool isLog = scale == LatencyBinning::Scale::Logarithmic;
        Histogram binned;
        printRow(isLog ? "rebin the stored latencies, logarithmic" : "rebin the stored latencies, linear (auto 1-2-5 bins)",
                 measure(repeat, [&] { binned = LatencyBinning::bin(stored, scale); }), samples);
        printRow("  then draw bars and markers, replot into a pixmap",
                 measure(repeat, [&] {
                     HistogramChart::draw(plot, {{QString(), binned.edgesNs(), binned.counts(), binned.isLogarithmic()}},
                                          {{QStringLiteral("median"), double(stored.medianNs()), QColor()}});
                     (void)plot.toPixmap(900, 500);
                 }),
                 samples);
    }
    {
        LatencyRuns runs;
        LatencyHistogramPanel panel(&runs);
        panel.resize(1100, 500);
        for (qsizetype i = 0; i < transactions.size(); i += 1000)
            runs.addTransactions(transactions.mid(i, 1000));
        const Transaction one = transactions.constFirst();
        printRow("whole panel redraw: rebin, statistics table, plot, pixmap",
                 measure(repeat, [&] {
                     panel.redrawNow();
                     (void)panel.plot()->toPixmap(900, 500);
                 }, [&] { runs.addTransactions({one}); }),
                 samples);
    }

    std::printf("baselines\n");
    {
        QCustomPlot raw;
        raw.resize(900, 500);
        QCPGraph *graph = raw.addGraph();
        graph->setLineStyle(QCPGraph::lsNone);
        graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDot));
        QVector<double> keys(qsizetype(latencies.size()));
        QVector<double> values(qsizetype(latencies.size()));
        for (std::size_t i = 0; i < latencies.size(); ++i) {
            keys[qsizetype(i)] = double(i);
            values[qsizetype(i)] = double(latencies[i]) / 1e6;
        }
        printRow("QCustomPlot: the latencies as raw points, set and replot",
                 measure(repeat, [&] {
                     graph->setData(keys, values, true);
                     raw.rescaleAxes();
                     (void)raw.toPixmap(900, 500);
                 }),
                 samples);
    }
    {
        const Histogram layout = LatencyBinning::bin(stored, LatencyBinning::Scale::Linear);
        const std::vector<double> &edges = layout.edgesNs();
        std::vector<quint64> counts(edges.size() - 1, 0);
        printRow("naive re-binning: scan the edges for every sample",
                 measure(repeat, [&] {
                     std::fill(counts.begin(), counts.end(), 0);
                     for (const qint64 v : latencies) {
                         for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
                             if (double(v) >= edges[b] && double(v) < edges[b + 1]) {
                                 ++counts[b];
                                 break;
                             }
                         }
                     }
                 }),
                 samples);
    }
    return 0;
}
