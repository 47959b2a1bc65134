#include "delayspec.h"

#include "sim/simrandom.h"

#include <algorithm>
#include <cmath>

namespace mbscope {

DelaySpec DelaySpec::fixed(double ms)
{
    DelaySpec spec;
    spec.ms = ms;
    return spec;
}

qint64 DelaySpec::sampleNs(SimRandom &random) const
{
    double drawn = 0;
    switch (kind) {
    case Kind::Fixed:
        drawn = ms;
        break;
    case Kind::Uniform:
        drawn = random.uniform(minMs, std::max(minMs, maxMs));
        break;
    case Kind::Normal:
        drawn = random.normal(meanMs, stddevMs);
        break;
    case Kind::Exponential:
        drawn = random.exponential(meanMs);
        break;
    case Kind::LogNormal:
        drawn = random.logNormal(meanMs, stddevMs);
        break;
    }
    drawn = std::max(drawn, std::max(0.0, minMs));
    if (maxMs >= 0)
        drawn = std::min(drawn, maxMs);
    return qint64(std::llround(drawn * 1e6));
}

double DelaySpec::nominalMs() const
{
    switch (kind) {
    case Kind::Fixed:
        return ms;
    case Kind::Uniform:
        return (minMs + std::max(minMs, maxMs)) / 2;
    case Kind::Normal:
    case Kind::Exponential:
    case Kind::LogNormal:
        return meanMs;
    }
    return 0;
}

QString DelaySpec::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Fixed:
        return QStringLiteral("fixed");
    case Kind::Uniform:
        return QStringLiteral("uniform");
    case Kind::Normal:
        return QStringLiteral("normal");
    case Kind::Exponential:
        return QStringLiteral("exponential");
    case Kind::LogNormal:
        return QStringLiteral("lognormal");
    }
    return QString();
}

} // namespace mbscope
