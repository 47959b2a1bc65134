#pragma once

#include "exchange/trafficentry.h"
#include "protocol/severity.h"

#include <QtCore/QString>
#include <QtGui/QColor>

namespace mbscope {

// How traffic reads, in one place, so the traffic list and the decode view agree: a verdict's
// severity (its colour comes from SeverityStyle), its words, and the colour of a direction.
class TrafficStyle
{
public:
    // Ok and Sent are fine; Broadcast is information; Exception, Late and Unsolicited are worth a
    // look (the device answered, just not as hoped or not when expected); the rest are errors.
    [[nodiscard]] static Severity severity(TrafficVerdict verdict);
    // "ok", "crc error", "link error": trafficVerdictName with spaces.
    [[nodiscard]] static QString verdictText(TrafficVerdict verdict);
    // "→ out", "← in".
    [[nodiscard]] static QString directionText(TrafficDirection direction);
    // Blue for requests out, green for answers in; lighter on a dark palette.
    [[nodiscard]] static QColor directionColor(TrafficDirection direction);
};

} // namespace mbscope
