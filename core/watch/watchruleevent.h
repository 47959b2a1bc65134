#pragma once

#include "watch/watchdefinition.h"

#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace mbscope {

// A rule of a watch that started or stopped holding (after its forPolls consecutive polls).
struct WatchRuleEvent {
    int watch = -1;              // index in SessionWatches::watches (the runner sets it)
    QString watchName;
    int rule = -1;               // index in WatchDefinition::rules
    bool fired = true;           // false: cleared
    WatchSeverity severity = WatchSeverity::Warning;
    QString colour;              // the rule's colour, empty: the severity's
    QString point;               // the point's name, or for an address no point names "0x01AF" (upper-case hex, as elsewhere)
    double value = 0;            // the value that fired or cleared it
    QString message;             // the rule's message, or one made from the rule
    qint64 timeMs = 0;           // milliseconds since the epoch, UTC
    quint64 firedCount = 0;      // how often this rule has fired since the watch started

    friend bool operator==(const WatchRuleEvent &, const WatchRuleEvent &) = default;
};

[[nodiscard]] QString watchSeverityName(WatchSeverity severity); // "info", "warning", "alarm"

} // namespace mbscope

Q_DECLARE_METATYPE(mbscope::WatchRuleEvent)
