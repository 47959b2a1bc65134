// Timing truth of the simulator and of the engine, in one run on the loopback (issue 19).
//
// mbscope's simulator serves unit 1 with rosrao-gamma's response time (normal 4 +/- 1.5 ms, 1-12
// ms) on tcp://127.0.0.1 while mbscope's engine polls it N times, one request at a time, and
// tshark captures the port. Each exchange is found on the wire (request and response segments in
// order on the connection), then:
//   simulator: wire delay (response segment - request segment) minus the delay it drew for that
//              answer: how late the answer left, which the millisecond timer made 0-1 ms;
//   engine:    the engine's latency minus the wire's: its own timing error.
// Median and p99 of each difference are printed side by side, beside the baseline of the
// millisecond timer the simulator used before (measured once with the CLI, 1000 polls of
// rosrao-gamma over rtu-tcp: a median latency of 5.248 ms for draws whose median is 4.0 ms, i.e.
// answers about 1.25 ms late at the median; see docs/guide/simulator.md). Without tshark (or without capture rights on lo) it says
// so and prints the simulator's accuracy as seen by the engine instead (engine latency minus
// the drawn delay). Figures are printed, never asserted.
//
// Usage: bench_simdelay [--count N]
#include "tsharkcapture.h"

#include "engine/transactionengine.h"
#include "exchange/transaction.h"
#include "protocol/adubuilder.h"
#include "protocol/requestbuilder.h"
#include "sim/faultinjector.h"
#include "sim/simendpoint.h"
#include "sim/simexchange.h"
#include "sim/simulator.h"
#include "sim/simunit.h"
#include "transport/linkurl.h"

#include <QtCore/QCoreApplication>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace mbscope;

namespace {

// The millisecond QTimer before issue 19 (see the header).
constexpr const char *kBefore = "ms timer before: median ~+1250";

double percentileUs(std::vector<qint64> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const auto n = qsizetype(v.size());
    const qsizetype rank = std::clamp<qsizetype>(qsizetype(std::ceil(p / 100.0 * double(n))), 1, n);
    return double(v[size_t(rank - 1)]) / 1000.0;
}

void printRow(const char *what, const std::vector<qint64> &differenceNs, const char *baseline)
{
    std::printf("%-44s %9.1f %9.1f %9.1f %9.1f   %s\n", what, percentileUs(differenceNs, 50), percentileUs(differenceNs, 99),
                percentileUs(differenceNs, 0), percentileUs(differenceNs, 100), baseline);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    int count = 1000;
    const QStringList args = QCoreApplication::arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args.at(i) == QLatin1String("--count") && i + 1 < args.size())
            count = std::max(1, args.at(++i).toInt());
    }

    Simulator sim;
    SimUnit *unit = sim.addUnit(1);
    SimRange range;
    range.count = 22;
    range.start = 0x79;
    if (!unit->addRange(range)) {
        std::fprintf(stderr, "bench_simdelay: the unit refused its registers\n");
        return 2;
    }
    FaultInjector injector;
    DelaySpec gamma;
    gamma.kind = DelaySpec::Kind::Normal;
    gamma.meanMs = 4;
    gamma.stddevMs = 1.5;
    gamma.minMs = 1;
    gamma.maxMs = 12;
    injector.setResponseDelay(1, gamma);
    std::vector<qint64> drawnNs;
    sim.setFaultHook([&injector, &drawnNs](const SimExchange &exchange) {
        FaultPlan plan = injector.plan(FaultContext::forExchange(exchange));
        drawnNs.push_back(plan.chunks.isEmpty() ? 0 : plan.chunks.first().delayNs);
        return plan;
    });
    QString error;
    SimEndpoint *endpoint = sim.listen(QStringLiteral("tcp://127.0.0.1:0"), {}, &error);
    if (!endpoint) {
        std::fprintf(stderr, "bench_simdelay: %s\n", qPrintable(error));
        return 2;
    }
    const quint16 port = endpoint->boundUrl().port;

    testpeers::TsharkCapture capture;
    const bool wire = capture.start(port);
    if (!wire)
        std::printf("tshark: %s; the simulator is measured through the engine instead of the wire\n",
                    qPrintable(capture.error()));

    const auto parsed = LinkUrl::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
    const LinkUrl url = *parsed.url;
    TransactionEngine engine;
    engine.setTarget(url);
    QList<Transaction> records;
    QObject::connect(&engine, &TransactionEngine::transactionsFinished,
                     [&records](const QList<Transaction> &batch) { records += batch; });
    PollSettings settings;
    settings.items = {RequestItem::forLink(AduBuilder::mbap(RequestBuilder::readHoldingRegisters(0x79, 22).pdu, 1, 0x2A2A), url)};
    settings.count = quint64(count);
    settings.intervalNs = 0;
    engine.startPoll(settings);
    if (!engine.waitForFinished(600000)) {
        std::fprintf(stderr, "bench_simdelay: the poll did not finish\n");
        return 1;
    }
    QCoreApplication::processEvents();
    engine.closeLink();
    std::sort(records.begin(), records.end(), [](const Transaction &a, const Transaction &b) { return a.id < b.id; });

    std::printf("simulator delay accuracy and engine timing error, %d polls of a normal 4 +/- 1.5 ms response time on "
                "tcp://127.0.0.1 (microseconds)\n",
                count);
    std::printf("%-44s %9s %9s %9s %9s   %s\n", "", "median", "p99", "min", "max", "baseline");
    if (records.size() != qsizetype(drawnNs.size())) {
        std::fprintf(stderr, "bench_simdelay: %lld transactions, %zu answers planned\n", static_cast<long long>(records.size()),
                     drawnNs.size());
        return 1;
    }

    std::vector<qint64> engineMinusDrawn;
    for (qsizetype i = 0; i < records.size(); ++i) {
        if (records.at(i).isOk())
            engineMinusDrawn.push_back(records.at(i).latencyNs() - drawnNs[size_t(i)]);
    }
    if (!wire) {
        printRow("simulator: engine latency - drawn delay", engineMinusDrawn, kBefore);
        return 0;
    }

    QList<testpeers::WireSegment> segments;
    if (!capture.stopAndRead(&segments)) {
        std::printf("tshark: %s\n", qPrintable(capture.error()));
        printRow("simulator: engine latency - drawn delay", engineMinusDrawn, kBefore);
        return 0;
    }
    QList<qint64> requestNs;
    QList<qint64> responseNs;
    for (const testpeers::WireSegment &s : segments) {
        if (s.destinationPort == port)
            requestNs.append(s.timeNs);
        else if (s.sourcePort == port)
            responseNs.append(s.timeNs);
    }
    if (requestNs.size() != records.size() || responseNs.size() != records.size()) {
        std::printf("tshark: %lld request and %lld response segments for %lld transactions: not paired\n",
                    static_cast<long long>(requestNs.size()), static_cast<long long>(responseNs.size()),
                    static_cast<long long>(records.size()));
        printRow("simulator: engine latency - drawn delay", engineMinusDrawn, kBefore);
        return 0;
    }
    std::vector<qint64> wireMinusDrawn;
    std::vector<qint64> engineMinusWire;
    for (qsizetype i = 0; i < records.size(); ++i) {
        const qint64 wireNs = responseNs.at(i) - requestNs.at(i);
        wireMinusDrawn.push_back(wireNs - drawnNs[size_t(i)]);
        if (records.at(i).isOk())
            engineMinusWire.push_back(records.at(i).latencyNs() - wireNs);
    }
    printRow("simulator: wire delay - drawn delay", wireMinusDrawn, kBefore);
    printRow("engine: engine latency - wire latency", engineMinusWire, "(what the engine adds: tst_latency_truth)");
    printRow("both: engine latency - drawn delay", engineMinusDrawn, kBefore);
    return 0;
}
