// libFuzzer target over the simulator's request path: random bytes arrive on an endpoint of each
// framing, are cut by that endpoint's framer as the endpoint cuts them (SimConnection for tcp,
// rtu-tcp and ascii-tcp; SimDatagramEndpoint for udp and rtu-udp, one datagram one frame;
// SimSerialEndpoint for rtu and ascii), and every frame goes through Simulator::handleFrame to
// the conformance profile's units (SimProcessor, QModbusServer underneath) and, when asked, the
// FaultInjector with a rule of every kind. Nothing may crash, and without faults every answer
// must be one well-formed frame of the request's framing: same unit (and transaction id), the
// request's function code or its exception, checksum right, PDU within 253 bytes; serial
// broadcasts and malformed frames are never answered.
//
// Input layout:
//   byte 0   endpoint: 0 tcp, 1 rtu-tcp, 2 ascii-tcp, 3 udp, 4 rtu-udp, 5 rtu, 6 ascii (wraps)
//   byte 1   bits 0-1: chunking of stream bytes: 1 byte, 16 bytes, pseudo-random 1-64, all at once
//            bits 2-5: seed of the pseudo-random chunk sizes and of the fault rules
//            bit 6:    a silence after every chunk
//            bit 7:    the fault injector's rules on
//   the rest is what the client sent (datagram endpoints: datagrams of length-prefixed records,
//   one length byte then that many bytes)
#include "protocol/adubuilder.h"
#include "protocol/asciiframer.h"
#include "protocol/mbapframer.h"
#include "protocol/rtuframer.h"
#include "sim/faultinjector.h"
#include "sim/profileapplier.h"
#include "profile/profileloader.h"
#include "sim/simendpoint.h"
#include "sim/simexchange.h"
#include "sim/simulator.h"
#include "sim/simunit.h"
#include "transport/linkurl.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>

using namespace mbscope;

namespace {

void check(bool condition)
{
    if (!condition)
        std::abort();
}

// An endpoint that binds nothing: the fuzzer hands its frames to the simulator itself.
class FuzzEndpoint : public SimEndpoint
{
public:
    FuzzEndpoint(Simulator *simulator, const LinkUrl &url)
        : SimEndpoint(simulator, url, {})
    {
    }
    bool start(QString *) override
    {
        setBound(url(), true);
        return true;
    }
    void stop() override {}
};

const char *const kUrls[] = {
    "tcp://127.0.0.1:5020", "rtu-tcp://127.0.0.1:5021", "ascii-tcp://127.0.0.1:5022", "udp://127.0.0.1:5020",
    "rtu-udp://127.0.0.1:5023", "rtu:///dev/fuzz-rtu?baud=19200", "ascii:///dev/fuzz-ascii?baud=9600",
};
constexpr int kEndpoints = 7;

// Every fault kind, each firing half the time.
const char kRules[] = R"({"seed": 1, "rules": [
  {"kind": "drop", "probability": 0.1},
  {"kind": "delay", "probability": 0.5, "delay": {"distribution": "exponential", "meanMs": 5, "maxMs": 50}},
  {"kind": "wrongChecksum", "probability": 0.5},
  {"kind": "wrongTransactionId", "probability": 0.5, "delta": 3},
  {"kind": "wrongUnit", "probability": 0.5},
  {"kind": "exception", "probability": 0.5, "code": 6},
  {"kind": "fewerRegisters", "probability": 0.5, "fewer": 2},
  {"kind": "chunks", "probability": 0.5, "chunkBytes": 3, "gapMs": 1},
  {"kind": "trickle", "probability": 0.2, "gapMs": 1},
  {"kind": "junk", "probability": 0.5, "before": 3, "after": "DE AD"},
  {"kind": "duplicate", "probability": 0.5, "copies": 2},
  {"kind": "close", "probability": 0.1, "when": "midway"}
]})";

struct Fixture {
    DeviceProfile profile;
    FaultRuleSet rules;
    std::optional<LinkUrl> urls[kEndpoints];
};

const Fixture &fixture()
{
    static const Fixture f = [] {
        Fixture out;
        ProfileLoadResult loaded = ProfileLoader::load(QStringLiteral("conformance"));
        check(loaded.ok);
        out.profile = loaded.profile;
        FaultRulesLoadResult rules = ProfileLoader::parseFaults(QByteArray(kRules), QStringLiteral("fuzz rules"));
        check(rules.ok);
        out.rules = rules.rules;
        for (int i = 0; i < kEndpoints; ++i) {
            out.urls[i] = LinkUrl::parse(QString::fromLatin1(kUrls[i]), LinkUse::Listen).url;
            check(out.urls[i].has_value());
        }
        return out;
    }();
    return f;
}

std::unique_ptr<StreamFramer> framerFor(const LinkUrl &url)
{
    switch (url.framing()) {
    case Framing::Rtu: {
        auto rtu = std::make_unique<RtuFramer>(Direction::Request);
        if (url.isSerial())
            rtu->setBaudRate(url.serial.baud);
        return rtu;
    }
    case Framing::Ascii: return std::make_unique<AsciiFramer>();
    default: return std::make_unique<MbapFramer>();
    }
}

// Without faults, the plan for a request is silence or exactly its answer.
void checkPlan(const FaultPlan &plan, QByteArrayView request, Framing framing, bool faults)
{
    for (const ResponseChunk &chunk : plan.chunks)
        check(chunk.delayNs >= 0);
    if (plan.drop || plan.closeBefore) {
        check(plan.chunks.isEmpty());
        return;
    }
    if (faults)
        return;
    check(plan.chunks.size() == 1 && plan.faults.isEmpty() && !plan.closeAfter);
    const AduParts asked = AduBuilder::parse(request, framing);
    const AduParts answer = AduBuilder::parse(plan.chunks.constFirst().bytes, framing);
    check(asked.complete && !asked.pdu.isEmpty());
    check(answer.complete && answer.error.isEmpty());
    check(answer.unitId == asked.unitId);
    if (framing == Framing::Rtu || framing == Framing::Ascii) {
        check(asked.unitId != 0); // a broadcast is never answered
        check(answer.checksumValid());
    } else {
        check(answer.transactionId == asked.transactionId && answer.protocolId == 0 && answer.lengthMatches);
    }
    check(!answer.pdu.isEmpty() && answer.pdu.size() <= 253);
    const quint8 function = quint8(asked.pdu.at(0));
    const quint8 answered = quint8(answer.pdu.at(0));
    check(answered == function || answered == (function | 0x80));
    if (answered & 0x80) // an exception: code only (V1.1b3 section 7)
        check(answer.pdu.size() == 2 && quint8(answer.pdu.at(1)) != 0);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    const Fixture &f = fixture();
    const LinkUrl &url = *f.urls[data[0] % kEndpoints];
    const int chunking = data[1] & 0x03;
    std::uint32_t seed = (data[1] >> 2) & 0x0F;
    const bool silences = (data[1] & 0x40) != 0;
    const bool faults = (data[1] & 0x80) != 0;
    const QByteArray bytes(reinterpret_cast<const char *>(data + 2), qsizetype(size - 2));

    // A fresh simulator per input, so that an input's outcome never depends on the ones before.
    Simulator sim;
    QString error;
    for (SimUnit *unit : ProfileApplier::createUnits(f.profile, nullptr, &error))
        check(sim.adoptUnit(std::unique_ptr<SimUnit>(unit)) != nullptr);
    check(error.isEmpty());
    FaultInjector injector;
    if (faults) {
        ProfileApplier::configure(&injector, f.profile);
        FaultRuleSet rules = f.rules;
        rules.seed = seed + 1;
        injector.setRules(rules);
        sim.setFaultHook([&injector](const SimExchange &exchange) {
            return injector.plan(FaultContext::forExchange(exchange));
        });
    }
    FuzzEndpoint endpoint(&sim, url);
    check(endpoint.start(&error));
    const Framing framing = url.framing();
    const QString peer = QStringLiteral("fuzz");
    qint64 now = 0;

    if (url.kind == LinkKind::Udp || url.kind == LinkKind::RtuUdp) {
        qsizetype at = 0;
        while (at < bytes.size()) {
            const qsizetype length = qMin<qsizetype>(quint8(bytes.at(at)), bytes.size() - at - 1);
            const QByteArray datagram = bytes.mid(at + 1, length);
            at += 1 + length;
            now += 1'000'000;
            const FaultPlan plan = sim.handleFrame(&endpoint, datagram, FrameStatus::Valid, peer, now);
            checkPlan(plan, datagram, framing, faults);
        }
        return 0;
    }

    std::unique_ptr<StreamFramer> framer = framerFor(url);
    const bool mbap = framing == Framing::Tcp;
    bool closed = false;
    auto drain = [&] {
        // As SimConnection::drain: on MBAP a skipped run closes the connection.
        if (mbap && framer->openSkippedRunSize() > 0)
            framer->flushOnSilence();
        const QList<StreamFrame> frames = framer->takeFrames();
        const QList<SkippedBytes> skipped = framer->takeSkipped();
        qsizetype fi = 0;
        qsizetype si = 0;
        while (!closed && (fi < frames.size() || si < skipped.size())) {
            if (si < skipped.size() && (fi >= frames.size() || skipped.at(si).offset < frames.at(fi).offset)) {
                sim.noteSkipped(&endpoint, skipped.at(si++), peer);
                closed = mbap;
                continue;
            }
            const StreamFrame &frame = frames.at(fi++);
            const FaultPlan plan = sim.handleFrame(&endpoint, frame.bytes, frame.status, peer, now);
            if (frame.status == FrameStatus::Valid)
                checkPlan(plan, frame.bytes, framing, faults);
            else
                check(plan.drop);
            closed = closed || plan.closeBefore || plan.closeAfter;
        }
    };
    qsizetype at = 0;
    while (at < bytes.size() && !closed) {
        qsizetype chunk = bytes.size();
        switch (chunking) {
        case 0: chunk = 1; break;
        case 1: chunk = 16; break;
        case 2:
            seed = seed * 1103515245u + 12345u;
            chunk = 1 + qsizetype((seed >> 16) % 64);
            break;
        default: break;
        }
        chunk = qMin(chunk, bytes.size() - at);
        now += 100'000;
        framer->feed(QByteArrayView(bytes).sliced(at, chunk), now);
        at += chunk;
        if (silences) {
            now += 50'000'000;
            framer->flushOnSilence();
        }
        drain();
    }
    if (!closed) {
        framer->flushOnSilence();
        drain();
    }
    return 0;
}
