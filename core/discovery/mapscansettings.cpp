#include "mapscansettings.h"

namespace mbscope {

QString MapScanSettings::problem() const
{
    if (url.delimited.enabled)
        return QStringLiteral("a delimited link carries no Modbus: there is no register map to scan");
    if (firstAddress < 0 || lastAddress > 65535 || firstAddress > lastAddress)
        return QStringLiteral("addresses %1-%2: expected FIRST-LAST within 0-65535").arg(firstAddress).arg(lastAddress);
    if (step < 1 || step > 2000)
        return QStringLiteral("step %1: expected 1 to 2000 addresses").arg(step);
    for (const quint8 f : functions) {
        if (f < 1 || f > 4)
            return QStringLiteral("function %1 reads no table: the map is of 01, 02, 03 and 04").arg(f);
    }
    if (timeoutMs < 1 || gapMs < 0 || maxRequests < 1 || maxDurationMs < 1)
        return QStringLiteral("the timeout, the request limit and the time limit must be positive, the gap not negative");
    return {};
}

} // namespace mbscope
