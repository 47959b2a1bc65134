#include "valueguess.h"

namespace mbscope {

QString ValueGuess::typeName() const
{
    if (bit)
        return QStringLiteral("bit");
    if (text)
        return QStringLiteral("ascii[%1]").arg(registers);
    return format.name();
}

} // namespace mbscope
