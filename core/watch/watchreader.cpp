#include "watchreader.h"

#include "watch/watchblock.h"
#include "watch/watchruleevaluator.h"
#include "watch/watchrulethresholds.h"

#include "json/jsonreader.h"
#include "transport/linkurl.h"

#include <QtCore/QJsonArray>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>

#include <cmath>

namespace mbscope {

namespace {

QString hex4(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

QString rangeText(const WatchDefinition &w)
{
    return QStringLiteral("%1-%2").arg(hex4(w.address), hex4(w.address + w.quantity - 1));
}

// "bits": 3 (one bit) or "8-11" (a range, low bit first).
bool readBits(JsonReader &reader, const QJsonObject &o, const QString &path, WatchBitField *field, int widthBits)
{
    const QString at = JsonReader::member(path, "bits");
    const QJsonValue v = o.value(QLatin1String("bits"));
    int first = -1;
    int last = -1;
    if (v.isDouble()) {
        const double d = v.toDouble();
        if (d == std::floor(d) && d >= 0 && d < 64)
            first = last = int(d);
    } else if (v.isString()) {
        static const QRegularExpression range(QStringLiteral("^\\s*(\\d+)\\s*(?:-\\s*(\\d+))?\\s*$"));
        const QRegularExpressionMatch m = range.match(v.toString());
        if (m.hasMatch()) {
            first = m.captured(1).toInt();
            last = m.captured(2).isEmpty() ? first : m.captured(2).toInt();
        }
    }
    if (first < 0) {
        reader.error(at, QStringLiteral("expected a bit number such as 3 or a range such as \"8-11\", found %1")
                             .arg(JsonReader::describe(v)));
        return false;
    }
    if (last < first) {
        reader.error(at, QStringLiteral("the range \"%1\" runs backwards: give the low bit first (\"%2-%3\")")
                             .arg(v.toString())
                             .arg(last)
                             .arg(first));
        return false;
    }
    if (last >= widthBits) {
        reader.error(at, QStringLiteral("bit %1 is beyond the value's %2 bits (0 to %3)").arg(last).arg(widthBits).arg(widthBits - 1));
        return false;
    }
    if (last - first + 1 > 32) {
        reader.error(at, QStringLiteral("a bit field holds at most 32 bits"));
        return false;
    }
    field->firstBit = first;
    field->bitCount = last - first + 1;
    return true;
}

std::optional<WatchBitField> readBitField(JsonReader &reader, const QJsonValue &value, const QString &path, int widthBits)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    reader.checkKeys(*o, path, {"name", "bits", "states"});
    WatchBitField f;
    if (reader.require(*o, path, "name")) {
        f.name = reader.string(*o, path, "name").value_or(QString());
        if (f.name.trimmed().isEmpty())
            reader.error(JsonReader::member(path, "name"), QStringLiteral("the name is empty"));
    }
    if (reader.require(*o, path, "bits"))
        readBits(reader, *o, path, &f, widthBits);
    if (const auto states = reader.array(*o, path, "states")) {
        const QString at = JsonReader::member(path, "states");
        for (qsizetype i = 0; i < states->size(); ++i) {
            if (const auto s = reader.stringValue(states->at(i), JsonReader::element(at, i)))
                f.states.append(*s);
        }
        if (f.bitCount < 32 && states->size() > (qsizetype(1) << f.bitCount))
            reader.error(at, QStringLiteral("%1 names for a field of %2 bits (at most %3 values)")
                                 .arg(states->size())
                                 .arg(f.bitCount)
                                 .arg(1LL << f.bitCount));
    }
    return f;
}

std::optional<WatchPoint> readPoint(JsonReader &reader, const QJsonValue &value, const QString &path,
                                    const WatchDefinition &w)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    reader.checkKeys(*o, path, {"address", "name", "description", "format", "scale", "offset", "unit", "writable", "bitFields"});
    WatchPoint p;
    const bool bits = WatchBlock::isBitFunction(w.function);
    if (reader.require(*o, path, "address")) {
        if (const auto a = reader.integer(*o, path, "address", 0, 65535)) {
            p.address = quint16(*a);
            if (*a < w.address || *a >= qint64(w.address) + w.quantity)
                reader.error(JsonReader::member(path, "address"),
                             QStringLiteral("%1 is outside the watch's addresses (%2)").arg(hex4(int(*a)), rangeText(w)));
        }
    }
    p.name = reader.string(*o, path, "name").value_or(QString());
    p.description = reader.string(*o, path, "description").value_or(QString());
    p.unit = reader.string(*o, path, "unit").value_or(QString());
    p.writable = reader.boolean(*o, path, "writable").value_or(false);
    if (const auto format = reader.string(*o, path, "format")) {
        const QString at = JsonReader::member(path, "format");
        const RegisterFormatResult parsed = RegisterFormat::parse(*format);
        if (bits)
            reader.error(at, QStringLiteral("a watch of coils or discrete inputs (function %1) reads bits: a point has no format").arg(w.function));
        else if (!parsed.ok)
            reader.error(at, parsed.error);
        else if (w.enron32 && parsed.format.registerCount() > 2)
            reader.error(at, QStringLiteral("an Enron watch holds one 32-bit value per address: %1 needs 64 bits (give a 16- or 32-bit format)")
                                 .arg(parsed.format.name()));
        else {
            p.format = parsed.format;
            const int addresses = w.enron32 ? 1 : parsed.format.registerCount();
            if (qint64(p.address) + addresses > qint64(w.address) + w.quantity && p.address >= w.address)
                reader.error(at, QStringLiteral("%1 at %2 takes %3 registers, past the watch's last address %4")
                                     .arg(parsed.format.name(), hex4(p.address))
                                     .arg(addresses)
                                     .arg(hex4(w.address + w.quantity - 1)));
        }
    }
    p.scale = reader.number(*o, path, "scale", -1e300, 1e300).value_or(1);
    if (p.scale == 0)
        reader.error(JsonReader::member(path, "scale"), QStringLiteral("a scale of 0 makes every value 0: leave it out for 1"));
    p.offset = reader.number(*o, path, "offset", -1e300, 1e300).value_or(0);
    if (const auto fields = reader.array(*o, path, "bitFields")) {
        const QString at = JsonReader::member(path, "bitFields");
        if (bits) {
            reader.error(at, QStringLiteral("bit fields are named bits inside registers; this watch reads coils or discrete inputs"));
        } else {
            const int widthBits = (w.enron32 ? 32 : 16 * p.format.registerCount());
            for (qsizetype i = 0; i < fields->size(); ++i) {
                if (auto f = readBitField(reader, fields->at(i), JsonReader::element(at, i), widthBits))
                    p.bitFields.append(*f);
            }
        }
    }
    return p;
}

struct ConditionKey {
    const char *key;
    WatchRule::Condition condition;
    bool range;
};

constexpr ConditionKey kConditions[] = {
    {"above", WatchRule::Condition::Above, false},     {"below", WatchRule::Condition::Below, false},
    {"outside", WatchRule::Condition::Outside, true},  {"inside", WatchRule::Condition::Inside, true},
    {"equal", WatchRule::Condition::Equal, false},     {"notEqual", WatchRule::Condition::NotEqual, false},
    {"bits", WatchRule::Condition::Bits, false},
};

std::optional<WatchRule> readRule(JsonReader &reader, const QJsonValue &value, const QString &path, const WatchDefinition &w)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    reader.checkKeys(*o, path, {"point", "above", "below", "outside", "inside", "equal", "notEqual", "bits", "forPolls",
                                "severity", "colour", "message"});
    WatchRule r;
    if (reader.require(*o, path, "point")) {
        const QJsonValue v = o->value(QLatin1String("point"));
        r.point = v.isDouble() ? QString::number(qint64(v.toDouble())) : v.toString();
        if (!v.isString() && !v.isDouble())
            reader.error(JsonReader::member(path, "point"),
                         QStringLiteral("expected a point's name or an address, found %1").arg(JsonReader::describe(v)));
        else if (WatchRuleEvaluator::ruleAddress(w, r.point) < 0)
            reader.error(JsonReader::member(path, "point"),
                         QStringLiteral("'%1' is neither a point's name nor an address of the watch (%2)").arg(r.point, rangeText(w)));
    }
    QStringList given;
    for (const ConditionKey &c : kConditions) {
        if (o->contains(QLatin1String(c.key)))
            given.append(QLatin1String(c.key));
    }
    if (given.isEmpty()) {
        reader.error(path, QStringLiteral("no condition: give one of above, below, outside, inside, equal, notEqual, bits"));
    } else if (given.size() > 1) {
        reader.error(path, QStringLiteral("%1 conditions (%2): a rule has one; write a rule for each").arg(given.size()).arg(given.join(QLatin1String(", "))));
    } else {
        for (const ConditionKey &c : kConditions) {
            if (given.first() != QLatin1String(c.key))
                continue;
            r.condition = c.condition;
            const QString at = JsonReader::member(path, c.key);
            bool thresholdsRead = false;
            if (c.range) {
                const QJsonValue v = o->value(QLatin1String(c.key));
                const QJsonArray a = v.toArray();
                if (!v.isArray() || a.size() != 2 || !a.at(0).isDouble() || !a.at(1).isDouble()) {
                    reader.error(at, QStringLiteral("expected [low, high], two numbers, found %1").arg(JsonReader::describe(v)));
                } else {
                    r.low = a.at(0).toDouble();
                    r.high = a.at(1).toDouble();
                    thresholdsRead = true;
                }
            } else if (c.condition == WatchRule::Condition::Bits) {
                if (const auto mask = reader.integer(*o, path, c.key, 1, 0xFFFFFFFFLL)) {
                    r.low = double(*mask);
                    thresholdsRead = true;
                }
            } else if (const auto n = reader.number(*o, path, c.key, -1e300, 1e300)) {
                (c.condition == WatchRule::Condition::Above ? r.high : r.low) = *n;
                thresholdsRead = true;
            }
            // A threshold the rule's point can never reach (a mask wider than the point, a coil
            // equal to 2) is refused here rather than leaving a rule that never fires.
            // (A mask needs the point's width: not said again for a point already refused.)
            if (thresholdsRead && (c.condition != WatchRule::Condition::Bits || WatchRuleEvaluator::ruleAddress(w, r.point) >= 0)) {
                if (const auto problem = WatchRuleThresholds::problem(w, r))
                    reader.error(at, problem->message);
            }
        }
    }
    r.forPolls = int(reader.integer(*o, path, "forPolls", 1, 1'000'000).value_or(1));
    if (const auto severity = reader.string(*o, path, "severity")) {
        if (*severity == QLatin1String("info"))
            r.severity = WatchSeverity::Info;
        else if (*severity == QLatin1String("warning"))
            r.severity = WatchSeverity::Warning;
        else if (*severity == QLatin1String("alarm"))
            r.severity = WatchSeverity::Alarm;
        else
            reader.error(JsonReader::member(path, "severity"), QStringLiteral("'%1' is not a severity: expected info, warning or alarm").arg(*severity));
    }
    if (const auto colour = reader.string(*o, path, "colour")) {
        static const QRegularExpression rgb(QStringLiteral("^#[0-9A-Fa-f]{6}$"));
        if (!rgb.match(*colour).hasMatch())
            reader.error(JsonReader::member(path, "colour"), QStringLiteral("'%1' is not a colour: expected #RRGGBB such as \"#D32F2F\"").arg(*colour));
        r.colour = *colour;
    }
    r.message = reader.string(*o, path, "message").value_or(QString());
    return r;
}

void readLinks(JsonReader &reader, const QJsonArray &links, SessionWatches *watches)
{
    QSet<QString> targets;
    for (const WatchDefinition &w : std::as_const(watches->watches))
        targets.insert(w.target);
    QSet<QString> seen;
    for (qsizetype i = 0; i < links.size(); ++i) {
        const QString path = JsonReader::element(QStringLiteral("watchLinks"), i);
        const auto o = reader.objectValue(links.at(i), path);
        if (!o)
            continue;
        reader.checkKeys(*o, path, {"target", "gapMs", "warmUpMs", "timeoutMs", "retries", "reconnectMinMs", "reconnectMaxMs"});
        WatchLinkSettings s;
        if (reader.require(*o, path, "target")) {
            s.target = reader.string(*o, path, "target").value_or(QString());
            const QString at = JsonReader::member(path, "target");
            if (seen.contains(s.target))
                reader.error(at, QStringLiteral("'%1' has settings earlier in watchLinks too").arg(s.target));
            else if (!targets.contains(s.target))
                reader.error(at, QStringLiteral("no watch uses '%1': a link's settings name the target of a watch, exactly as written there").arg(s.target));
            seen.insert(s.target);
        }
        s.gapMs = int(reader.integer(*o, path, "gapMs", 0, 60'000).value_or(0));
        s.warmUpMs = int(reader.integer(*o, path, "warmUpMs", 0, 3'600'000).value_or(0));
        s.timeoutMs = int(reader.integer(*o, path, "timeoutMs", 1, 3'600'000).value_or(-1));
        s.retries = int(reader.integer(*o, path, "retries", 0, 100).value_or(0));
        s.reconnectMinMs = int(reader.integer(*o, path, "reconnectMinMs", 1, 3'600'000).value_or(s.reconnectMinMs));
        s.reconnectMaxMs = int(reader.integer(*o, path, "reconnectMaxMs", 1, 3'600'000).value_or(qMax(s.reconnectMaxMs, s.reconnectMinMs)));
        if (s.reconnectMaxMs < s.reconnectMinMs)
            reader.error(JsonReader::member(path, "reconnectMaxMs"), QStringLiteral("%1 is below reconnectMinMs %2").arg(s.reconnectMaxMs).arg(s.reconnectMinMs));
        watches->links.append(s);
    }
}

std::optional<WatchLogSettings> readLog(JsonReader &reader, const QJsonValue &value)
{
    const QString path = QStringLiteral("watchLog");
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    reader.checkKeys(*o, path, {"directory", "mode", "rollBytes", "rollSeconds", "enabled"});
    WatchLogSettings log;
    if (reader.require(*o, path, "directory")) {
        log.directory = reader.string(*o, path, "directory").value_or(QString());
        if (log.directory.trimmed().isEmpty())
            reader.error(JsonReader::member(path, "directory"), QStringLiteral("the directory is empty"));
    }
    if (const auto mode = reader.string(*o, path, "mode")) {
        if (*mode == QLatin1String("poll"))
            log.mode = WatchLogSettings::Mode::EveryPoll;
        else if (*mode == QLatin1String("change"))
            log.mode = WatchLogSettings::Mode::OnChange;
        else
            reader.error(JsonReader::member(path, "mode"), QStringLiteral("'%1' is not a mode: expected \"poll\" (a row per poll) or \"change\" (a row when a value changes)").arg(*mode));
    }
    log.rollBytes = reader.integer(*o, path, "rollBytes", 0, 1LL << 50).value_or(0);
    log.rollSeconds = reader.integer(*o, path, "rollSeconds", 0, 366LL * 24 * 3600).value_or(0);
    log.enabled = reader.boolean(*o, path, "enabled").value_or(true);
    return log;
}

} // namespace

bool WatchReader::isWatchKey(const QString &key)
{
    return key == QLatin1String("watches") || key == QLatin1String("watchLinks") || key == QLatin1String("watchLog");
}

std::optional<WatchDefinition> WatchReader::readWatch(JsonReader &reader, const QJsonValue &value, const QString &path)
{
    const auto o = reader.objectValue(value, path);
    if (!o)
        return std::nullopt;
    reader.checkKeys(*o, path, {"name", "target", "unit", "function", "address", "quantity", "intervalMs", "enron32",
                                "profileBlock", "points", "rules", "enabled"});
    WatchDefinition w;
    if (reader.require(*o, path, "name")) {
        w.name = reader.string(*o, path, "name").value_or(QString());
        if (w.name.trimmed().isEmpty())
            reader.error(JsonReader::member(path, "name"), QStringLiteral("the name is empty: CSV files, metrics and topics are named by it"));
    }
    if (reader.require(*o, path, "target")) {
        if (const auto target = reader.string(*o, path, "target")) {
            w.target = *target;
            const LinkUrl::Result parsed = LinkUrl::parse(*target);
            if (!parsed.url)
                reader.error(JsonReader::member(path, "target"), parsed.error);
        }
    }
    w.unit = quint8(reader.integer(*o, path, "unit", 0, 255).value_or(1));
    if (const auto f = reader.integer(*o, path, "function", 1, 255)) {
        if (!WatchBlock::isWatchFunction(quint8(*f)))
            reader.error(JsonReader::member(path, "function"),
                         *f == 0x17 ? QStringLiteral("0x17 writes every time it reads: a watch only reads (1, 2, 3, 4 or 0x18)")
                                    : QStringLiteral("%1 is not a read a watch makes: expected 1 (coils), 2 (discrete inputs), 3 (holding "
                                                     "registers), 4 (input registers) or 0x18 (FIFO)").arg(*f));
        else
            w.function = quint8(*f);
    }
    w.enron32 = reader.boolean(*o, path, "enron32").value_or(false);
    if (w.enron32 && w.function != 3 && w.function != 4) {
        reader.error(JsonReader::member(path, "enron32"), QStringLiteral("32-bit (Enron) registers are holding or input registers (function 3 or 4), not function %1").arg(w.function));
        w.enron32 = false;
    }
    if (reader.require(*o, path, "address"))
        w.address = quint16(reader.integer(*o, path, "address", 0, 65535).value_or(0));
    const int max = WatchBlock::maxQuantity(w.function, w.enron32);
    if (w.function == 0x18) {
        // The FIFO's pointer address; quantity: the most values expected (V1.1b3, 6.18: 31).
        w.quantity = quint16(reader.integer(*o, path, "quantity", 1, max).value_or(max));
    } else if (reader.require(*o, path, "quantity")) {
        if (const auto q = reader.integer(*o, path, "quantity", 1, 65535)) {
            const QString at = JsonReader::member(path, "quantity");
            // Points and rules are checked against the addresses asked for, even when too many.
            w.quantity = quint16(qMin<qint64>(*q, 65536 - w.address));
            if (*q > max)
                reader.error(at, w.enron32 ? QStringLiteral("%1 is above %2: a read answers at most 62 32-bit registers (4 bytes each in a 253-byte PDU)").arg(*q).arg(max)
                                           : QStringLiteral("%1 is above %2, the most function %3 reads at once").arg(*q).arg(max).arg(w.function));
            else if (w.address + *q - 1 > 65535)
                reader.error(at, QStringLiteral("%1 addresses from %2 run past 0xFFFF").arg(*q).arg(hex4(w.address)));
        }
    }
    w.intervalMs = reader.integer(*o, path, "intervalMs", 0, 24LL * 3600 * 1000).value_or(1000);
    w.profileBlock = reader.string(*o, path, "profileBlock").value_or(QString());
    w.enabled = reader.boolean(*o, path, "enabled").value_or(true);

    if (const auto points = reader.array(*o, path, "points")) {
        const QString at = JsonReader::member(path, "points");
        QSet<QString> names;
        int nextFree = -1; // the first address after the previous point
        for (qsizetype i = 0; i < points->size(); ++i) {
            const QString pointPath = JsonReader::element(at, i);
            const auto p = readPoint(reader, points->at(i), pointPath, w);
            if (!p)
                continue;
            if (!p->name.isEmpty()) {
                if (names.contains(p->name))
                    reader.error(JsonReader::member(pointPath, "name"), QStringLiteral("'%1' names an earlier point of the watch too").arg(p->name));
                names.insert(p->name);
            }
            if (p->address < nextFree)
                reader.error(JsonReader::member(pointPath, "address"),
                             QStringLiteral("%1 is inside or before the previous point (which ends before %2): points go in address order, not overlapping")
                                 .arg(hex4(p->address), hex4(nextFree)));
            nextFree = p->address + (w.enron32 || WatchBlock::isBitFunction(w.function) ? 1 : p->format.registerCount());
            w.points.append(*p);
        }
    }
    if (const auto rules = reader.array(*o, path, "rules")) {
        const QString at = JsonReader::member(path, "rules");
        for (qsizetype i = 0; i < rules->size(); ++i) {
            if (const auto r = readRule(reader, rules->at(i), JsonReader::element(at, i), w))
                w.rules.append(*r);
        }
    }
    return w;
}

SessionWatches WatchReader::read(JsonReader &reader, const QJsonObject &root)
{
    SessionWatches watches;
    const QString top;
    if (const auto list = reader.array(root, top, "watches")) {
        QSet<QString> names;
        for (qsizetype i = 0; i < list->size(); ++i) {
            const QString path = JsonReader::element(QStringLiteral("watches"), i);
            const auto w = readWatch(reader, list->at(i), path);
            if (!w)
                continue;
            if (!w->name.isEmpty() && names.contains(w->name))
                reader.error(JsonReader::member(path, "name"),
                             QStringLiteral("'%1' names an earlier watch too: CSV files, metrics and topics are named by it").arg(w->name));
            names.insert(w->name);
            watches.watches.append(*w);
        }
    }
    if (const auto links = reader.array(root, top, "watchLinks"))
        readLinks(reader, *links, &watches);
    if (root.contains(QLatin1String("watchLog")))
        watches.log = readLog(reader, root.value(QLatin1String("watchLog")));
    return watches;
}

} // namespace mbscope
