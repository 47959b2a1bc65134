#include "trafficfilter.h"

namespace mbscope {

void TrafficFilter::setVerdict(TrafficVerdict verdict, bool shown)
{
    const quint32 bit = quint32(1) << int(verdict);
    verdicts = shown ? (verdicts | bit) : (verdicts & ~bit);
}

bool TrafficFilter::showsVerdict(TrafficVerdict verdict) const
{
    return verdicts & (quint32(1) << int(verdict));
}

bool TrafficFilter::acceptsAll() const
{
    return unit < 0 && function < 0 && direction < 0 && (verdicts & kAllVerdicts) == kAllVerdicts;
}

bool TrafficFilter::accepts(const TrafficEntry &frame, const FrameKeys &keys) const
{
    if (direction >= 0 && int(frame.direction) != direction)
        return false;
    if (!showsVerdict(frame.verdict))
        return false;
    if (unit >= 0 && (!keys.valid || keys.unit != unit))
        return false;
    // An exception response carries the function code with its high bit set (V1.1b3, 7).
    if (function >= 0 && (!keys.valid || (keys.functionCode & 0x7F) != (function & 0x7F)))
        return false;
    return true;
}

} // namespace mbscope
