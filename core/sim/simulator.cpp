#include "sim/simulator.h"
#include "protocol/framingtraits.h"

#include "traffic/trafficlog.h"
#include "protocol/adubuilder.h"
#include "protocol/delimitedframer.h"
#include "sim/lineresponder.h"
#include "script/scripthost.h"
#include "sim/simprocessor.h"
#include "sim/simscriptreply.h"
#include "sim/simendpoint.h"
#include "sim/simunit.h"
#include "sim/simremote.h"
#include "transport/linkurl.h"
#include "transport/monotonicclock.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>

namespace mbscope {

namespace {

TrafficVerdict trafficVerdictOf(SimLogEntry::Verdict verdict)
{
    switch (verdict) {
    case SimLogEntry::Verdict::Answered: return TrafficVerdict::Ok;
    case SimLogEntry::Verdict::Exception: return TrafficVerdict::Exception;
    case SimLogEntry::Verdict::NoAnswer: return TrafficVerdict::Broadcast;
    case SimLogEntry::Verdict::UnknownUnit: return TrafficVerdict::Unexpected;
    case SimLogEntry::Verdict::ChecksumError: return TrafficVerdict::CrcError;
    case SimLogEntry::Verdict::Malformed: return TrafficVerdict::Malformed;
    default: return TrafficVerdict::Garbage;
    }
}

QString hex4(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).toUpper().rightJustified(4, QLatin1Char('0'));
}

} // namespace

Simulator::Simulator(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<SimLogEntry>();
}

Simulator::~Simulator()
{
    // Endpoints report their last connections closing: delete them while the units and the log
    // still exist, not later as children; and say nothing any more (whoever listened may be
    // gone already).
    blockSignals(true);
    m_trafficLog = nullptr;
    const QList<SimEndpoint *> all = m_endpoints;
    m_endpoints.clear();
    for (SimEndpoint *endpoint : all) {
        endpoint->stop();
        delete endpoint;
    }
}

SimUnit *Simulator::addUnit(quint8 id)
{
    return adoptUnit(std::make_unique<SimUnit>(id));
}

SimUnit *Simulator::adoptUnit(std::unique_ptr<SimUnit> unit)
{
    if (!unit || unit->id() == 0 || m_units.count(unit->id()) != 0)
        return nullptr;
    const quint8 id = unit->id();
    Slot slot;
    slot.unit = std::move(unit);
    slot.processor = std::make_unique<SimProcessor>(slot.unit.get());
    return m_units.emplace(id, std::move(slot)).first->second.unit.get();
}

void Simulator::removeUnit(quint8 id)
{
    m_units.erase(id);
}

SimUnit *Simulator::unit(quint8 id) const
{
    const auto it = m_units.find(id);
    return it == m_units.end() ? nullptr : it->second.unit.get();
}

QList<quint8> Simulator::unitIds() const
{
    QList<quint8> ids;
    for (const auto &entry : m_units)
        ids.append(entry.first);
    return ids;
}

void Simulator::setScript(quint8 unitId, ScriptHost *script)
{
    if (const auto it = m_units.find(unitId); it != m_units.end())
        it->second.script = script;
}

ScriptHost *Simulator::script(quint8 unitId) const
{
    const auto it = m_units.find(unitId);
    return it == m_units.end() ? nullptr : it->second.script;
}

void Simulator::closeEndpoint(SimEndpoint *endpoint)
{
    if (!m_endpoints.removeOne(endpoint))
        return;
    endpoint->stop();
    m_trafficLinks.remove(endpoint);
    m_lastArrivalNs.remove(endpoint);
    endpoint->deleteLater();
}

void Simulator::closeAll()
{
    const QList<SimEndpoint *> all = m_endpoints;
    for (SimEndpoint *endpoint : all)
        closeEndpoint(endpoint);
}

void Simulator::setTrafficLog(TrafficLog *log)
{
    m_trafficLog = log;
    m_trafficLinks.clear();
    m_trafficPeers.clear();
}

Simulator::SlotList Simulator::slotsOf(const SimEndpoint *endpoint)
{
    SlotList out;
    const QList<quint8> &only = endpoint->options().units;
    for (auto &entry : m_units) {
        if (only.isEmpty() || only.contains(entry.first))
            out.append(&entry.second);
    }
    return out;
}

std::optional<SimReply> Simulator::limitReply(const QByteArray &pdu, qint64 receivedNs, bool *silent)
{
    *silent = false;
    const quint8 function = quint8(pdu.at(0));
    if (m_limits.minGapMs > 0 && m_lastTakenNs != 0) {
        const double gapMs = double(receivedNs - m_lastTakenNs) / 1e6;
        if (gapMs < m_limits.minGapMs) {
            // Which limit refused it and by how much, as the CLI's line and the window's log show.
            const QString note = QStringLiteral("refused by minGapMs: %1 ms after the last request taken, minGapMs is %2")
                                     .arg(QString::number(gapMs, 'f', 1), QString::number(m_limits.minGapMs));
            if (m_limits.tooSoon == DeviceLimits::TooSoon::Silent) {
                *silent = true;
                return SimReply::silent(note);
            }
            // V1.1b3 section 7: 06, server device busy.
            return SimReply::exception(function, 0x06, note);
        }
    }
    m_lastTakenNs = receivedNs;
    // 01-04, 0F, 10 and 17 carry their (read) quantity in bytes 3-4 of the PDU.
    if (const auto it = m_limits.maxQuantity.constFind(function); it != m_limits.maxQuantity.constEnd() && pdu.size() >= 5) {
        const int quantity = quint8(pdu.at(3)) << 8 | quint8(pdu.at(4));
        if (quantity > *it)
            return SimReply::exception(function, 0x03, QStringLiteral("refused by maxQuantity: quantity %1 of function %3, "
                                                                      "maxQuantity is %2")
                                                           .arg(quantity)
                                                           .arg(*it)
                                                           .arg(QString::number(function, 16).toUpper().rightJustified(2, QLatin1Char('0'))));
    }
    return std::nullopt;
}

qint64 Simulator::intervalSince(const SimEndpoint *endpoint, qint64 receivedNs)
{
    auto it = m_lastArrivalNs.find(endpoint);
    const qint64 interval = it == m_lastArrivalNs.end() ? -1 : receivedNs - *it;
    m_lastArrivalNs.insert(endpoint, receivedNs);
    return interval;
}

bool Simulator::warmingUp(SimEndpoint *endpoint, const QString &peer, int unitId, QByteArrayView adu, qint64 receivedNs,
                          qint64 connectedNs)
{
    if (m_limits.warmUpMs <= 0)
        return false;
    const qint64 since = connectedNs != 0 ? connectedNs : endpoint->startedNs();
    const double upMs = double(receivedNs - since) / 1e6;
    if (upMs >= m_limits.warmUpMs)
        return false;
    log(endpoint, peer, unitId, adu, {}, SimLogEntry::Verdict::NoAnswer,
        QStringLiteral("refused by warmUpMs: %1 ms after connecting, warmUpMs is %2")
            .arg(QString::number(upMs, 'f', 1), QString::number(m_limits.warmUpMs)));
    return true;
}

std::optional<LineAnswer> Simulator::lineScriptAnswer(const QByteArray &body, int unitId, qint64 *delayNs)
{
    const ScriptAnswer a = m_lineScript->frame(body);
    LineAnswer out;
    out.rule = m_lineScript->settings().name;
    out.unitId = unitId;
    *delayNs = a.delayNs;
    switch (a.kind) {
    case ScriptAnswer::Kind::Normal:
        if (!m_lineTable.isEmpty())
            return std::nullopt;
        out.note = out.rule + QStringLiteral(": onFrame returned undefined and the profile has no table: no answer");
        return out;
    case ScriptAnswer::Kind::Adu:
        out.matched = true;
        out.answers = true;
        out.bytes = a.bytes;
        return out;
    case ScriptAnswer::Kind::Failed:
        *delayNs = -1;
        if (m_lineScript->settings().onError == ScriptSettings::OnError::Normal && !m_lineTable.isEmpty())
            return std::nullopt;
        out.note = QStringLiteral("script error (no answer): ") + a.note;
        return out;
    default:
        // null, {silent: true}; an exception or a PDU has no meaning on a line protocol
        out.matched = a.kind == ScriptAnswer::Kind::Silence;
        out.note = a.kind == ScriptAnswer::Kind::Silence
                       ? out.rule + QStringLiteral(": no answer")
                       : out.rule + QStringLiteral(": onFrame answers with text or bytes, null or undefined (exceptions and PDUs are Modbus): no answer");
        return out;
    }
}

FaultPlan Simulator::handleLine(SimEndpoint *endpoint, QByteArrayView frame, FrameStatus status, const QString &peer,
                                qint64 receivedNs, qint64 connectedNs)
{
    FaultPlan silence;
    silence.drop = true;
    const DelimitedFraming &framing = endpoint->url().delimited;
    if (status != FrameStatus::Valid) {
        log(endpoint, peer, -1, frame, {}, SimLogEntry::Verdict::ChecksumError,
            QStringLiteral("%1 checksum wrong: discarded").arg(DelimitedFramer::checksumName(framing.checksum)));
        return silence;
    }
    const qint64 intervalNs = intervalSince(endpoint, receivedNs);
    if (warmingUp(endpoint, peer, -1, frame, receivedNs, connectedNs))
        return silence;
    const QByteArrayView body = framing.checksum == DelimitedChecksum::None ? frame : frame.first(std::max<qsizetype>(0, frame.size() - 1));
    const SlotList units = slotsOf(endpoint);
    std::optional<LineAnswer> scripted;
    qint64 scriptDelayNs = -1;
    if (m_lineScript && m_lineScript->handlesFrames())
        scripted = lineScriptAnswer(body.toByteArray(), units.isEmpty() ? -1 : units.first()->unit->id(), &scriptDelayNs);
    const LineAnswer answer = scripted ? *scripted : LineResponder::respond(m_lineTable, body, [&units](int id) -> SimUnit * {
        for (Slot *slot : units) {
            if (id < 0 || slot->unit->id() == id)
                return slot->unit.get();
        }
        return nullptr;
    });
    if (!answer.answers) {
        log(endpoint, peer, answer.unitId, frame, {},
            answer.unitMissing ? SimLogEntry::Verdict::UnknownUnit : SimLogEntry::Verdict::NoAnswer,
            answer.note.isEmpty() ? answer.rule + QStringLiteral(": no answer") : answer.note);
        return silence;
    }
    const qint64 delayNs = scriptDelayNs >= 0 ? scriptDelayNs
                           : unit(quint8(answer.unitId)) ? unit(quint8(answer.unitId))->responseDelayNs() : 0;
    if (bool limitSilent = false; const auto refused = limitReply(QByteArray(1, '\0'), receivedNs, &limitSilent)) {
        // A delimited device has no exception answers: too soon means no answer.
        log(endpoint, peer, answer.unitId, frame, {}, SimLogEntry::Verdict::NoAnswer, refused->note);
        return silence;
    }
    const QByteArray bytes = DelimitedFramer::complete(framing, answer.bytes);
    FaultPlan plan;
    if (m_faultHook) {
        SimExchange exchange;
        exchange.endpoint = endpoint->name();
        exchange.peer = peer;
        exchange.framing = endpoint->framing();
        exchange.delimited = true;
        exchange.unitId = quint8(answer.unitId);
        exchange.routedUnitId = quint8(answer.unitId);
        exchange.requestAdu = frame.toByteArray();
        exchange.responseAdu = bytes;
        exchange.responseDelayNs = delayNs;
        exchange.responseDelayFixed = scriptDelayNs >= 0;
        exchange.receivedNs = receivedNs;
        exchange.intervalNs = intervalNs;
        exchange.reply = SimReply::normal(bytes);
        plan = m_faultHook(exchange);
    } else {
        plan.chunks.append(ResponseChunk{bytes, delayNs});
    }
    const QString note = answer.note.isEmpty() ? answer.rule : answer.rule + QStringLiteral(": ") + answer.note;
    plan.trafficId = log(endpoint, peer, answer.unitId, frame, bytes, SimLogEntry::Verdict::Answered, note, plan.faults);
    noteFaultPlan(endpoint, plan);
    return plan;
}

bool Simulator::acceptModbusFrame(SimEndpoint *endpoint, QByteArrayView adu, FrameStatus status, const QString &peer,
                                  const SlotList &units, AduParts *out)
{
    const Framing framing = endpoint->framing();
    const bool serial = isSerialLine(framing);
    *out = AduBuilder::parse(adu, framing);
    const AduParts &parts = *out;
    const int unitForLog = parts.complete || !parts.pdu.isEmpty() ? parts.unitId : -1;

    if (serial) {
        // Serial Line V1.02, 2.5.1.2 / 2.5.2.2: a frame with a wrong CRC or LRC is discarded
        // silently; the bus communication error counter counts it.
        if (status != FrameStatus::Valid || !parts.complete || !parts.checksumValid()) {
            for (Slot *slot : units)
                SimProcessor::noteCommError(*slot->unit);
            const bool badChecksum = parts.complete && parts.checksumPresent && !parts.checksumValid();
            const QString reason = badChecksum ? QStringLiteral("%1 %2, expected %3: discarded")
                                                     .arg(framing == Framing::Rtu ? QStringLiteral("CRC") : QStringLiteral("LRC"),
                                                          hex4(parts.checksum), hex4(parts.expectedChecksum))
                                               : (parts.error.isEmpty() ? QStringLiteral("incomplete frame: discarded")
                                                                        : parts.error + QStringLiteral(": discarded"));
            log(endpoint, peer, unitForLog, adu, {},
                badChecksum ? SimLogEntry::Verdict::ChecksumError : SimLogEntry::Verdict::Malformed, reason);
            return false;
        }
    } else if (!parts.complete || parts.protocolId != 0 || !parts.lengthMatches) {
        // Messaging on TCP/IP V1.0b, 3.1.3: protocol id 0 is Modbus; the length counts what follows.
        QString reason = parts.error;
        if (reason.isEmpty() && parts.protocolId != 0)
            reason = QStringLiteral("MBAP protocol id %1, expected 0 (Modbus)").arg(parts.protocolId);
        if (reason.isEmpty())
            reason = QStringLiteral("MBAP length %1 does not match the %2 bytes that follow the length field")
                         .arg(parts.length)
                         .arg(adu.size() - 6);
        log(endpoint, peer, unitForLog, adu, {}, SimLogEntry::Verdict::Malformed, reason + QStringLiteral(": dropped"));
        return false;
    }
    if (parts.pdu.isEmpty()) {
        log(endpoint, peer, unitForLog, adu, {}, SimLogEntry::Verdict::Malformed, QStringLiteral("no function code: dropped"));
        return false;
    }
    return true;
}

FaultPlan Simulator::handleFrame(SimEndpoint *endpoint, QByteArrayView adu, FrameStatus status,
                                 const QString &peer, qint64 receivedNs, qint64 connectedNs)
{
    if (endpoint->url().delimited.enabled)
        return handleLine(endpoint, adu, status, peer, receivedNs, connectedNs);
    FaultPlan silence;
    silence.drop = true;
    const Framing framing = endpoint->framing();
    const bool serial = isSerialLine(framing);
    const SlotList units = slotsOf(endpoint);
    AduParts parts;
    if (!acceptModbusFrame(endpoint, adu, status, peer, units, &parts))
        return silence;
    const qint64 intervalNs = intervalSince(endpoint, receivedNs);
    if (warmingUp(endpoint, peer, parts.unitId, adu, receivedNs, connectedNs))
        return silence;
    for (Slot *slot : units)
        SimProcessor::noteBusMessage(*slot->unit);

    const quint8 unitId = parts.unitId;
    if (serial && unitId == 0 && !(endpoint->options().answerBroadcasts && !units.isEmpty())) {
        for (Slot *slot : units)
            slot->processor->process(parts.pdu, true);
        log(endpoint, peer, 0, adu, {}, SimLogEntry::Verdict::NoAnswer,
            QStringLiteral("broadcast to %1 unit(s): processed, never answered (Serial Line V1.02, 2.1)").arg(units.size()));
        return silence;
    }
    Slot *target = nullptr;
    for (Slot *slot : units) {
        if (slot->unit->id() == unitId)
            target = slot;
    }
    if (!target && serial && unitId == 0 && endpoint->options().answerBroadcasts && !units.isEmpty())
        target = units.first(); // a deviation asked for: the broadcast answered as a request
    if (!target && !serial && endpoint->options().directUnitIds && (unitId == 0 || unitId == 0xFF) && !units.isEmpty())
        target = units.first();
    // Many TCP servers answer whatever unit id is asked as their one device.
    if (!target && !endpoint->url().isSerial() && !units.isEmpty()
        && endpoint->options().unknownUnit == SimEndpointOptions::UnknownUnit::FirstUnit)
        target = units.first();

    SimReply reply;
    qint64 delayNs = 0;
    QByteArray exactAnswer; // a script's "adu": sent as it is
    bool delayFixed = false; // a script's "delay"
    SimLogEntry::Verdict verdict = SimLogEntry::Verdict::Answered;
    if (!target) {
        auto policy = endpoint->options().unknownUnit;
        if (policy == SimEndpointOptions::UnknownUnit::Auto || policy == SimEndpointOptions::UnknownUnit::FirstUnit)
            policy = endpoint->url().isSerial() ? SimEndpointOptions::UnknownUnit::Ignore
                                                : SimEndpointOptions::UnknownUnit::Exception;
        if (policy == SimEndpointOptions::UnknownUnit::Ignore) {
            log(endpoint, peer, unitId, adu, {}, SimLogEntry::Verdict::UnknownUnit,
                QStringLiteral("no unit %1 here: ignored").arg(unitId));
            return silence;
        }
        // V1.1b3 section 7: 0B, gateway target device failed to respond.
        reply = SimReply::exception(quint8(parts.pdu[0]) & 0x7F, 0x0B,
                                    QStringLiteral("no unit %1 here: exception 0B (gateway target device failed to respond)").arg(unitId));
        verdict = SimLogEntry::Verdict::UnknownUnit;
    } else if (bool limitSilent = false; const auto refused = limitReply(parts.pdu, receivedNs, &limitSilent)) {
        reply = *refused;
        delayNs = target->unit->responseDelayNs();
        verdict = limitSilent ? SimLogEntry::Verdict::NoAnswer : SimLogEntry::Verdict::Exception;
    } else if (target->script) {
        SimScriptReply scripted = SimScriptReply::make(
            *target->script, *target->processor,
            {unitId, parts.pdu, endpoint->name(), peer, serial ? -1 : int(parts.transactionId)});
        reply = scripted.reply;
        delayNs = scripted.delayNs >= 0 ? scripted.delayNs : target->unit->responseDelayNs();
        delayFixed = scripted.delayNs >= 0;
        exactAnswer = scripted.adu;
        if (reply.kind == SimReply::Kind::Exception)
            verdict = SimLogEntry::Verdict::Exception;
        else if (!reply.hasAnswer())
            verdict = SimLogEntry::Verdict::NoAnswer;
    } else {
        reply = target->processor->process(parts.pdu, false);
        delayNs = target->unit->responseDelayNs();
        if (reply.kind == SimReply::Kind::Exception)
            verdict = SimLogEntry::Verdict::Exception;
        else if (!reply.hasAnswer())
            verdict = SimLogEntry::Verdict::NoAnswer;
    }
    if (!reply.hasAnswer()) {
        log(endpoint, peer, unitId, adu, {}, verdict, reply.note);
        return silence;
    }
    const QByteArray answer = exactAnswer.isEmpty() ? AduBuilder::complete(reply.pdu, AduOptions{framing, unitId, parts.transactionId, 0}) : exactAnswer;
    FaultPlan plan;
    if (m_faultHook) {
        SimExchange exchange;
        exchange.endpoint = endpoint->name();
        exchange.peer = peer;
        exchange.framing = framing;
        exchange.unitId = unitId;
        exchange.routedUnitId = target ? target->unit->id() : unitId;
        exchange.transactionId = parts.transactionId;
        exchange.requestAdu = adu.toByteArray();
        exchange.requestPdu = parts.pdu;
        exchange.reply = reply;
        exchange.responseAdu = answer;
        exchange.responseDelayNs = delayNs;
        exchange.responseDelayFixed = delayFixed;
        exchange.receivedNs = receivedNs;
        exchange.intervalNs = intervalNs;
        plan = m_faultHook(exchange);
    } else {
        plan.chunks.append(ResponseChunk{answer, delayNs});
    }
    // A device that hangs up after each answer (limits.closesAfterAnswer): on connections only.
    if (m_limits.closesAfterAnswer && !plan.drop && !plan.closeBefore && !plan.closeAfter && !endpoint->url().isSerial()
        && !endpoint->url().isDatagram()) {
        plan.closeAfter = true;
        plan.closeReason = QStringLiteral("closesAfterAnswer: the device hangs up after each answer");
    }
    plan.trafficId = log(endpoint, peer, unitId, adu, answer, verdict, reply.note, plan.faults);
    noteFaultPlan(endpoint, plan);
    return plan;
}

void Simulator::noteSkipped(SimEndpoint *endpoint, const SkippedBytes &skipped, const QString &peer)
{
    if (isSerialLine(endpoint->framing())) {
        for (Slot *slot : slotsOf(endpoint)) {
            if (skipped.reason == SkipReason::TooLong)
                SimProcessor::noteOverrun(*slot->unit);
            else if (skipped.reason == SkipReason::ChecksumMismatch || skipped.reason == SkipReason::Incomplete)
                SimProcessor::noteCommError(*slot->unit);
        }
    }
    log(endpoint, peer, -1, skipped.bytes, {}, SimLogEntry::Verdict::Garbage,
        QStringLiteral("%1 byte(s) skipped: %2").arg(skipped.count()).arg(QLatin1String(skipReasonName(skipped.reason))));
}

void Simulator::noteConnection(SimEndpoint *endpoint, const QString &peer, SimLogEntry::Verdict verdict,
                               const QString &reason)
{
    log(endpoint, peer, -1, {}, {}, verdict, reason);
}

void Simulator::noteSent(SimEndpoint *endpoint, const QByteArray &bytes, quint64 trafficId)
{
    if (!m_trafficLog)
        return;
    // An exception answer says so in its function code (V1.1b3, 7: code + 0x80).
    const AduParts parts = AduBuilder::parse(bytes, endpoint->framing());
    const bool exception = !parts.pdu.isEmpty() && (quint8(parts.pdu.at(0)) & 0x80) != 0;
    m_trafficLog->append(monotonicNowNs(), TrafficDirection::Out, trafficLink(endpoint),
                         exception ? TrafficVerdict::Exception : TrafficVerdict::Ok, trafficId, bytes);
}

void Simulator::noteFaultPlan(SimEndpoint *endpoint, const FaultPlan &plan)
{
    if (!m_trafficLog || plan.trafficId == 0)
        return;
    const bool silent = plan.drop || plan.closeBefore;
    if (silent)
        m_trafficLog->append(monotonicNowNs(), TrafficDirection::Out, trafficLink(endpoint), TrafficVerdict::Timeout,
                             plan.trafficId, {});
    if (plan.faults.isEmpty())
        return;
    QJsonObject note{{QStringLiteral("faults"), QJsonArray::fromStringList(plan.faults)}};
    if (plan.drop)
        note.insert(QStringLiteral("drop"), true);
    if (plan.closeBefore || plan.closeAfter)
        note.insert(QStringLiteral("close"), plan.closeBefore ? QStringLiteral("before") : QStringLiteral("after"));
    if (!silent) {
        qint64 delayNs = 0;
        for (const ResponseChunk &chunk : plan.chunks)
            delayNs += chunk.delayNs;
        note.insert(QStringLiteral("chunks"), plan.chunks.size());
        note.insert(QStringLiteral("delay_ms"), double(delayNs) / 1e6);
    }
    m_trafficLog->annotate(trafficLink(endpoint), plan.trafficId, monotonicNowNs(),
                           QJsonDocument(note).toJson(QJsonDocument::Compact));
}

quint16 Simulator::trafficLink(const SimEndpoint *endpoint)
{
    auto it = m_trafficLinks.find(endpoint);
    if (it == m_trafficLinks.end())
        it = m_trafficLinks.insert(endpoint, m_trafficLog->addLink(endpoint->name()));
    return *it;
}

quint64 Simulator::logArrival(SimEndpoint *endpoint, const QString &peer, QByteArrayView request, TrafficVerdict verdict,
                              qint64 tNs)
{
    if (!m_trafficLog || request.isEmpty())
        return 0;
    // Skipped bytes are not a request: no id, no outcome.
    const quint64 id = verdict == TrafficVerdict::Garbage ? 0 : ++m_lastTrafficId;
    const quint16 link = trafficLink(endpoint);
    // Which client this request came from, when it is another than the last one's: the
    // journal's endpoints note (journalendpoints.h). A serial line's URL names its port.
    if (id != 0 && !endpoint->url().isSerial()) {
        QString &last = m_trafficPeers[link];
        if (last != peer) {
            last = peer;
            const LinkUrl &bound = endpoint->boundUrl();
            const QString host = bound.host.contains(QLatin1Char(':')) ? QLatin1Char('[') + bound.host + QLatin1Char(']') : bound.host;
            m_trafficLog->setEndpoints(link, tNs, id, JournalEndpoints{peer, host + QLatin1Char(':') + QString::number(bound.port)});
        }
    }
    m_trafficLog->append(tNs, TrafficDirection::In, link, verdict, id, request);
    return id;
}

void Simulator::logUnanswered(SimEndpoint *endpoint, quint64 id, bool broadcast, qint64 tNs)
{
    // A request left unanswered: what its client saw, in the engine's way (an empty record).
    if (m_trafficLog && id != 0)
        m_trafficLog->append(tNs, TrafficDirection::Out, trafficLink(endpoint),
                             broadcast ? TrafficVerdict::Broadcast : TrafficVerdict::Timeout, id, {});
}

void Simulator::emitEntry(SimEndpoint *endpoint, const QString &peer, int unitId, QByteArrayView request,
                          const QByteArray &response, SimLogEntry::Verdict verdict, const QString &reason,
                          const QStringList &faults)
{
    SimLogEntry entry;
    entry.tNs = monotonicNowNs();
    entry.endpoint = endpoint->name();
    entry.peer = peer;
    entry.unitId = unitId;
    entry.request = request.toByteArray();
    entry.response = response;
    entry.verdict = verdict;
    entry.reason = reason;
    entry.faults = faults;
    Q_EMIT logged(entry);
}

quint64 Simulator::log(SimEndpoint *endpoint, const QString &peer, int unitId, QByteArrayView request,
                       const QByteArray &response, SimLogEntry::Verdict verdict, const QString &reason,
                       const QStringList &faults)
{
    const qint64 tNs = monotonicNowNs();
    const quint64 id = logArrival(endpoint, peer, request, trafficVerdictOf(verdict), tNs);
    if (response.isEmpty())
        logUnanswered(endpoint, id, verdict == SimLogEntry::Verdict::NoAnswer && unitId == 0, tNs);
    emitEntry(endpoint, peer, unitId, request, response, verdict, reason, faults);
    return id;
}

} // namespace mbscope

#include "moc_simulator.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
