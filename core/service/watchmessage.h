#pragma once

#include "fleet/watchsample.h"
#include "watch/watchdefinition.h"
#include "watch/watchruleevent.h"

#include <QtCore/QByteArray>
#include <QtCore/QString>

namespace mbscope {

// The JSON the watch service publishes to MQTT, one compact object per message:
//   PREFIX/WATCH        a poll: {"watch":"boiler","target":"tcp://10.0.0.5:502","unit":1,"poll":12,
//                       "time":"2026-11-26T06:00:00.123Z","status":"ok","latency_seconds":0.0012,
//                       "values":{"pressure":1013.2,"0x007A":7},"units":{"pressure":"hPa"},
//                       "bits":{"flags":{"door":"open","mode":3}}}
//                       failed polls: "status" timeout, exception, crc_error or error, "error" says
//                       what, "exception_code" for exceptions; no values.
//   PREFIX/WATCH/event  a rule that fired or cleared: {"watch","rule","fired","severity","point",
//                       "value","message","time"}
// Values are keyed by the point's name, an address no point names by its hex address ("0x007A").
class WatchMessage
{
public:
    [[nodiscard]] static QByteArray sample(const WatchDefinition &watch, const WatchSample &sample);
    [[nodiscard]] static QByteArray ruleEvent(const WatchRuleEvent &event);
    // A watch's name as one topic level: '/', '+', '#' and NUL become '_'.
    [[nodiscard]] static QString topicLevel(const QString &name);
    // "0x007A"
    [[nodiscard]] static QString addressKey(quint16 address);
    [[nodiscard]] static QString timeText(qint64 msSinceEpoch);
};

} // namespace mbscope
