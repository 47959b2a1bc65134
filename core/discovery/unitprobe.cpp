#include "unitprobe.h"

#include "protocol/functioncode.h"

namespace mbscope {

const char *unitProbeKindName(UnitProbeKind kind)
{
    switch (kind) {
    case UnitProbeKind::Answers: return "answers";
    case UnitProbeKind::Exception: return "exception";
    case UnitProbeKind::GatewayPathUnavailable: return "gateway_path_unavailable";
    case UnitProbeKind::GatewayTargetFailed: return "gateway_target_failed";
    case UnitProbeKind::Silent: return "silent";
    case UnitProbeKind::WrongUnit: return "wrong_unit";
    case UnitProbeKind::Garbage: return "garbage";
    case UnitProbeKind::Echo: return "echo";
    case UnitProbeKind::LinkError: return "link_error";
    }
    return "silent";
}

QString UnitProbe::summary() const
{
    const auto exception = [this] {
        return QStringLiteral("exception %1 (%2)")
            .arg(QStringLiteral("%1").arg(exceptionCode, 2, 16, QLatin1Char('0')).toUpper())
            .arg(QString::fromLatin1(exceptionName(exceptionCode)));
    };
    switch (kind) {
    case UnitProbeKind::Answers: return QStringLiteral("answers");
    case UnitProbeKind::Exception: return exception();
    case UnitProbeKind::GatewayPathUnavailable:
        return exception() + QStringLiteral(": the gateway has no path to this unit");
    case UnitProbeKind::GatewayTargetFailed:
        return exception() + QStringLiteral(": nothing answered behind the gateway");
    case UnitProbeKind::Silent: return QStringLiteral("silent");
    case UnitProbeKind::WrongUnit: return QStringLiteral("answered as unit %1").arg(answeredUnit);
    case UnitProbeKind::Garbage: return QStringLiteral("garbage: %1").arg(problem);
    case UnitProbeKind::Echo: return QStringLiteral("echo of the request");
    case UnitProbeKind::LinkError: return QStringLiteral("link error: %1").arg(problem);
    }
    return {};
}

} // namespace mbscope
