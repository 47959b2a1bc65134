#include "valueguess.h"

namespace mbscope {

QString valueKindName(ValueKind kind)
{
    switch (kind) {
    case ValueKind::Constant: return QStringLiteral("constant");
    case ValueKind::Counter: return QStringLiteral("counter");
    case ValueKind::Measurement: return QStringLiteral("measurement");
    case ValueKind::Status: return QStringLiteral("status bits");
    }
    return QStringLiteral("constant");
}

QString ValueGuess::typeName() const
{
    if (bit)
        return QStringLiteral("bit");
    if (text)
        return QStringLiteral("ascii[%1]").arg(registers);
    return format.name();
}

} // namespace mbscope
