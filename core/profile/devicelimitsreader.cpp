#include "devicelimitsreader.h"

#include "json/jsonreader.h"
#include "protocol/functionspec.h"

namespace mbscope {

namespace {

constexpr double kMaxMs = 3600.0 * 1000.0; // an hour: anything longer is a typing error

template<typename Enum>
struct Choice {
    const char *name;
    Enum value;
};

// A string out of a few choices; fallback (and a problem naming the choices) otherwise.
template<typename Enum, size_t N>
Enum readChoice(JsonReader &reader, const QJsonObject &o, const QString &path, const char *key,
                const Choice<Enum> (&choices)[N], Enum fallback)
{
    const auto text = reader.string(o, path, key);
    if (!text)
        return fallback;
    QStringList names;
    for (const Choice<Enum> &c : choices) {
        if (*text == QLatin1String(c.name))
            return c.value;
        names.append(QString::fromLatin1(c.name));
    }
    reader.error(JsonReader::member(path, key),
                 QStringLiteral("'%1' is not one of %2").arg(*text, names.join(QStringLiteral(", "))));
    return fallback;
}

// "maxQuantity": {"0x03": 16, "0x10": 8}: the keys are function codes as hex text or decimal.
void readMaxQuantity(JsonReader &reader, const QJsonObject &limits, const QString &path, DeviceLimits *out)
{
    const auto o = reader.object(limits, path, "maxQuantity");
    if (!o)
        return;
    const QString at = JsonReader::member(path, "maxQuantity");
    for (auto it = o->begin(); it != o->end(); ++it) {
        const QString keyAt = JsonReader::member(at, it.key());
        const QString key = it.key();
        const int function = DeviceLimits::parseFunctionKey(key).value_or(0);
        if (function < 1 || function > 255) {
            reader.error(keyAt, QStringLiteral("'%1' is not a function code: expected hex text such as \"0x03\"").arg(key));
            continue;
        }
        const int spec = QuantityLimits::maxQuantity(quint8(function));
        if (spec == 0) {
            reader.error(keyAt, QStringLiteral("function %1 has no quantity to limit: expected one of 0x01, 0x02, 0x03, "
                                               "0x04, 0x0F, 0x10, 0x17")
                                    .arg(key));
            continue;
        }
        if (const auto n = reader.integerValue(it.value(), keyAt, 1, spec))
            out->maxQuantity.insert(quint8(function), int(*n));
    }
}

} // namespace

DeviceLimits DeviceLimitsReader::read(JsonReader &reader, const QJsonObject &root)
{
    using L = DeviceLimits;
    DeviceLimits limits;
    static constexpr Choice<L::UnknownUnit> kUnknown[] = {
        {"first", L::UnknownUnit::FirstUnit}, {"exception", L::UnknownUnit::Exception},
        {"silent", L::UnknownUnit::Silent}, {"auto", L::UnknownUnit::Auto}};
    limits.unknownUnit = readChoice(reader, root, QString(), "unknownUnit", kUnknown, L::UnknownUnit::Auto);
    limits.answersBroadcasts = reader.boolean(root, QString(), "answersBroadcasts").value_or(false);

    const auto o = reader.object(root, QString(), "limits");
    if (!o)
        return limits;
    const QString path = QStringLiteral("limits");
    reader.checkKeys(*o, path, {"minGapMs", "tooSoon", "maxClients", "extraClients", "maxQuantity", "warmUpMs", "closesAfterAnswer"});
    limits.minGapMs = reader.number(*o, path, "minGapMs", 0, kMaxMs).value_or(0);
    static constexpr Choice<L::TooSoon> kTooSoon[] = {{"busy", L::TooSoon::Busy}, {"silent", L::TooSoon::Silent}};
    limits.tooSoon = readChoice(reader, *o, path, "tooSoon", kTooSoon, L::TooSoon::Busy);
    if (o->contains(QLatin1String("tooSoon")) && !o->contains(QLatin1String("minGapMs")))
        reader.error(JsonReader::member(path, "tooSoon"), QStringLiteral("'tooSoon' needs 'minGapMs' (the gap it is about)"));
    limits.maxClients = int(reader.integer(*o, path, "maxClients", 1, 1024).value_or(0));
    static constexpr Choice<L::ExtraClient> kExtra[] = {{"refuse", L::ExtraClient::Refuse},
                                                        {"dropOldest", L::ExtraClient::DropOldest}};
    limits.extraClients = readChoice(reader, *o, path, "extraClients", kExtra, L::ExtraClient::Refuse);
    if (o->contains(QLatin1String("extraClients")) && !o->contains(QLatin1String("maxClients")))
        reader.error(JsonReader::member(path, "extraClients"),
                     QStringLiteral("'extraClients' needs 'maxClients' (how many clients are too many)"));
    readMaxQuantity(reader, *o, path, &limits);
    limits.warmUpMs = reader.number(*o, path, "warmUpMs", 0, kMaxMs).value_or(0);
    limits.closesAfterAnswer = reader.boolean(*o, path, "closesAfterAnswer").value_or(false);
    return limits;
}

} // namespace mbscope
