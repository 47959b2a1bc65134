#include "responsematcher.h"

#include "protocol/adubuilder.h"

namespace mbscope {

namespace {

QString hexCode(quint8 code)
{
    return QStringLiteral("0x") + QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

int asciiByte(QByteArrayView frame, qsizetype at)
{
    if (at + 1 >= frame.size())
        return -1;
    const int high = AduBuilder::hexDigitValue(frame[at]);
    const int low = AduBuilder::hexDigitValue(frame[at + 1]);
    return high < 0 || low < 0 ? -1 : (high << 4 | low);
}

} // namespace

FrameKeys ResponseMatcher::keysOf(QByteArrayView frame, Framing framing)
{
    FrameKeys keys;
    switch (framing) {
    case Framing::Tcp:
    case Framing::Udp:
        // MBAP header (Messaging on TCP/IP V1.0b, 3.1.3): transaction id 0-1, unit id 6, then the PDU.
        if (frame.size() >= 8) {
            keys.valid = true;
            keys.transactionId = quint16(quint8(frame[0]) << 8 | quint8(frame[1]));
            keys.unit = quint8(frame[6]);
            keys.functionCode = quint8(frame[7]);
        }
        break;
    case Framing::Rtu:
        if (frame.size() >= 2) {
            keys.valid = true;
            keys.unit = quint8(frame[0]);
            keys.functionCode = quint8(frame[1]);
        }
        break;
    case Framing::Ascii: {
        // ':' then the unit id and the function code as two hex digits each (Serial Line V1.02, 2.5.2.1).
        const int unit = frame.size() > 0 && frame[0] == ':' ? asciiByte(frame, 1) : -1;
        const int function = unit >= 0 ? asciiByte(frame, 3) : -1;
        if (function >= 0) {
            keys.valid = true;
            keys.unit = quint8(unit);
            keys.functionCode = quint8(function);
        }
        break;
    }
    case Framing::Pdu:
    case Framing::Auto:
        break;
    }
    return keys;
}

bool ResponseMatcher::answersFunction(quint8 requestFunction, quint8 responseFunction)
{
    return responseFunction == requestFunction
        || (requestFunction < 0x80 && responseFunction == (requestFunction | 0x80));
}

ResponseMatcher::Result ResponseMatcher::match(const RequestItem &request, QByteArrayView frame)
{
    if (request.rule == MatchRule::NextFrame)
        return Result{Outcome::Match, {}};
    return match(request, keysOf(frame, request.framing));
}

ResponseMatcher::Result ResponseMatcher::match(const RequestItem &request, const FrameKeys &keys)
{
    if (request.rule == MatchRule::NextFrame)
        return Result{Outcome::Match, {}};
    if (!keys.valid)
        return Result{Outcome::NoKeys, request.rule == MatchRule::Mbap
                                           ? QStringLiteral("the answer is too short for an MBAP header and a function code (8 bytes)")
                                           : QStringLiteral("the answer is too short for a unit id and a function code")};
    if (request.rule == MatchRule::Mbap && keys.transactionId != request.transactionId)
        return Result{Outcome::WrongTransactionId,
                      QStringLiteral("transaction id %1 does not match the request's %2").arg(keys.transactionId).arg(request.transactionId)};
    if (keys.unit != request.unit)
        return Result{Outcome::WrongUnit,
                      QStringLiteral("unit %1 does not match the request's unit %2").arg(keys.unit).arg(request.unit)};
    if (!answersFunction(request.functionCode, keys.functionCode)) {
        QString problem = QStringLiteral("function code %1 does not answer the request's %2")
                              .arg(hexCode(keys.functionCode), hexCode(request.functionCode));
        if (request.functionCode < 0x80)
            problem += QStringLiteral(" (nor is it its exception %1)").arg(hexCode(quint8(request.functionCode | 0x80)));
        return Result{Outcome::WrongFunction, problem};
    }
    return Result{Outcome::Match, {}};
}

} // namespace mbscope
