#include "devicelimits.h"

namespace mbscope {

QString DeviceLimits::unknownUnitName(UnknownUnit policy)
{
    switch (policy) {
    case UnknownUnit::FirstUnit: return QStringLiteral("first");
    case UnknownUnit::Exception: return QStringLiteral("exception");
    case UnknownUnit::Silent: return QStringLiteral("silent");
    case UnknownUnit::Auto: break;
    }
    return QStringLiteral("auto");
}

} // namespace mbscope
