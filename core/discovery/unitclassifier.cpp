#include "unitclassifier.h"

#include "exchange/responsematcher.h"

namespace mbscope {

UnitProbe UnitClassifier::classify(quint8 unit, const Transaction &transaction, Framing framing,
                                   const QByteArray &bytesRead)
{
    UnitProbe probe;
    probe.unit = unit;
    probe.request = transaction.request;
    probe.response = transaction.response.isEmpty() ? bytesRead : transaction.response;
    probe.problem = transaction.problem;
    probe.latencyNs = transaction.latencyNs();

    // An echo fits a request's keys (same unit, same function), so the engine may have matched it
    // and found it malformed, or framed it as garbage: only the bytes tell.
    if (!transaction.request.isEmpty()
        && (transaction.response == transaction.request || bytesRead.startsWith(transaction.request))) {
        probe.kind = UnitProbeKind::Echo;
        probe.response = transaction.request;
        probe.problem = QStringLiteral("the bytes read back are the request");
        return probe;
    }

    switch (transaction.status) {
    case TransactionStatus::Ok:
        probe.kind = UnitProbeKind::Answers;
        break;
    case TransactionStatus::Exception:
        probe.exceptionCode = transaction.exceptionCode;
        if (transaction.exceptionCode == 0x0A)
            probe.kind = UnitProbeKind::GatewayPathUnavailable;
        else if (transaction.exceptionCode == 0x0B)
            probe.kind = UnitProbeKind::GatewayTargetFailed;
        else
            probe.kind = UnitProbeKind::Exception;
        break;
    case TransactionStatus::Unexpected: {
        const FrameKeys keys = ResponseMatcher::keysOf(transaction.response, framing);
        if (keys.valid && keys.unit != unit) {
            probe.kind = UnitProbeKind::WrongUnit;
            probe.answeredUnit = keys.unit;
        } else {
            probe.kind = UnitProbeKind::Garbage;
        }
        break;
    }
    case TransactionStatus::CrcError:
    case TransactionStatus::Malformed:
        probe.kind = UnitProbeKind::Garbage;
        break;
    case TransactionStatus::LinkError:
        probe.kind = UnitProbeKind::LinkError;
        break;
    case TransactionStatus::Timeout:
    case TransactionStatus::Late:
    case TransactionStatus::Broadcast:
        if (bytesRead.isEmpty()) {
            probe.kind = UnitProbeKind::Silent;
            probe.problem.clear();
        } else {
            probe.kind = UnitProbeKind::Garbage;
            probe.problem = QStringLiteral("%1 bytes read that made no answer").arg(bytesRead.size());
        }
        probe.latencyNs = -1;
        break;
    }
    if (probe.kind == UnitProbeKind::Answers)
        probe.problem.clear();
    return probe;
}

} // namespace mbscope
