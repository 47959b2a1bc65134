#include "watchruleevaluator.h"

#include "watch/watchdecoder.h"

namespace mbscope {

QString watchSeverityName(WatchSeverity severity)
{
    switch (severity) {
    case WatchSeverity::Info: return QStringLiteral("info");
    case WatchSeverity::Warning: return QStringLiteral("warning");
    case WatchSeverity::Alarm: return QStringLiteral("alarm");
    }
    return {};
}

WatchRuleEvaluator::WatchRuleEvaluator(const WatchDefinition &watch)
    : m_watch(watch)
{
    m_states.reserve(watch.rules.size());
    for (const WatchRule &rule : watch.rules) {
        State state;
        state.address = ruleAddress(watch, rule.point);
        m_states.append(state);
    }
}

int WatchRuleEvaluator::ruleAddress(const WatchDefinition &watch, const QString &point)
{
    for (const WatchPoint &p : watch.points) {
        if (!p.name.isEmpty() && p.name == point)
            return p.address;
    }
    bool ok = false;
    const QString text = point.trimmed();
    const uint address = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? text.mid(2).toUInt(&ok, 16)
                                                                                    : text.toUInt(&ok, 10);
    if (!ok || address < watch.address || address >= uint(watch.address) + watch.quantity)
        return -1;
    return int(address);
}

bool WatchRuleEvaluator::holds(const WatchRule &rule, double value, quint64 raw)
{
    switch (rule.condition) {
    case WatchRule::Condition::Above: return value > rule.high;
    case WatchRule::Condition::Below: return value < rule.low;
    case WatchRule::Condition::Outside: return value < rule.low || value > rule.high;
    case WatchRule::Condition::Inside: return value >= rule.low && value <= rule.high;
    case WatchRule::Condition::Equal: return value == rule.low;
    case WatchRule::Condition::NotEqual: return value != rule.low;
    case WatchRule::Condition::Bits: return (raw & quint64(rule.low)) != 0;
    }
    return false;
}

QString WatchRuleEvaluator::message(const WatchRule &rule, const QString &pointName, const QString &unit)
{
    if (!rule.message.isEmpty())
        return rule.message;
    const auto n = [&unit](double v) {
        return unit.isEmpty() ? WatchDecoder::numberText(v) : WatchDecoder::numberText(v) + QLatin1Char(' ') + unit;
    };
    QString condition;
    switch (rule.condition) {
    case WatchRule::Condition::Above: condition = QStringLiteral("above %1").arg(n(rule.high)); break;
    case WatchRule::Condition::Below: condition = QStringLiteral("below %1").arg(n(rule.low)); break;
    case WatchRule::Condition::Outside: condition = QStringLiteral("outside %1 to %2").arg(n(rule.low), n(rule.high)); break;
    case WatchRule::Condition::Inside: condition = QStringLiteral("within %1 to %2").arg(n(rule.low), n(rule.high)); break;
    case WatchRule::Condition::Equal: condition = QStringLiteral("equal to %1").arg(n(rule.low)); break;
    case WatchRule::Condition::NotEqual: condition = QStringLiteral("not equal to %1").arg(n(rule.low)); break;
    case WatchRule::Condition::Bits:
        condition = QStringLiteral("has bits 0x%1 set").arg(QString::number(quint64(rule.low), 16).toUpper());
        break;
    }
    QString text = pointName + QLatin1Char(' ') + condition;
    if (rule.forPolls > 1)
        text += QStringLiteral(" for %1 polls").arg(rule.forPolls);
    return text;
}

QList<WatchRuleEvent> WatchRuleEvaluator::evaluate(const QList<WatchPointValue> &values, qint64 timeMs)
{
    QList<WatchRuleEvent> events;
    if (values.isEmpty())
        return events;
    for (int r = 0; r < m_states.size(); ++r) {
        State &state = m_states[r];
        const WatchRule &rule = m_watch.rules.at(r);
        const WatchPointValue *value = nullptr;
        for (const WatchPointValue &v : values) {
            if (v.address == state.address) {
                value = &v;
                break;
            }
        }
        if (!value)
            continue;
        const bool now = holds(rule, value->value, value->raw);
        state.run = now ? state.run + 1 : 0;
        const bool fire = now && !state.active && state.run >= qMax(1, rule.forPolls);
        const bool clear = !now && state.active;
        if (!fire && !clear)
            continue;
        state.active = fire;
        if (fire)
            ++state.fired;
        WatchRuleEvent event;
        event.watchName = m_watch.name;
        event.rule = r;
        event.fired = fire;
        event.severity = rule.severity;
        event.colour = rule.colour;
        // An address no point names, as the watch's lines and CSV columns show it ("0x01AF").
        event.point = value->name.isEmpty()
            ? QStringLiteral("0x") + QString::number(value->address, 16).rightJustified(4, QLatin1Char('0')).toUpper()
            : value->name;
        event.value = value->value;
        event.message = message(rule, event.point, value->unit);
        event.timeMs = timeMs;
        event.firedCount = state.fired;
        events.append(event);
    }
    return events;
}

} // namespace mbscope
