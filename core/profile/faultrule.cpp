#include "faultrule.h"

#include <QtCore/QStringList>

namespace mbscope {

namespace {

struct KindName {
    FaultRule::Kind kind;
    const char *name;
};

constexpr KindName kKindNames[] = {
    {FaultRule::Kind::Delay, "delay"},
    {FaultRule::Kind::Drop, "drop"},
    {FaultRule::Kind::WrongChecksum, "wrongChecksum"},
    {FaultRule::Kind::WrongTransactionId, "wrongTransactionId"},
    {FaultRule::Kind::WrongUnit, "wrongUnit"},
    {FaultRule::Kind::Exception, "exception"},
    {FaultRule::Kind::FewerRegisters, "fewerRegisters"},
    {FaultRule::Kind::Chunks, "chunks"},
    {FaultRule::Kind::Trickle, "trickle"},
    {FaultRule::Kind::Junk, "junk"},
    {FaultRule::Kind::Duplicate, "duplicate"},
    {FaultRule::Kind::Close, "close"},
    {FaultRule::Kind::Noise, "noise"},
};

} // namespace

QString FaultRule::kindName(Kind kind)
{
    for (const KindName &k : kKindNames) {
        if (k.kind == kind)
            return QString::fromLatin1(k.name);
    }
    return QString();
}

std::optional<FaultRule::Kind> FaultRule::kindFromName(QStringView name)
{
    for (const KindName &k : kKindNames) {
        if (name == QLatin1String(k.name))
            return k.kind;
    }
    return std::nullopt;
}

double FaultRule::probabilityAt(double intervalMs) const
{
    if (byIntervalMs.isEmpty())
        return probability;
    if (intervalMs < 0 || intervalMs >= byIntervalMs.last().first)
        return byIntervalMs.last().second;
    if (intervalMs <= byIntervalMs.first().first)
        return byIntervalMs.first().second;
    for (qsizetype i = 1; i < byIntervalMs.size(); ++i) {
        const auto &[x1, p1] = byIntervalMs.at(i);
        if (intervalMs <= x1) {
            const auto &[x0, p0] = byIntervalMs.at(i - 1);
            return x1 == x0 ? p1 : p0 + (p1 - p0) * (intervalMs - x0) / (x1 - x0);
        }
    }
    return byIntervalMs.last().second;
}

QString FaultRule::kindNames()
{
    QStringList names;
    for (const KindName &k : kKindNames)
        names.append(QString::fromLatin1(k.name));
    return names.join(QStringLiteral(", "));
}

} // namespace mbscope
