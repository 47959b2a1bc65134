#pragma once

#include "fleet/watchcounters.h"
#include "fleet/watchlinkstate.h"
#include "fleet/watchsample.h"
#include "watch/watchruleevent.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace mbscope::app {

// What `mbscope watch` prints: a line (or a JSON object) per poll, rule event and link change,
// and the counters of each watch at the end.
class WatchReport
{
public:
    // "06:15:01.234 gamma #3 ok 4.2 ms | high voltage 1050 V | 0x007A 0"
    [[nodiscard]] static QString sampleLine(const WatchSample &sample);
    // "06:15:01.234 gamma: timeout: no answer within 1000 ms"
    [[nodiscard]] static QString errorLine(const WatchSample &sample);
    // "06:15:02.001 gamma ALARM: counts above 300 counts for 3 polls (312)"; "... cleared: ..."
    [[nodiscard]] static QString ruleLine(const WatchRuleEvent &event);
    // "gamma: 120 polls, 118 ok, 2 timeouts ...; latency min 2.1 ms, mean 4.3 ms, max 9.8 ms"
    [[nodiscard]] static QString countersLine(const WatchCounters &counters);

    [[nodiscard]] static QJsonObject sampleJson(const WatchSample &sample);
    [[nodiscard]] static QJsonObject ruleJson(const WatchRuleEvent &event);
    [[nodiscard]] static QJsonObject linkJson(const WatchLinkState &state);
    [[nodiscard]] static QJsonObject countersJson(const WatchCounters &counters);
    [[nodiscard]] static QString timeText(qint64 ms); // local time of day with ms
    [[nodiscard]] static QString isoTime(qint64 ms);  // ISO 8601 UTC with ms
};

} // namespace mbscope::app
