// The Simulator's requests answered by a remote device (Simulator::setRemote): the rest of the
// class is simulator.cpp.
#include "sim/simulator.h"

#include "protocol/adubuilder.h"
#include "protocol/framingtraits.h"
#include "sim/simendpoint.h"
#include "exchange/trafficentry.h"
#include "sim/simremote.h"
#include "transport/monotonicclock.h"

namespace mbscope {

bool Simulator::answersLocally(const SimEndpoint *endpoint) const
{
    return !m_remote || endpoint->url().delimited.enabled;
}

void Simulator::takeFrame(SimEndpoint *endpoint, QByteArrayView adu, FrameStatus status, const QString &peer,
                          qint64 receivedNs, qint64 connectedNs, const PlanSink &sink)
{
    if (answersLocally(endpoint)) {
        sink(handleFrame(endpoint, adu, status, peer, receivedNs, connectedNs));
        return;
    }
    FaultPlan silence;
    silence.drop = true;
    AduParts parts;
    if (!acceptModbusFrame(endpoint, adu, status, peer, {}, &parts)) {
        sink(silence);
        return;
    }
    const qint64 intervalNs = intervalSince(endpoint, receivedNs);
    SimRemote::Request request;
    request.unitId = parts.unitId;
    request.pdu = parts.pdu;
    request.framing = endpoint->framing();
    request.broadcast = isSerialLine(request.framing) && parts.unitId == 0;
    request.endpoint = endpoint->name();
    request.peer = peer;
    request.receivedNs = receivedNs;
    // The request is in the journal from the moment it came (the answer may take a while, and
    // requests of other clients come meanwhile).
    Pending pending{QPointer<SimEndpoint>(endpoint), peer, adu.toByteArray(), parts, receivedNs, intervalNs,
                    logArrival(endpoint, peer, adu, TrafficVerdict::Ok, receivedNs), sink};
    QPointer<Simulator> self(this);
    m_remote->forward(request, [self, pending = std::move(pending)](const SimRemote::Answer &answer) {
        if (self && pending.endpoint)
            self->finishForward(pending, answer);
    });
}

void Simulator::finishForward(const Pending &pending, const SimRemote::Answer &answer)
{
    SimEndpoint *endpoint = pending.endpoint;
    const AduParts &parts = pending.parts;
    const bool broadcast = isSerialLine(endpoint->framing()) && parts.unitId == 0;
    if (!answer.reply.hasAnswer() && answer.exactAdu.isEmpty()) {
        logUnanswered(endpoint, pending.trafficId, broadcast, monotonicNowNs());
        emitEntry(endpoint, pending.peer, parts.unitId, pending.adu, {}, SimLogEntry::Verdict::NoAnswer, answer.reply.note);
        FaultPlan silence;
        silence.drop = true;
        pending.sink(silence);
        return;
    }
    const QByteArray bytes = !answer.exactAdu.isEmpty()
                                 ? answer.exactAdu
                                 : AduBuilder::complete(answer.reply.pdu, AduOptions{endpoint->framing(), parts.unitId, parts.transactionId, 0});
    const AduParts sent = AduBuilder::parse(bytes, endpoint->framing());
    const bool exception = !sent.pdu.isEmpty() && (quint8(sent.pdu.at(0)) & 0x80) != 0;
    const SimLogEntry::Verdict verdict = exception ? SimLogEntry::Verdict::Exception : SimLogEntry::Verdict::Answered;
    FaultPlan plan;
    if (m_faultHook) {
        SimExchange exchange;
        exchange.endpoint = endpoint->name();
        exchange.peer = pending.peer;
        exchange.framing = endpoint->framing();
        exchange.unitId = parts.unitId;
        exchange.routedUnitId = parts.unitId;
        exchange.transactionId = parts.transactionId;
        exchange.requestAdu = pending.adu;
        exchange.requestPdu = parts.pdu;
        exchange.reply = answer.reply;
        exchange.responseAdu = bytes;
        exchange.responseDelayNs = 0; // the device's own time has passed already
        exchange.responseDelayFixed = true;
        exchange.receivedNs = pending.receivedNs;
        exchange.intervalNs = pending.intervalNs;
        plan = m_faultHook(exchange);
    } else {
        plan.chunks.append(ResponseChunk{bytes, 0});
    }
    plan.trafficId = pending.trafficId;
    emitEntry(endpoint, pending.peer, parts.unitId, pending.adu, bytes, verdict, answer.reply.note, plan.faults);
    noteFaultPlan(endpoint, plan);
    pending.sink(plan);
}

} // namespace mbscope
