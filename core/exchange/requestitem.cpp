#include "requestitem.h"

#include "protocol/framingtraits.h"

#include "protocol/adubuilder.h"
#include "protocol/broadcastrule.h"
#include "protocol/dissector.h"
#include "transport/linkurl.h"

namespace mbscope {

namespace {

// Well formed but for being a read sent to unit 0, which is still a broadcast on the wire: every
// server takes it and none answers (Serial Line V1.02, 2.1); the report says it cannot be answered.
bool isWellFormedRequest(const QByteArray &bytes, Framing framing)
{
    DissectOptions options;
    options.framing = framing;
    options.direction = Direction::Request;
    const Dissection d = Dissector::dissect(bytes, options);
    if (d.isValid())
        return true;
    if (!BroadcastRule::isBroadcastRead(bytes, framing))
        return false;
    int errors = 0;
    for (const Field &f : d.fields.fields())
        errors += f.severity == Severity::Error ? 1 : 0;
    return errors == 1; // the unit id's, nothing else
}

} // namespace

RequestItem RequestItem::fromBytes(const QByteArray &bytes, Framing framing, bool delimited, const QString &name)
{
    RequestItem item;
    item.name = name;
    item.bytes = bytes;
    item.framing = framing;
    item.rule = MatchRule::NextFrame;
    if (delimited)
        return item;

    const AduParts parts = AduBuilder::parse(bytes, framing);
    if (parts.pdu.isEmpty())
        return item;
    item.unit = parts.unitId;
    item.functionCode = quint8(parts.pdu.at(0));
    const FramingTraits &traits = framingTraits(framing);
    if (traits.mbap) {
        item.rule = MatchRule::Mbap;
        item.transactionId = parts.transactionId;
    } else if (traits.serialLine) {
        item.rule = MatchRule::UnitFunction;
        // Only a well-formed frame to unit 0 is a broadcast: bytes mbscope judges malformed (MBAP
        // bytes sent to an RTU link start with a transaction id whose high byte is often 0) wait
        // for an answer like any request, and their verdict says what came back.
        item.broadcast = parts.unitId == 0 && isWellFormedRequest(bytes, framing);
    }
    return item;
}

RequestItem RequestItem::forLink(const QByteArray &bytes, const LinkUrl &url, const QString &name)
{
    RequestItem item = fromBytes(bytes, url.framing(), url.delimited.enabled, name);
    if (url.responseTimeoutMs > 0)
        item.timeoutMs = url.responseTimeoutMs;
    return item;
}

} // namespace mbscope
