#include "tapforwarder.h"
#include "protocol/framingtraits.h"

#include "engine/enginecore.h"
#include "engine/enginerecorder.h"
#include "exchange/requestitem.h"
#include "exchange/transaction.h"
#include "protocol/adubuilder.h"
#include "replay/recordedwrite.h"
#include "tapmetrics.h"
#include "transport/monotonicclock.h"
#include "time/duration.h"

namespace mbscope {

namespace {

QByteArray frameFor(Framing framing, const QByteArray &pdu, quint8 unit)
{
    // MBAP's transaction id 0: the engine numbers it (RequestItem::engineNumbered).
    return AduBuilder::complete(pdu, AduOptions{framing, unit, 0, 0});
}

LinkUrl withoutTimeout(LinkUrl url)
{
    url.responseTimeoutMs = -1;
    return url;
}

} // namespace

TapForwarder::TapForwarder(const TapSettings &settings, QObject *parent)
    : QObject(parent), m_settings(settings)
{
}

TapForwarder::~TapForwarder()
{
    // The engines go first: nothing they record reaches a forwarder half gone.
    for (Target &target : m_targets) {
        target.core->recorder()->removeRecordListener(this);
        delete target.core;
    }
}

void TapForwarder::setTrafficLog(TrafficLog *log)
{
    m_log = log;
    for (Target &target : m_targets)
        target.core->setTrafficLog(log);
}

QList<LinkUrl> TapForwarder::targets() const
{
    QList<LinkUrl> out;
    for (const Target &target : m_targets)
        out.append(target.url);
    return out;
}

TapForwarder::Target &TapForwarder::targetFor(const LinkUrl &url)
{
    const LinkUrl key = withoutTimeout(url);
    for (Target &target : m_targets) {
        if (target.url == key)
            return target;
    }
    Target target;
    target.url = key;
    target.core = new EngineCore;
    target.core->setTarget(key, m_settings.engine);
    target.core->setTrafficLog(m_log);
    target.core->recorder()->addRecordListener(this);
    target.name = key.toString();
    const QString name = target.name;
    connect(target.core, &EngineCore::linkOpened, this, [this, name] { Q_EMIT targetOpened(name); });
    connect(target.core, &EngineCore::linkMessage, this, [this, name](const QString &message) { Q_EMIT targetMessage(name, message); });
    m_targets.push_back(target);
    return m_targets.back();
}

bool TapForwarder::exceptionsFor(Framing masterFraming) const
{
    switch (m_settings.noAnswer) {
    case TapSettings::NoAnswer::Exception: return true;
    case TapSettings::NoAnswer::Silence: return false;
    case TapSettings::NoAnswer::Auto: break;
    }
    return !isSerialLine(masterFraming);
}

SimRemote::Answer TapForwarder::nothing(Framing masterFraming, quint8 function, quint8 code, const QString &why) const
{
    Answer answer;
    if (exceptionsFor(masterFraming))
        answer.reply = SimReply::exception(function & 0x7F, code, why);
    else
        answer.reply = SimReply::silent(why);
    return answer;
}

void TapForwarder::forward(const Request &request, Done done)
{
    ++m_counters.requests;
    const quint8 function = request.pdu.isEmpty() ? 0 : quint8(request.pdu.at(0));
    const TapRoute *route = m_settings.routeFor(request.unitId);
    if (!route) {
        ++m_counters.noRoute;
        // V1.1b3 section 7: 0A, gateway path unavailable.
        done(nothing(request.framing, function, 0x0A,
                     QStringLiteral("no route serves unit %1").arg(request.unitId)));
        return;
    }
    if (m_settings.readOnly) {
        if (const std::optional<RecordedWrite> write = RecordedWrite::of(0, request.unitId, request.pdu)) {
            ++m_counters.refusedWrites;
            const QString what = QStringLiteral("read-only: %1 not forwarded").arg(write->text().section(QLatin1Char(' '), 3));
            Answer answer;
            answer.reply = request.broadcast || m_settings.refusal == TapSettings::Refusal::Silence
                               ? SimReply::silent(what)
                               : SimReply::exception(function & 0x7F, 0x01, what);
            done(answer);
            return;
        }
    }
    Target &target = targetFor(route->target);
    const quint8 deviceUnit = route->deviceUnitFor(request.unitId);
    const Framing deviceFraming = target.url.framing();
    RequestItem item = RequestItem::fromBytes(frameFor(deviceFraming, request.pdu, deviceUnit), deviceFraming);
    item.engineNumbered = item.rule == MatchRule::Mbap;
    item.timeoutMs = route->target.responseTimeoutMs > 0 ? route->target.responseTimeoutMs : m_settings.timeoutMs;
    // A write goes once, as its master sent it: a retry after a timeout could apply it twice
    // (the device may have acted and only its answer got lost). Reads are retried.
    const bool write = RecordedWrite::of(0, request.unitId, request.pdu).has_value();
    item.retries = write ? 0 : route->retries >= 0 ? route->retries : m_settings.retries;
    Waiting waiting;
    waiting.done = std::move(done);
    waiting.masterFraming = request.framing;
    waiting.deviceFraming = deviceFraming;
    waiting.passThrough = isSerialLine(request.framing) && request.framing == deviceFraming && deviceUnit == request.unitId;
    waiting.broadcast = request.broadcast || item.broadcast;
    waiting.function = function;
    waiting.masterUnit = request.unitId;
    waiting.receivedNs = request.receivedNs;
    waiting.target = target.name;
    waiting.core = target.core;
    if (!write && !waiting.broadcast)
        waiting.resend = item;
    if (waiting.broadcast)
        ++m_counters.broadcasts;
    ++m_counters.forwarded;
    const quint64 id = target.core->reserveId();
    m_waiting.insert(id, std::move(waiting));
    target.core->submit(item, id);
}

void TapForwarder::onRecord(const Transaction &transaction, quint64 /*tag*/)
{
    if (transaction.status == TransactionStatus::Late)
        return; // its request was answered (0B, or silence) already
    const auto it = m_waiting.find(transaction.id);
    if (it == m_waiting.end())
        return;
    Waiting waiting = std::move(*it);
    m_waiting.erase(it);
    if (transaction.status == TransactionStatus::LinkError && transaction.sentNs > 0 && waiting.resend) {
        // The request went and the link failed before the answer: a device that closes its
        // connection (after every answer, or idle) closed it as the request arrived. A read is
        // sent once more, on a new connection; the master sees an answer, not 0B.
        ++m_counters.resent;
        const RequestItem item = *std::exchange(waiting.resend, std::nullopt);
        EngineCore *core = waiting.core;
        const quint64 id = core->reserveId();
        m_waiting.insert(id, std::move(waiting));
        core->submit(item, id);
        return;
    }

    const auto device = QStringLiteral("device %1").arg(formatDuration(std::max<qint64>(0, transaction.latencyNs())));
    Answer answer;
    switch (transaction.status) {
    case TransactionStatus::Ok:
    case TransactionStatus::Exception:
    case TransactionStatus::Malformed:
    case TransactionStatus::Unexpected: {
        // Passed on unchanged: a malformed or unexpected answer is the device's, for the master
        // to judge, as it would without the tap.
        const AduParts parts = AduBuilder::parse(transaction.response, waiting.deviceFraming);
        if (parts.pdu.isEmpty()) {
            ++m_counters.damaged;
            answer = nothing(waiting.masterFraming, waiting.function, 0x0B,
                             QStringLiteral("the device's answer holds no PDU (%1): not passed on").arg(transaction.problem));
            break;
        }
        if (transaction.status == TransactionStatus::Exception)
            ++m_counters.exceptions;
        else
            ++m_counters.answered;
        m_counters.deviceLatencyNsSum += quint64(std::max<qint64>(0, transaction.latencyNs()));
        ++m_counters.deviceLatencyCount;
        if (m_metrics)
            m_metrics->observe(waiting.target, transaction.latencyNs(), monotonicNowNs() - waiting.receivedNs);
        if (waiting.passThrough)
            answer.exactAdu = transaction.response;
        else
            answer.reply = (quint8(parts.pdu.at(0)) & 0x80) != 0 ? SimReply{SimReply::Kind::Exception, parts.pdu,
                                                                             parts.pdu.size() > 1 ? quint8(parts.pdu.at(1)) : quint8(0), {}}
                                                                  : SimReply::normal(parts.pdu);
        answer.reply.note = transaction.status == TransactionStatus::Ok || transaction.status == TransactionStatus::Exception
                                ? device
                                : device + QStringLiteral(", ") + transaction.problem;
        break;
    }
    case TransactionStatus::CrcError:
        if (waiting.passThrough) {
            // The master sees the bad checksum, as it would on the line.
            ++m_counters.damaged;
            answer.exactAdu = transaction.response;
            answer.reply.note = device + QStringLiteral(", ") + transaction.problem + QStringLiteral(": passed on as it came");
            break;
        }
        ++m_counters.damaged;
        answer = nothing(waiting.masterFraming, waiting.function, 0x0B,
                         QStringLiteral("the device's answer failed its check (%1): not passed on").arg(transaction.problem));
        break;
    case TransactionStatus::Broadcast:
        answer.reply = SimReply::silent(QStringLiteral("broadcast forwarded to %1: nobody answers").arg(waiting.target));
        break;
    case TransactionStatus::Timeout:
        ++m_counters.noAnswer;
        answer = waiting.broadcast
                     ? Answer{SimReply::silent(QStringLiteral("broadcast forwarded to %1: nobody answers").arg(waiting.target)), {}}
                     : nothing(waiting.masterFraming, waiting.function, 0x0B,
                               QStringLiteral("%1 did not answer (%2)").arg(waiting.target, transaction.problem));
        break;
    case TransactionStatus::LinkError:
    case TransactionStatus::Late:
        ++m_counters.linkErrors;
        answer = nothing(waiting.masterFraming, waiting.function, 0x0B,
                         QStringLiteral("%1: %2").arg(waiting.target, transaction.problem));
        break;
    }
    if (waiting.broadcast && (answer.reply.hasAnswer() || !answer.exactAdu.isEmpty()))
        answer = Answer{SimReply::silent(QStringLiteral("a broadcast is never answered; the device's answer was not passed on")), {}};
    waiting.done(answer);
}

} // namespace mbscope

#include "moc_tapforwarder.cpp" // its meta-object code here: linked only with the class (docs/architecture.md)
