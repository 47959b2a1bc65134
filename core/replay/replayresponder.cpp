#include "replay/replayresponder.h"

#include "protocol/adubuilder.h"
#include "replay/replayscript.h"
#include "sim/simunit.h"

namespace mbscope {

namespace {

bool isMbap(Framing framing)
{
    return framing == Framing::Tcp || framing == Framing::Udp;
}

} // namespace

ReplayResponder::ReplayResponder(const ReplayScript &script, Unrecorded policy, double speed)
    : m_unitIds(script.unitIds()), m_policy(policy), m_speed(speed)
{
    for (const ReplayExchange &e : script.exchanges()) {
        Recorded r;
        r.framing = e.framing;
        // Only a whole answer is served: a recorded CRC error or malformed answer keeps its
        // bytes (served as they were), a timeout is silence.
        if (e.recordedAnswer()) {
            r.adu = e.recorded.response;
            r.pdu = AduBuilder::parse(r.adu, e.framing).pdu;
            r.latencyNs = std::max<qint64>(0, e.recorded.latencyNs());
        }
        ++(r.adu.isEmpty() ? m_recordedSilences : m_recordedAnswers);
        m_answers[key(e.unitId, e.requestPdu)].inTurn.append(r);
    }
}

QString ReplayResponder::policyText(Unrecorded policy)
{
    return policy == Unrecorded::Exception0B ? QStringLiteral("exception 0B (gateway target device failed to respond)")
                                             : QStringLiteral("no answer");
}

QByteArray ReplayResponder::key(quint8 unitId, const QByteArray &pdu)
{
    return char(unitId) + pdu;
}

void ReplayResponder::install(Simulator &sim)
{
    for (quint8 id : std::as_const(m_unitIds)) {
        // Unit 0 is the serial broadcast address: the simulator handles it without a unit.
        if (id != 0 && !sim.unit(id))
            sim.addUnit(id);
    }
    sim.setFaultHook([this](const SimExchange &exchange) { return answer(exchange); });
}

SimEndpointOptions ReplayResponder::endpointOptions() const
{
    SimEndpointOptions options;
    options.unknownUnit = m_policy == Unrecorded::Exception0B ? SimEndpointOptions::UnknownUnit::Exception
                                                             : SimEndpointOptions::UnknownUnit::Ignore;
    // Unit 0 and 0xFF over MBAP are answered only when they were recorded.
    options.directUnitIds = false;
    return options;
}

QByteArray ReplayResponder::frameFor(const Recorded &recorded, const SimExchange &exchange) const
{
    if (recorded.framing == exchange.framing || (isMbap(recorded.framing) && isMbap(exchange.framing))) {
        QByteArray adu = recorded.adu;
        // Messaging on TCP/IP V1.0b, 3.1.3: the answer echoes the request's transaction id.
        if (isMbap(exchange.framing) && adu.size() >= 2) {
            adu[0] = char(exchange.transactionId >> 8);
            adu[1] = char(exchange.transactionId & 0xFF);
        }
        return adu;
    }
    AduOptions options;
    options.framing = exchange.framing;
    options.unitId = exchange.unitId;
    options.transactionId = exchange.transactionId;
    return AduBuilder::complete(recorded.pdu, options);
}

FaultPlan ReplayResponder::answer(const SimExchange &exchange)
{
    FaultPlan plan;
    const auto it = m_answers.find(key(exchange.unitId, exchange.requestPdu));
    if (it == m_answers.end()) {
        ++m_counters.unrecorded;
        if (m_policy == Unrecorded::Ignore) {
            plan.drop = true;
            plan.faults.append(QStringLiteral("never recorded: ignored"));
            return plan;
        }
        const SimReply reply = SimReply::exception(quint8(exchange.requestPdu.at(0)) & 0x7F, 0x0B, {});
        AduOptions options;
        options.framing = exchange.framing;
        options.unitId = exchange.unitId;
        options.transactionId = exchange.transactionId;
        plan.chunks.append(ResponseChunk{AduBuilder::complete(reply.pdu, options), 0});
        plan.faults.append(QStringLiteral("never recorded: exception 0B"));
        return plan;
    }
    Answers &answers = *it;
    const Recorded &recorded = answers.inTurn.at(answers.next);
    answers.next = (answers.next + 1) % answers.inTurn.size();
    if (recorded.adu.isEmpty()) {
        ++m_counters.silences;
        plan.drop = true;
        plan.faults.append(QStringLiteral("recorded: no answer"));
        return plan;
    }
    ++m_counters.served;
    const qint64 delayNs = m_speed > 0 ? qint64(double(recorded.latencyNs) / m_speed) : 0;
    plan.chunks.append(ResponseChunk{frameFor(recorded, exchange), delayNs});
    return plan;
}

} // namespace mbscope
