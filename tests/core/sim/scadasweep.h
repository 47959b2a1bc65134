#pragma once

// One sweep of the shipped profile scada-rs485 through the simulator's request path, with arrival
// times made up by the caller's clock instead of waited for: Simulator::handleFrame with the
// profile's units, delimited table and fault rules, each answer read back through a client's
// delimited framer as mbscope's engine reads it. Used by tests/core/sim/tst_scadacurve (one run,
// the profile's own seed) and tests/bench/bench_scadacurve (the mean of many seeded runs).

#include "profile/deviceprofile.h"
#include "protocol/delimitedframer.h"
#include "sim/faultinjector.h"
#include "sim/profileapplier.h"
#include "sim/simendpoint.h"
#include "sim/simfaulthook.h"
#include "sim/simulator.h"
#include "sim/simunit.h"

#include <QtCore/QString>

#include <memory>
#include <vector>

namespace mbscope::scadasweep {

// The SCADA paper's table: 300 requests per poll interval on its RS485 bus (issue 15).
struct PaperPoint {
    int intervalMs;
    double percent;
};
inline constexpr PaperPoint kPaper[] = {{100, 50.66}, {200, 32.66}, {300, 27.66}, {333, 22.66}, {350, 22.0}, {400, 22.33}};
inline constexpr int kPaperRequests = 300;

// Sends '$01R#' `requests` times at each interval of kPaper in turn (as `mbscope sweep
// --intervals 100,200,300,333,350,400` does), on a fresh simulator whose fault rules draw from
// `seed` (the profile's "seed" otherwise). Returns the count of errors (no answer, or none that
// the framer reads as valid) per interval, or an empty list with *error set.
inline std::vector<int> run(const DeviceProfile &profile, quint64 seed, int requests, QString *error)
{
    Simulator sim;
    for (SimUnit *unit : ProfileApplier::createUnits(profile, nullptr, error)) {
        if (!sim.adoptUnit(std::unique_ptr<SimUnit>(unit))) {
            if (error)
                *error = QStringLiteral("the simulator refused one of the profile's units");
            return {};
        }
    }
    sim.setLineTable(profile.delimited);
    DeviceProfile seeded = profile;
    seeded.faults.seed = seed; // what the profile's "seed" sets (ProfileLoader: faults.seed = seed)
    FaultInjector injector;
    ProfileApplier::configure(&injector, seeded);
    sim.setFaultHook(faultHookFor(&injector));
    SimEndpoint *endpoint = sim.listen(QStringLiteral("tcp://127.0.0.1:0?framing=delimited&start=24&end=23"), {}, error);
    if (!endpoint)
        return {};

    std::vector<int> errors;
    qint64 t = 1'000'000'000'000;
    for (const PaperPoint &p : kPaper) {
        int count = 0;
        for (int i = 0; i < requests; ++i) {
            t += qint64(p.intervalMs) * 1'000'000;
            const FaultPlan plan = sim.handleFrame(endpoint, "$01R#", FrameStatus::Valid, QStringLiteral("sweep"), t);
            DelimitedFramer client(endpoint->url().delimited);
            for (const ResponseChunk &chunk : plan.chunks)
                client.feed(chunk.bytes, 0);
            const QList<StreamFrame> frames = client.takeFrames();
            const bool ok = !plan.drop && !plan.closeBefore && !frames.isEmpty() && frames.first().status == FrameStatus::Valid;
            count += ok ? 0 : 1;
        }
        errors.push_back(count);
    }
    return errors;
}

} // namespace mbscope::scadasweep
