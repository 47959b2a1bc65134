#include "faultrulereader.h"

#include "protocol/hextext.h"
#include "json/jsonreader.h"
#include "protocol/quantitylimits.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>

namespace mbscope {

namespace {

constexpr double kMaxDelayMs = 3600.0 * 1000.0; // an hour: anything longer is a typing error
constexpr int kMaxJunk = 4096;

std::optional<DelaySpec::Kind> delayKind(QStringView name)
{
    for (auto kind : {DelaySpec::Kind::Fixed, DelaySpec::Kind::Uniform, DelaySpec::Kind::Normal,
                      DelaySpec::Kind::Exponential, DelaySpec::Kind::LogNormal}) {
        if (name == DelaySpec::kindName(kind))
            return kind;
    }
    return std::nullopt;
}

// A list of small integers, or one integer: "units": [1, 3] or "units": 1.
QList<quint8> readByteList(JsonReader &reader, const QJsonObject &o, const QString &path, const char *key,
                           qint64 min)
{
    QList<quint8> out;
    const QJsonValue v = o.value(QLatin1String(key));
    const QString at = JsonReader::member(path, key);
    if (v.isUndefined())
        return out;
    if (!v.isArray()) {
        if (const auto n = reader.integerValue(v, at, min, 255))
            out.append(quint8(*n));
        return out;
    }
    const QJsonArray a = v.toArray();
    if (a.isEmpty())
        reader.error(at, QStringLiteral("the list is empty: leave '%1' out to match every value").arg(QLatin1String(key)));
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (const auto n = reader.integerValue(a.at(i), JsonReader::element(at, i), min, 255))
            out.append(quint8(*n));
    }
    return out;
}

// "before": 7 (random bytes) or "before": "DE AD BE EF" (these bytes).
void readJunk(JsonReader &reader, const QJsonObject &o, const QString &path, const char *key, QByteArray *bytes,
              int *count)
{
    const QJsonValue v = o.value(QLatin1String(key));
    const QString at = JsonReader::member(path, key);
    if (v.isUndefined())
        return;
    if (v.isString()) {
        const HexTextResult hex = HexText::parse(v.toString());
        if (!hex.ok)
            reader.error(at, QStringLiteral("expected hex bytes such as \"DE AD BE EF\": %1").arg(hex.error.message));
        else
            *bytes = hex.bytes;
        return;
    }
    if (const auto n = reader.integerValue(v, at, 0, kMaxJunk))
        *count = int(*n);
}

// The keys every rule may have (how it matches, how often it fires), then those of its kind.
QList<const char *> ruleKeys(std::initializer_list<const char *> specific)
{
    QList<const char *> keys = {"kind", "name", "units", "functions", "meets", "addresses", "start", "quantity",
                                "values", "probability"};
    keys.append(QList<const char *>(specific));
    return keys;
}

// "meets": [first, last] or one address; "addresses" is its older name.
void readMeets(JsonReader &reader, const QJsonObject &o, const QString &path, FaultRule *rule)
{
    const bool meets = o.contains(QLatin1String("meets"));
    if (meets && o.contains(QLatin1String("addresses"))) {
        reader.error(JsonReader::member(path, "addresses"),
                     QStringLiteral("give 'meets' or its older name 'addresses', not both"));
        return;
    }
    const char *key = meets ? "meets" : "addresses";
    const QJsonValue addresses = o.value(QLatin1String(key));
    const QString at = JsonReader::member(path, key);
    if (addresses.isArray()) {
        const QJsonArray a = addresses.toArray();
        if (a.size() != 2) {
            reader.error(at, QStringLiteral("expected [first, last] (two addresses), found %1 values").arg(a.size()));
        } else {
            const auto first = reader.integerValue(a.at(0), JsonReader::element(at, 0), 0, 65535);
            const auto last = reader.integerValue(a.at(1), JsonReader::element(at, 1), 0, 65535);
            if (first && last && *last < *first)
                reader.error(JsonReader::element(at, 1), QStringLiteral("%1 is below the first address %2").arg(*last).arg(*first));
            else if (first && last) {
                rule->firstAddress = int(*first);
                rule->lastAddress = int(*last);
            }
        }
    } else if (!addresses.isUndefined()) {
        if (const auto n = reader.integerValue(addresses, at, 0, 65535)) {
            rule->firstAddress = int(*n);
            rule->lastAddress = int(*n);
        }
    }
}

// A list of whole numbers in [min, max], or one: "start": 368 or "start": [368, "0x0171"].
QList<int> readIntList(JsonReader &reader, const QJsonObject &o, const QString &path, const char *key, qint64 min,
                       qint64 max)
{
    QList<int> out;
    const QJsonValue v = o.value(QLatin1String(key));
    const QString at = JsonReader::member(path, key);
    if (v.isUndefined())
        return out;
    if (!v.isArray()) {
        if (const auto n = reader.integerValue(v, at, min, max))
            out.append(int(*n));
        return out;
    }
    const QJsonArray a = v.toArray();
    if (a.isEmpty())
        reader.error(at, QStringLiteral("the list is empty: leave '%1' out to match every value").arg(QLatin1String(key)));
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (const auto n = reader.integerValue(a.at(i), JsonReader::element(at, i), min, max))
            out.append(int(*n));
    }
    return out;
}

// "values": [1, 0, 1] (the values a write carries, in order; coils as 0 and 1).
void readValues(JsonReader &reader, const QJsonObject &o, const QString &path, FaultRule *rule)
{
    const QJsonValue v = o.value(QLatin1String("values"));
    if (v.isUndefined())
        return;
    const QString at = JsonReader::member(path, "values");
    if (!v.isArray()) {
        reader.error(at, QStringLiteral("expected a list of the values written, such as [1, 0] or [\"0x1234\"], found %1")
                             .arg(JsonReader::describe(v)));
        return;
    }
    const QJsonArray a = v.toArray();
    if (a.isEmpty() || a.size() > QuantityLimits::kWriteRegisters) {
        reader.error(at, QStringLiteral("expected 1 to %1 values (a write carries at most %1 registers), found %2")
                             .arg(QuantityLimits::kWriteRegisters).arg(a.size()));
        return;
    }
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (const auto n = reader.integerValue(a.at(i), JsonReader::element(at, i), 0, 65535))
            rule->values.append(quint16(*n));
    }
    rule->hasValues = true;
}

// "probability": 0.1, {"byIntervalMs": [[100, 0.5], [400, 0.2]]} or {"turnaround": DELAY}.
void readProbability(JsonReader &reader, const QJsonObject &o, const QString &path, FaultRule *rule)
{
    const QJsonValue v = o.value(QLatin1String("probability"));
    const QString at = JsonReader::member(path, "probability");
    if (v.isUndefined())
        return;
    if (!v.isObject()) {
        if (v.isDouble()) {
            rule->probability = reader.numberValue(v, at, 0, 1).value_or(1);
        } else {
            reader.error(at, QStringLiteral("expected a number 0-1, {\"byIntervalMs\": [[ms, p], ...]} or "
                                            "{\"turnaround\": DELAY}, found %1")
                                 .arg(JsonReader::describe(v)));
        }
        return;
    }
    const QJsonObject p = v.toObject();
    if (!reader.checkKeys(p, at, {"byIntervalMs", "turnaround"}))
        return;
    if (p.contains(QLatin1String("byIntervalMs")) == p.contains(QLatin1String("turnaround"))) {
        reader.error(at, QStringLiteral("give one of 'byIntervalMs' or 'turnaround'"));
        return;
    }
    if (p.contains(QLatin1String("turnaround"))) {
        if (const auto d = FaultRuleReader::readDelay(reader, p.value(QLatin1String("turnaround")),
                                                      JsonReader::member(at, "turnaround"))) {
            rule->turnaround = *d;
            rule->hasTurnaround = true;
        }
        return;
    }
    const QString tableAt = JsonReader::member(at, "byIntervalMs");
    const auto table = reader.array(p, at, "byIntervalMs");
    if (!table)
        return;
    if (table->isEmpty())
        reader.error(tableAt, QStringLiteral("the list is empty: expected [interval ms, probability] points"));
    double previous = -1;
    for (qsizetype i = 0; i < table->size(); ++i) {
        const QString pointAt = JsonReader::element(tableAt, i);
        const QJsonArray point = table->at(i).toArray();
        if (!table->at(i).isArray() || point.size() != 2) {
            reader.error(pointAt, QStringLiteral("expected [interval ms, probability], found %1").arg(JsonReader::describe(table->at(i))));
            continue;
        }
        const auto ms = reader.numberValue(point.at(0), JsonReader::element(pointAt, 0), 0, kMaxDelayMs);
        const auto chance = reader.numberValue(point.at(1), JsonReader::element(pointAt, 1), 0, 1);
        if (!ms || !chance)
            continue;
        if (*ms <= previous) {
            reader.error(JsonReader::element(pointAt, 0), QStringLiteral("%1 ms does not follow %2 ms: intervals go up")
                                                              .arg(JsonReader::numberText(*ms), JsonReader::numberText(previous)));
            continue;
        }
        previous = *ms;
        rule->byIntervalMs.append({*ms, *chance});
    }
}

} // namespace

std::optional<DelaySpec> FaultRuleReader::readDelay(JsonReader &reader, const QJsonValue &value, const QString &path)
{
    if (value.isDouble()) {
        const auto ms = reader.numberValue(value, path, 0, kMaxDelayMs);
        if (!ms)
            return std::nullopt;
        return DelaySpec::fixed(*ms);
    }
    if (!value.isObject()) {
        reader.error(path, QStringLiteral("expected milliseconds or an object such as "
                                          "{\"distribution\": \"normal\", \"meanMs\": 4, \"stddevMs\": 1}, found %1")
                               .arg(JsonReader::describe(value)));
        return std::nullopt;
    }
    const QJsonObject o = value.toObject();
    const int before = reader.problemCount();
    if (!reader.require(o, path, "distribution"))
        return std::nullopt;
    const auto name = reader.string(o, path, "distribution");
    if (!name)
        return std::nullopt;
    const auto kind = delayKind(*name);
    if (!kind) {
        reader.error(JsonReader::member(path, "distribution"),
                     QStringLiteral("'%1' is not a distribution: expected fixed, uniform, normal, exponential or lognormal").arg(*name));
        return std::nullopt;
    }
    DelaySpec spec;
    spec.kind = *kind;
    switch (*kind) {
    case DelaySpec::Kind::Fixed:
        reader.checkKeys(o, path, {"distribution", "ms"});
        if (reader.require(o, path, "ms"))
            spec.ms = reader.number(o, path, "ms", 0, kMaxDelayMs).value_or(0);
        break;
    case DelaySpec::Kind::Uniform:
        reader.checkKeys(o, path, {"distribution", "minMs", "maxMs"});
        if (reader.require(o, path, "minMs") && reader.require(o, path, "maxMs")) {
            spec.minMs = reader.number(o, path, "minMs", 0, kMaxDelayMs).value_or(0);
            spec.maxMs = reader.number(o, path, "maxMs", 0, kMaxDelayMs).value_or(0);
            if (spec.maxMs < spec.minMs)
                reader.error(JsonReader::member(path, "maxMs"),
                             QStringLiteral("%1 is below minMs %2").arg(JsonReader::numberText(spec.maxMs),
                                                                        JsonReader::numberText(spec.minMs)));
        }
        break;
    case DelaySpec::Kind::Normal:
    case DelaySpec::Kind::Exponential:
    case DelaySpec::Kind::LogNormal:
        if (*kind != DelaySpec::Kind::Exponential) {
            reader.checkKeys(o, path, {"distribution", "meanMs", "stddevMs", "minMs", "maxMs"});
            if (reader.require(o, path, "stddevMs"))
                spec.stddevMs = reader.number(o, path, "stddevMs", 0, kMaxDelayMs).value_or(0);
        } else {
            reader.checkKeys(o, path, {"distribution", "meanMs", "minMs", "maxMs"});
        }
        if (reader.require(o, path, "meanMs"))
            spec.meanMs = reader.number(o, path, "meanMs", 0, kMaxDelayMs).value_or(0);
        spec.minMs = reader.number(o, path, "minMs", 0, kMaxDelayMs).value_or(0);
        spec.maxMs = reader.number(o, path, "maxMs", 0, kMaxDelayMs).value_or(-1);
        if (o.contains(QLatin1String("maxMs")) && spec.maxMs >= 0 && spec.maxMs < spec.minMs)
            reader.error(JsonReader::member(path, "maxMs"),
                         QStringLiteral("%1 is below minMs %2").arg(JsonReader::numberText(spec.maxMs),
                                                                    JsonReader::numberText(spec.minMs)));
        break;
    }
    if (reader.problemCount() != before)
        return std::nullopt;
    return spec;
}

std::optional<FaultRule> FaultRuleReader::readRule(JsonReader &reader, const QJsonValue &value, const QString &path)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    const int before = reader.problemCount();
    if (!reader.require(*o, path, "kind"))
        return std::nullopt;
    const auto name = reader.string(*o, path, "kind");
    if (!name)
        return std::nullopt;
    const auto kind = FaultRule::kindFromName(*name);
    if (!kind) {
        reader.error(JsonReader::member(path, "kind"),
                     QStringLiteral("'%1' is not a fault: expected one of %2").arg(*name, FaultRule::kindNames()));
        return std::nullopt;
    }

    FaultRule rule;
    rule.kind = *kind;
    using K = FaultRule::Kind;
    switch (*kind) {
    case K::Delay:
        reader.checkKeys(*o, path, ruleKeys({"delay"}));
        if (reader.require(*o, path, "delay")) {
            if (const auto d = readDelay(reader, o->value(QLatin1String("delay")), JsonReader::member(path, "delay")))
                rule.delay = *d;
        }
        break;
    case K::Drop:
    case K::WrongChecksum:
        reader.checkKeys(*o, path, ruleKeys({}));
        break;
    case K::WrongTransactionId:
    case K::WrongUnit:
        reader.checkKeys(*o, path, ruleKeys({"delta"}));
        rule.delta = int(reader.integer(*o, path, "delta", 1, *kind == K::WrongUnit ? 255 : 65535).value_or(1));
        break;
    case K::Exception:
        reader.checkKeys(*o, path, ruleKeys({"code"}));
        rule.exceptionCode = quint8(reader.integer(*o, path, "code", 1, 255).value_or(4));
        break;
    case K::FewerRegisters:
        reader.checkKeys(*o, path, ruleKeys({"fewer"}));
        rule.fewer = int(reader.integer(*o, path, "fewer", 1, QuantityLimits::kReadRegisters).value_or(1));
        break;
    case K::Chunks:
        reader.checkKeys(*o, path, ruleKeys({"chunkBytes", "gapMs"}));
        rule.chunkBytes = int(reader.integer(*o, path, "chunkBytes", 1, 65535).value_or(4));
        rule.gapMs = reader.number(*o, path, "gapMs", 0, kMaxDelayMs).value_or(10);
        break;
    case K::Trickle:
        reader.checkKeys(*o, path, ruleKeys({"gapMs"}));
        rule.gapMs = reader.number(*o, path, "gapMs", 0, kMaxDelayMs).value_or(20);
        break;
    case K::Junk:
        reader.checkKeys(*o, path, ruleKeys({"before", "after"}));
        readJunk(reader, *o, path, "before", &rule.junkBefore, &rule.junkBeforeCount);
        readJunk(reader, *o, path, "after", &rule.junkAfter, &rule.junkAfterCount);
        if (!o->contains(QLatin1String("before")) && !o->contains(QLatin1String("after")))
            reader.error(path, QStringLiteral("junk needs 'before' or 'after' (a byte count or hex bytes)"));
        break;
    case K::Duplicate:
        reader.checkKeys(*o, path, ruleKeys({"copies", "gapMs"}));
        rule.copies = int(reader.integer(*o, path, "copies", 1, 16).value_or(1));
        rule.gapMs = reader.number(*o, path, "gapMs", 0, kMaxDelayMs).value_or(0);
        break;
    case K::Noise: {
        reader.checkKeys(*o, path, ruleKeys({"bitErrorRate", "on"}));
        if (reader.require(*o, path, "bitErrorRate"))
            rule.bitErrorRate = reader.number(*o, path, "bitErrorRate", 0, 0.5).value_or(0);
        const QString on = reader.string(*o, path, "on").value_or(QStringLiteral("both"));
        if (on == QLatin1String("both"))
            rule.noiseOn = FaultRule::NoiseOn::Both;
        else if (on == QLatin1String("request"))
            rule.noiseOn = FaultRule::NoiseOn::Request;
        else if (on == QLatin1String("answer"))
            rule.noiseOn = FaultRule::NoiseOn::Answer;
        else
            reader.error(JsonReader::member(path, "on"),
                         QStringLiteral("'%1' is not a direction: expected both, request or answer").arg(on));
        break;
    }
    case K::Close: {
        reader.checkKeys(*o, path, ruleKeys({"when"}));
        const QString when = reader.string(*o, path, "when").value_or(QStringLiteral("after"));
        if (when == QLatin1String("before"))
            rule.closeWhen = FaultRule::CloseWhen::Before;
        else if (when == QLatin1String("midway"))
            rule.closeWhen = FaultRule::CloseWhen::Midway;
        else if (when == QLatin1String("after"))
            rule.closeWhen = FaultRule::CloseWhen::After;
        else
            reader.error(JsonReader::member(path, "when"),
                         QStringLiteral("'%1' is not a moment: expected before, midway or after").arg(when));
        break;
    }
    }

    rule.name = reader.string(*o, path, "name").value_or(QString());
    rule.units = readByteList(reader, *o, path, "units", 0);
    rule.functions = readByteList(reader, *o, path, "functions", 1);
    readProbability(reader, *o, path, &rule);

    readMeets(reader, *o, path, &rule);
    rule.starts = readIntList(reader, *o, path, "start", 0, 65535);
    rule.quantities = readIntList(reader, *o, path, "quantity", 0, 65535);
    readValues(reader, *o, path, &rule);

    if (reader.problemCount() != before)
        return std::nullopt;
    return rule;
}

FaultRuleSet FaultRuleReader::readRuleSet(JsonReader &reader, const QJsonValue &value, const QString &path,
                                          quint64 defaultSeed)
{
    FaultRuleSet set;
    set.seed = defaultSeed;
    const auto o = reader.objectValue(value, path);
    if (!o)
        return set;
    reader.checkKeys(*o, path, {"$schema", "description", "seed", "rules"});
    if (const auto seed = reader.integer(*o, path, "seed", 0, qint64(9007199254740991LL)))
        set.seed = quint64(*seed);
    if (const auto rules = reader.array(*o, path, "rules")) {
        const QString at = JsonReader::member(path, "rules");
        for (qsizetype i = 0; i < rules->size(); ++i) {
            if (const auto rule = readRule(reader, rules->at(i), JsonReader::element(at, i)))
                set.rules.append(*rule);
        }
    }
    return set;
}

} // namespace mbscope
