#include "sim/faultinjector.h"

#include "protocol/functionspec.h"
#include "protocol/framingtraits.h"

#include "protocol/adubuilder.h"
#include "sim/faultbytes.h"
#include "sim/simexchange.h"

#include <QtCore/QMutexLocker>

#include <algorithm>
#include <cmath>

namespace mbscope {

namespace {

constexpr quint64 kRuleStream = 1;
constexpr quint64 kDelayStream = 2;

quint16 word(const QByteArray &pdu, qsizetype at)
{
    return quint16(quint8(pdu.at(at)) << 8 | quint8(pdu.at(at + 1)));
}

qint64 msToNs(double ms)
{
    return qint64(std::llround(ms * 1e6));
}

// A segment of the bytes to send: the answer (with junk), or a duplicate, after a delay.
struct Segment {
    QByteArray bytes;
    qint64 delayNs = 0;
};

void split(const Segment &segment, int pieceBytes, qint64 gapNs, QList<ResponseChunk> *out)
{
    for (qsizetype at = 0; at < segment.bytes.size(); at += pieceBytes)
        out->append(ResponseChunk{segment.bytes.mid(at, pieceBytes), at == 0 ? segment.delayNs : gapNs});
}

} // namespace

FaultContext FaultContext::forRequest(Framing framing, const QByteArray &request, const QByteArray &response,
                                      qint64 responseDelayNs)
{
    FaultContext c;
    c.framing = framing;
    c.request = request;
    c.response = response;
    c.responseDelayNs = responseDelayNs;
    const AduParts parts = AduBuilder::parse(request, framing);
    c.unit = parts.unitId;
    const QByteArray &pdu = parts.pdu;
    if (pdu.isEmpty())
        return c;
    c.function = quint8(pdu.at(0));
    auto span = [&c](int start, int count) {
        c.firstAddress = start;
        c.lastAddress = std::min(65535, start + std::max(count, 1) - 1);
    };
    auto registers = [&c, &pdu](qsizetype at, int count) {
        c.writes = true;
        for (int i = 0; i < count && at + 2 * i + 1 < pdu.size(); ++i)
            c.written.append(word(pdu, at + 2 * i));
    };
    // A code outside the public table (user-defined) is taken to start with an address too, as
    // such functions usually do.
    if (pdu.size() >= 3 && (functionStartsWithAddress(c.function) || !functionSpec(c.function)))
        c.start = word(pdu, 1);
    switch (c.function) {
    case 0x01: case 0x02: case 0x03: case 0x04: case 0x0F: case 0x10:
        if (pdu.size() >= 5) {
            span(word(pdu, 1), word(pdu, 3));
            c.quantity = word(pdu, 3);
        }
        if (c.function == 0x10 && c.quantity >= 0)
            registers(6, c.quantity);
        if (c.function == 0x0F && c.quantity >= 0) {
            c.writes = true;
            for (int i = 0; i < c.quantity && 6 + i / 8 < pdu.size(); ++i)
                c.written.append(quint16((quint8(pdu.at(6 + i / 8)) >> (i % 8)) & 1));
        }
        break;
    case 0x05: case 0x06:
        if (pdu.size() >= 5) {
            span(word(pdu, 1), 1);
            c.quantity = 1;
            const quint16 value = word(pdu, 3);
            c.writes = true;
            c.written.append(c.function == 0x05 && value == 0xFF00 ? quint16(1) : value);
        }
        break;
    case 0x16:
        if (pdu.size() >= 3)
            span(word(pdu, 1), 1);
        if (pdu.size() >= 7)
            registers(3, 2);
        break;
    case 0x18:
        if (pdu.size() >= 3)
            span(word(pdu, 1), 1);
        break;
    case 0x17:
        if (pdu.size() >= 5)
            c.quantity = word(pdu, 3);
        if (pdu.size() >= 9)
            registers(10, word(pdu, 7));
        if (pdu.size() >= 9) {
            const int readStart = word(pdu, 1);
            const int writeStart = word(pdu, 5);
            const int end = std::max(readStart + std::max<int>(word(pdu, 3), 1), writeStart + std::max<int>(word(pdu, 7), 1));
            const int start = std::min(readStart, writeStart);
            span(start, end - start);
        }
        break;
    default:
        break;
    }
    return c;
}

FaultContext FaultContext::forExchange(const SimExchange &exchange)
{
    if (exchange.delimited) {
        FaultContext c;
        c.framing = exchange.framing;
        c.delimited = true;
        c.unit = exchange.routedUnitId;
        c.request = exchange.requestAdu;
        c.response = exchange.responseAdu;
        c.responseDelayNs = exchange.responseDelayNs;
        c.responseDelayFixed = exchange.responseDelayFixed;
        c.intervalNs = exchange.intervalNs;
        return c;
    }
    FaultContext c = forRequest(exchange.framing, exchange.requestAdu, exchange.responseAdu, exchange.responseDelayNs);
    c.responseDelayFixed = exchange.responseDelayFixed;
    c.unit = exchange.routedUnitId;
    c.intervalNs = exchange.intervalNs;
    return c;
}

void FaultInjector::setRules(const FaultRuleSet &rules)
{
    QMutexLocker lock(&m_mutex);
    m_rules = rules;
    resetStreams(); // under the same lock: plan() never sees rules without their streams
}

FaultRuleSet FaultInjector::rules() const
{
    QMutexLocker lock(&m_mutex);
    return m_rules;
}

void FaultInjector::setResponseDelay(quint8 unit, const DelaySpec &delay)
{
    QMutexLocker lock(&m_mutex);
    m_delays.insert(unit, delay);
    m_delayRandom.remove(unit);
}

void FaultInjector::clearResponseDelays()
{
    QMutexLocker lock(&m_mutex);
    m_delays.clear();
    m_delayRandom.clear();
}

void FaultInjector::reset()
{
    QMutexLocker lock(&m_mutex);
    resetStreams();
}

void FaultInjector::resetStreams()
{
    m_ruleRandom.clear();
    for (qsizetype i = 0; i < m_rules.rules.size(); ++i)
        m_ruleRandom.emplace_back(SimRandom::derive(m_rules.seed, kRuleStream, quint64(i)));
    m_delayRandom.clear();
}

SimRandom &FaultInjector::delayRandom(quint8 unit)
{
    auto it = m_delayRandom.find(unit);
    if (it == m_delayRandom.end())
        it = m_delayRandom.insert(unit, SimRandom(SimRandom::derive(m_rules.seed, kDelayStream, unit)));
    return it.value();
}

bool FaultInjector::matches(const FaultRule &rule, const FaultContext &context)
{
    if (!rule.units.isEmpty() && !rule.units.contains(context.unit))
        return false;
    if (!rule.functions.isEmpty() && !rule.functions.contains(context.function))
        return false;
    if (rule.hasAddressRange()
        && (context.firstAddress < 0 || context.lastAddress < rule.firstAddress || context.firstAddress > rule.lastAddress))
        return false;
    if (!rule.starts.isEmpty() && !rule.starts.contains(context.start))
        return false;
    if (!rule.quantities.isEmpty() && !rule.quantities.contains(context.quantity))
        return false;
    if (rule.hasValues && (!context.writes || context.written != rule.values))
        return false;
    using K = FaultRule::Kind;
    if (context.delimited) {
        switch (rule.kind) {
        case K::WrongChecksum: case K::WrongTransactionId: case K::WrongUnit: case K::Exception: case K::FewerRegisters:
            return false;
        default:
            return true;
        }
    }
    switch (rule.kind) {
    case K::WrongChecksum:
        return isSerialLine(context.framing);
    case K::WrongTransactionId:
        return context.framing == Framing::Tcp || context.framing == Framing::Udp;
    case K::FewerRegisters:
        return !FaultBytes::fewerRegisters(context.response, context.framing, rule.fewer).isEmpty();
    default:
        return true;
    }
}

bool FaultInjector::fires(const FaultRule &rule, const FaultContext &context, SimRandom &random)
{
    if (rule.hasTurnaround) {
        // The transceiver needs this long to turn around; a request sooner than that after the
        // previous one finds it still sending. The draw is made for every request, so that one
        // without an interval does not shift the draws of those after it.
        const qint64 turnaroundNs = rule.turnaround.sampleNs(random);
        return context.intervalNs >= 0 && context.intervalNs < turnaroundNs;
    }
    if (!rule.byIntervalMs.isEmpty())
        return random.chance(rule.probabilityAt(context.intervalNs < 0 ? -1.0 : double(context.intervalNs) / 1e6));
    return random.chance(rule.probability);
}

FaultPlan FaultInjector::planWithoutRules(quint8 unit, const QByteArray &response, qint64 responseDelayNs, bool delayFixed)
{
    // No rule: the answer as built after the unit's response time, without the rule machinery
    // of plan() (its lists cost more than the rest of a request, issue 15). The delay is drawn
    // as there, so the draws are the same with and without this path. A script's own delay
    // (delayFixed) stands, as there.
    FaultPlan plan;
    qint64 delayNs = responseDelayNs;
    if (const auto it = m_delays.constFind(unit); it != m_delays.constEnd()) {
        const qint64 drawn = it->sampleNs(delayRandom(unit));
        if (!delayFixed)
            delayNs = drawn;
    }
    plan.chunks.append(ResponseChunk{response, delayNs});
    return plan;
}

FaultPlan FaultInjector::plan(const SimExchange &exchange)
{
    {
        QMutexLocker lock(&m_mutex);
        if (m_rules.rules.isEmpty()) {
            // FaultContext::forExchange's unit: the unit that answers (unit 0 or 255 over MBAP is
            // the endpoint's first unit, whose response time it takes).
            return planWithoutRules(exchange.routedUnitId, exchange.responseAdu, exchange.responseDelayNs,
                                    exchange.responseDelayFixed);
        }
    }
    return plan(FaultContext::forExchange(exchange));
}

FaultPlan FaultInjector::plan(const FaultContext &context)
{
    QMutexLocker lock(&m_mutex);
    using K = FaultRule::Kind;
    FaultPlan plan;
    if (m_rules.rules.isEmpty())
        return planWithoutRules(context.unit, context.response, context.responseDelayNs, context.responseDelayFixed);

    // Which rules fire: each matching rule draws once from its own stream.
    QList<qsizetype> fired;
    for (qsizetype i = 0; i < m_rules.rules.size(); ++i) {
        const FaultRule &rule = m_rules.rules.at(i);
        if (matches(rule, context) && fires(rule, context, m_ruleRandom[size_t(i)])) {
            fired.append(i);
            plan.faults.append(rule.name.isEmpty() ? FaultRule::kindName(rule.kind) : rule.name);
        }
    }
    auto firedOf = [&](K kind) {
        QList<const FaultRule *> out;
        for (qsizetype i : fired) {
            if (m_rules.rules.at(i).kind == kind)
                out.append(&m_rules.rules.at(i));
        }
        return out;
    };
    auto randomOf = [&](const FaultRule *rule) -> SimRandom & {
        return m_ruleRandom[size_t(rule - m_rules.rules.constData())];
    };
    auto closeFired = [&](FaultRule::CloseWhen when) {
        const auto closes = firedOf(K::Close);
        return std::any_of(closes.cbegin(), closes.cend(), [when](const FaultRule *r) { return r->closeWhen == when; });
    };

    // The unit's response time is drawn for every answer, so that faults do not shift the
    // delays of the answers after them.
    qint64 delayNs = context.responseDelayNs;
    if (const auto it = m_delays.constFind(context.unit); it != m_delays.constEnd()) {
        const qint64 drawn = it->sampleNs(delayRandom(context.unit));
        if (!context.responseDelayFixed)
            delayNs = drawn;
    }

    // Noise on the request: a frame with any bit flipped is lost (its CRC or LRC fails; a
    // delimited frame no longer reads as the request).
    // A noise rule that changed nothing is not named among the plan's faults.
    QList<const FaultRule *> noisy;
    bool requestLost = false;
    for (const FaultRule *rule : firedOf(K::Noise)) {
        if (rule->noiseOn == FaultRule::NoiseOn::Answer)
            continue;
        const double bits = 8.0 * double(context.request.size());
        if (randomOf(rule).chance(1.0 - std::pow(1.0 - rule->bitErrorRate, bits))) {
            requestLost = true;
            noisy.append(rule);
        }
    }
    const auto quietNoise = [&] {
        for (const FaultRule *rule : firedOf(K::Noise)) {
            if (!noisy.contains(rule))
                plan.faults.removeOne(rule->name.isEmpty() ? FaultRule::kindName(rule->kind) : rule->name);
        }
    };
    plan.drop = !firedOf(K::Drop).isEmpty() || requestLost;
    plan.closeBefore = closeFired(FaultRule::CloseWhen::Before);
    if (plan.drop || plan.closeBefore) {
        quietNoise();
        return plan;
    }

    // Content: the PDU and unit, then the bytes as sent.
    QByteArray adu = context.response;
    for (const FaultRule *rule : firedOf(K::Exception)) {
        const QByteArray changed = FaultBytes::exception(adu, context.framing, context.function, rule->exceptionCode);
        if (!changed.isEmpty())
            adu = changed;
    }
    for (const FaultRule *rule : firedOf(K::FewerRegisters)) {
        const QByteArray changed = FaultBytes::fewerRegisters(adu, context.framing, rule->fewer);
        if (!changed.isEmpty())
            adu = changed;
    }
    for (const FaultRule *rule : firedOf(K::WrongUnit)) {
        const QByteArray changed = FaultBytes::wrongUnit(adu, context.framing, rule->delta);
        if (!changed.isEmpty())
            adu = changed;
    }
    for (const FaultRule *rule : firedOf(K::WrongTransactionId)) {
        const QByteArray changed = FaultBytes::wrongTransactionId(adu, context.framing, rule->delta);
        if (!changed.isEmpty())
            adu = changed;
    }
    if (!firedOf(K::WrongChecksum).isEmpty()) {
        const QByteArray changed = FaultBytes::wrongChecksum(adu, context.framing);
        if (!changed.isEmpty())
            adu = changed;
    }

    for (const FaultRule *rule : firedOf(K::Noise)) {
        if (rule->noiseOn == FaultRule::NoiseOn::Request)
            continue;
        const QByteArray flipped = FaultBytes::flipBits(adu, rule->bitErrorRate, randomOf(rule));
        if (flipped != adu && !noisy.contains(rule))
            noisy.append(rule);
        adu = flipped;
    }
    quietNoise();

    for (const FaultRule *rule : firedOf(K::Delay))
        delayNs = rule->delay.sampleNs(randomOf(rule));

    QByteArray before;
    QByteArray after;
    for (const FaultRule *rule : firedOf(K::Junk)) {
        SimRandom &random = randomOf(rule);
        before += rule->junkBefore;
        for (int i = 0; i < rule->junkBeforeCount; ++i)
            before.append(char(random.below(256)));
        after += rule->junkAfter;
        for (int i = 0; i < rule->junkAfterCount; ++i)
            after.append(char(random.below(256)));
    }

    QList<Segment> segments = {Segment{before + adu + after, delayNs}};
    for (const FaultRule *rule : firedOf(K::Duplicate)) {
        for (int i = 0; i < rule->copies; ++i)
            segments.append(Segment{adu, msToNs(rule->gapMs)});
    }
    if (closeFired(FaultRule::CloseWhen::Midway)) {
        Segment &first = segments.first();
        first.bytes.truncate(std::max<qsizetype>(1, first.bytes.size() / 2));
        segments = {first};
        plan.closeAfter = true;
    }

    const auto trickles = firedOf(K::Trickle);
    const auto chunks = firedOf(K::Chunks);
    for (const Segment &segment : segments) {
        if (!trickles.isEmpty())
            split(segment, 1, msToNs(trickles.last()->gapMs), &plan.chunks);
        else if (!chunks.isEmpty())
            split(segment, chunks.last()->chunkBytes, msToNs(chunks.last()->gapMs), &plan.chunks);
        else
            plan.chunks.append(ResponseChunk{segment.bytes, segment.delayNs});
    }
    plan.closeAfter = plan.closeAfter || closeFired(FaultRule::CloseWhen::After);
    return plan;
}

} // namespace mbscope
