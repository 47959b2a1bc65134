#pragma once

#include "watch/watchdefinition.h"
#include "watch/watchpointvalue.h"
#include "watch/watchruleevent.h"

#include <QtCore/QList>

namespace mbscope {

// The rules of one watch, poll after poll: a rule fires once its condition has held for forPolls
// consecutive good polls, and clears on the first good poll it does not hold. A failed poll (no
// values) neither advances nor breaks a run. Events carry the watch's name and the rule's index;
// the caller sets the watch index and time.
class WatchRuleEvaluator
{
public:
    WatchRuleEvaluator() = default;
    explicit WatchRuleEvaluator(const WatchDefinition &watch);

    // The events of this poll's values (fired or cleared), in rule order.
    QList<WatchRuleEvent> evaluate(const QList<WatchPointValue> &values, qint64 timeMs = 0);

    [[nodiscard]] bool isActive(int rule) const { return m_states.at(rule).active; }
    [[nodiscard]] quint64 firedCount(int rule) const { return m_states.at(rule).fired; }

    // Whether the condition holds for a value (raw for the bits condition).
    [[nodiscard]] static bool holds(const WatchRule &rule, double value, quint64 raw);
    // "pressure above 1100 hPa for 3 polls" (the rule's message when it has one).
    [[nodiscard]] static QString message(const WatchRule &rule, const QString &pointName, const QString &unit);
    // The address a rule's point names in the watch, or -1: a point's name, or an address as a
    // number ("121", "0x0079") within the watch's block.
    [[nodiscard]] static int ruleAddress(const WatchDefinition &watch, const QString &point);

private:
    struct State {
        int address = -1;
        int run = 0;
        bool active = false;
        quint64 fired = 0;
    };
    WatchDefinition m_watch;
    QList<State> m_states;
};

} // namespace mbscope
