#include "faultrulewriter.h"

#include <QtCore/QJsonArray>

namespace mbscope {

namespace {

QJsonValue byteList(const QList<quint8> &values)
{
    QJsonArray out;
    for (const quint8 v : values)
        out.append(int(v));
    return out;
}

QJsonValue intList(const QList<int> &values)
{
    QJsonArray out;
    for (const int v : values)
        out.append(v);
    return out;
}

QJsonObject delayJson(const DelaySpec &d);

// 0.25, {"byIntervalMs": [[ms, p], ...]} or {"turnaround": DELAY}.
QJsonValue probabilityJson(const FaultRule &rule)
{
    if (rule.hasTurnaround)
        return QJsonObject{{QStringLiteral("turnaround"), delayJson(rule.turnaround)}};
    if (!rule.byIntervalMs.isEmpty()) {
        QJsonArray table;
        for (const auto &[ms, chance] : rule.byIntervalMs)
            table.append(QJsonArray{ms, chance});
        return QJsonObject{{QStringLiteral("byIntervalMs"), table}};
    }
    return rule.probability;
}

QString noiseOnName(FaultRule::NoiseOn on)
{
    switch (on) {
    case FaultRule::NoiseOn::Request:
        return QStringLiteral("request");
    case FaultRule::NoiseOn::Answer:
        return QStringLiteral("answer");
    case FaultRule::NoiseOn::Both:
        break;
    }
    return QStringLiteral("both");
}

QJsonObject delayJson(const DelaySpec &d)
{
    QJsonObject o{{QStringLiteral("distribution"), DelaySpec::kindName(d.kind)}};
    switch (d.kind) {
    case DelaySpec::Kind::Fixed:
        o.insert(QStringLiteral("ms"), d.ms);
        break;
    case DelaySpec::Kind::Uniform:
        o.insert(QStringLiteral("minMs"), d.minMs);
        o.insert(QStringLiteral("maxMs"), d.maxMs);
        break;
    case DelaySpec::Kind::Normal:
    case DelaySpec::Kind::Exponential:
    case DelaySpec::Kind::LogNormal:
        o.insert(QStringLiteral("meanMs"), d.meanMs);
        if (d.kind != DelaySpec::Kind::Exponential)
            o.insert(QStringLiteral("stddevMs"), d.stddevMs);
        if (d.minMs != 0)
            o.insert(QStringLiteral("minMs"), d.minMs);
        if (d.maxMs >= 0)
            o.insert(QStringLiteral("maxMs"), d.maxMs);
        break;
    }
    return o;
}

// "before": 7 random bytes, or the bytes themselves as hex.
void insertJunk(QJsonObject &o, const char *key, const QByteArray &bytes, int count)
{
    if (!bytes.isEmpty())
        o.insert(QLatin1String(key), QString::fromLatin1(bytes.toHex(' ').toUpper()));
    else if (count > 0)
        o.insert(QLatin1String(key), count);
}

QString closeWhenName(FaultRule::CloseWhen when)
{
    switch (when) {
    case FaultRule::CloseWhen::Before:
        return QStringLiteral("before");
    case FaultRule::CloseWhen::Midway:
        return QStringLiteral("midway");
    case FaultRule::CloseWhen::After:
        break;
    }
    return QStringLiteral("after");
}

} // namespace

QJsonObject FaultRuleWriter::toJson(const FaultRule &rule)
{
    QJsonObject o{{QStringLiteral("kind"), FaultRule::kindName(rule.kind)}};
    if (!rule.name.isEmpty())
        o.insert(QStringLiteral("name"), rule.name);
    if (!rule.units.isEmpty())
        o.insert(QStringLiteral("units"), byteList(rule.units));
    if (!rule.functions.isEmpty())
        o.insert(QStringLiteral("functions"), byteList(rule.functions));
    if (rule.hasAddressRange())
        o.insert(QStringLiteral("meets"), QJsonArray{rule.firstAddress, rule.lastAddress});
    if (!rule.starts.isEmpty())
        o.insert(QStringLiteral("start"), intList(rule.starts));
    if (!rule.quantities.isEmpty())
        o.insert(QStringLiteral("quantity"), intList(rule.quantities));
    if (rule.hasValues) {
        QJsonArray values;
        for (const quint16 v : rule.values)
            values.append(int(v));
        o.insert(QStringLiteral("values"), values);
    }
    if (rule.dependsOnTime() || rule.probability != 1)
        o.insert(QStringLiteral("probability"), probabilityJson(rule));

    using K = FaultRule::Kind;
    switch (rule.kind) {
    case K::Delay:
        o.insert(QStringLiteral("delay"), delayJson(rule.delay));
        break;
    case K::Drop:
    case K::WrongChecksum:
        break;
    case K::WrongTransactionId:
    case K::WrongUnit:
        o.insert(QStringLiteral("delta"), rule.delta);
        break;
    case K::Exception:
        o.insert(QStringLiteral("code"), int(rule.exceptionCode));
        break;
    case K::FewerRegisters:
        o.insert(QStringLiteral("fewer"), rule.fewer);
        break;
    case K::Chunks:
        o.insert(QStringLiteral("chunkBytes"), rule.chunkBytes);
        o.insert(QStringLiteral("gapMs"), rule.gapMs);
        break;
    case K::Trickle:
        o.insert(QStringLiteral("gapMs"), rule.gapMs);
        break;
    case K::Junk:
        insertJunk(o, "before", rule.junkBefore, rule.junkBeforeCount);
        insertJunk(o, "after", rule.junkAfter, rule.junkAfterCount);
        break;
    case K::Duplicate:
        o.insert(QStringLiteral("copies"), rule.copies);
        o.insert(QStringLiteral("gapMs"), rule.gapMs);
        break;
    case K::Close:
        o.insert(QStringLiteral("when"), closeWhenName(rule.closeWhen));
        break;
    case K::Noise:
        o.insert(QStringLiteral("bitErrorRate"), rule.bitErrorRate);
        o.insert(QStringLiteral("on"), noiseOnName(rule.noiseOn));
        break;
    }
    return o;
}

QJsonObject FaultRuleWriter::toJson(const FaultRuleSet &set)
{
    QJsonArray rules;
    for (const FaultRule &rule : set.rules)
        rules.append(toJson(rule));
    return QJsonObject{{QStringLiteral("seed"), qint64(set.seed)}, {QStringLiteral("rules"), rules}};
}

} // namespace mbscope
