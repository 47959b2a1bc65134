#include "unitscansettings.h"
#include "protocol/functionspec.h"

namespace mbscope {

QString UnitScanSettings::problem() const
{
    if (url.delimited.enabled)
        return QStringLiteral("a delimited link carries no Modbus: there are no unit ids to scan");
    if (firstUnit < 0 || firstUnit > 255 || lastUnit < 0 || lastUnit > 255)
        return QStringLiteral("unit ids are 0-255, %1-%2 given").arg(firstUnit).arg(lastUnit);
    if (firstUnit > lastUnit)
        return QStringLiteral("the first unit id %1 is above the last %2").arg(firstUnit).arg(lastUnit);
    if (firstUnit == 0 && url.framing() != Framing::Tcp && url.framing() != Framing::Udp)
        return QStringLiteral("unit 0 is the broadcast address on %1 framing: nobody answers it (its unit ids are 1-247: "
                              "start at 1)")
            .arg(framingName(url.framing()));
    if (lastUnit > 247 && url.framing() != Framing::Tcp && url.framing() != Framing::Udp)
        return QStringLiteral("unit ids 248-255 are reserved on %1 framing (Serial Line V1.02, 2.2; its unit ids are 1-247): "
                              "end at 247")
            .arg(framingName(url.framing()));
    if (function < 1 || function > 4)
        return QStringLiteral("function %1 is not a read: a scan asks with 01, 02, 03 or 04").arg(function);
    const int maxQuantity = QuantityLimits::maxQuantity(quint8(function));
    if (quantity < 1 || quantity > maxQuantity)
        return QStringLiteral("quantity %1 is out of range: function %2 reads 1-%3")
            .arg(quantity).arg(function).arg(maxQuantity);
    if (int(address) + quantity > 65536)
        return QStringLiteral("address %1 + quantity %2 runs past 65535").arg(address).arg(quantity);
    if (timeoutMs < 1)
        return QStringLiteral("the timeout must be at least 1 ms");
    if (gapMs < 0)
        return QStringLiteral("the gap cannot be negative");
    if (maxDurationMs < 1)
        return QStringLiteral("the time limit must be at least 1 ms");
    return {};
}

} // namespace mbscope
