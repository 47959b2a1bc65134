#include "watchwriter.h"

#include "watch/watchblock.h"

#include <QtCore/QJsonArray>

namespace mbscope {

namespace {

QString hex4(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

QJsonValue bitsJson(const WatchBitField &f)
{
    if (f.bitCount == 1)
        return f.firstBit;
    return QStringLiteral("%1-%2").arg(f.firstBit).arg(f.firstBit + f.bitCount - 1);
}

QJsonObject pointJson(const WatchPoint &p, bool bits)
{
    QJsonObject o;
    o.insert(QLatin1String("address"), hex4(p.address));
    if (!p.name.isEmpty())
        o.insert(QLatin1String("name"), p.name);
    if (!p.description.isEmpty())
        o.insert(QLatin1String("description"), p.description);
    if (!bits && p.format != RegisterFormat())
        o.insert(QLatin1String("format"), p.format.name());
    if (p.scale != 1)
        o.insert(QLatin1String("scale"), p.scale);
    if (p.offset != 0)
        o.insert(QLatin1String("offset"), p.offset);
    if (!p.unit.isEmpty())
        o.insert(QLatin1String("unit"), p.unit);
    if (p.writable)
        o.insert(QLatin1String("writable"), true);
    if (!p.bitFields.isEmpty()) {
        QJsonArray fields;
        for (const WatchBitField &f : p.bitFields) {
            QJsonObject fo;
            fo.insert(QLatin1String("name"), f.name);
            fo.insert(QLatin1String("bits"), bitsJson(f));
            if (!f.states.isEmpty())
                fo.insert(QLatin1String("states"), QJsonArray::fromStringList(f.states));
            fields.append(fo);
        }
        o.insert(QLatin1String("bitFields"), fields);
    }
    return o;
}

QJsonObject ruleJson(const WatchRule &r)
{
    QJsonObject o;
    o.insert(QLatin1String("point"), r.point);
    switch (r.condition) {
    case WatchRule::Condition::Above: o.insert(QLatin1String("above"), r.high); break;
    case WatchRule::Condition::Below: o.insert(QLatin1String("below"), r.low); break;
    case WatchRule::Condition::Outside: o.insert(QLatin1String("outside"), QJsonArray{r.low, r.high}); break;
    case WatchRule::Condition::Inside: o.insert(QLatin1String("inside"), QJsonArray{r.low, r.high}); break;
    case WatchRule::Condition::Equal: o.insert(QLatin1String("equal"), r.low); break;
    case WatchRule::Condition::NotEqual: o.insert(QLatin1String("notEqual"), r.low); break;
    case WatchRule::Condition::Bits:
        o.insert(QLatin1String("bits"), QStringLiteral("0x") + QString::number(quint64(r.low), 16).toUpper());
        break;
    }
    if (r.forPolls != 1)
        o.insert(QLatin1String("forPolls"), r.forPolls);
    if (r.severity != WatchSeverity::Warning)
        o.insert(QLatin1String("severity"), r.severity == WatchSeverity::Info ? QStringLiteral("info") : QStringLiteral("alarm"));
    if (!r.colour.isEmpty())
        o.insert(QLatin1String("colour"), r.colour);
    if (!r.message.isEmpty())
        o.insert(QLatin1String("message"), r.message);
    return o;
}

} // namespace

QJsonObject WatchWriter::watchToJson(const WatchDefinition &w)
{
    const WatchDefinition defaults;
    QJsonObject o;
    o.insert(QLatin1String("name"), w.name);
    o.insert(QLatin1String("target"), w.target);
    if (w.unit != defaults.unit)
        o.insert(QLatin1String("unit"), w.unit);
    if (w.function != defaults.function)
        o.insert(QLatin1String("function"), w.function == 0x18 ? QJsonValue(QStringLiteral("0x18")) : QJsonValue(w.function));
    o.insert(QLatin1String("address"), hex4(w.address));
    o.insert(QLatin1String("quantity"), w.quantity);
    if (w.intervalMs != defaults.intervalMs)
        o.insert(QLatin1String("intervalMs"), w.intervalMs);
    if (w.enron32)
        o.insert(QLatin1String("enron32"), true);
    if (!w.profileBlock.isEmpty())
        o.insert(QLatin1String("profileBlock"), w.profileBlock);
    if (!w.enabled)
        o.insert(QLatin1String("enabled"), false);
    if (!w.points.isEmpty()) {
        QJsonArray points;
        for (const WatchPoint &p : w.points)
            points.append(pointJson(p, WatchBlock::isBitFunction(w.function)));
        o.insert(QLatin1String("points"), points);
    }
    if (!w.rules.isEmpty()) {
        QJsonArray rules;
        for (const WatchRule &r : w.rules)
            rules.append(ruleJson(r));
        o.insert(QLatin1String("rules"), rules);
    }
    return o;
}

void WatchWriter::write(const SessionWatches &watches, QJsonObject *root)
{
    if (!watches.watches.isEmpty()) {
        QJsonArray list;
        for (const WatchDefinition &w : watches.watches)
            list.append(watchToJson(w));
        root->insert(QLatin1String("watches"), list);
    }
    if (!watches.links.isEmpty()) {
        const WatchLinkSettings defaults;
        QJsonArray links;
        for (const WatchLinkSettings &l : watches.links) {
            QJsonObject o;
            o.insert(QLatin1String("target"), l.target);
            if (l.gapMs != defaults.gapMs)
                o.insert(QLatin1String("gapMs"), l.gapMs);
            if (l.warmUpMs != defaults.warmUpMs)
                o.insert(QLatin1String("warmUpMs"), l.warmUpMs);
            if (l.timeoutMs > 0)
                o.insert(QLatin1String("timeoutMs"), l.timeoutMs);
            if (l.retries != defaults.retries)
                o.insert(QLatin1String("retries"), l.retries);
            if (l.reconnectMinMs != defaults.reconnectMinMs)
                o.insert(QLatin1String("reconnectMinMs"), l.reconnectMinMs);
            if (l.reconnectMaxMs != defaults.reconnectMaxMs)
                o.insert(QLatin1String("reconnectMaxMs"), l.reconnectMaxMs);
            links.append(o);
        }
        root->insert(QLatin1String("watchLinks"), links);
    }
    if (watches.log) {
        const WatchLogSettings &l = *watches.log;
        QJsonObject o;
        o.insert(QLatin1String("directory"), l.directory);
        o.insert(QLatin1String("mode"), l.mode == WatchLogSettings::Mode::OnChange ? QStringLiteral("change") : QStringLiteral("poll"));
        if (l.rollBytes > 0)
            o.insert(QLatin1String("rollBytes"), l.rollBytes);
        if (l.rollSeconds > 0)
            o.insert(QLatin1String("rollSeconds"), l.rollSeconds);
        if (!l.enabled)
            o.insert(QLatin1String("enabled"), false);
        root->insert(QLatin1String("watchLog"), o);
    }
}

} // namespace mbscope
