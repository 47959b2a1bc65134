#pragma once

#include "transport/linkurl.h"

#include <QtCore/QString>

#include <algorithm>

namespace mbscope {

// What a unit scan asks, of which ids, and how long it may take. A read only: function 01-04
// (never a write), so scanning a live plant changes nothing.
struct UnitScanSettings {
    LinkUrl url;
    int firstUnit = 1;     // 1-247 by default: the serial line's individual addresses (Serial Line V1.02, 2.2)
    int lastUnit = 247;
    quint8 function = 3;   // 01, 02, 03 or 04
    quint16 address = 0;
    quint16 quantity = 1;
    int timeoutMs = 200;   // per id
    int gapMs = 20;        // quiet line between the end of one probe and the next request
    qint64 maxDurationMs = 600000; // the whole scan stops after this long, whatever is left

    // Empty when the settings can be used, else what is wrong ("--last 300: unit ids are 0-255").
    // Unit 0 is only asked over MBAP (tcp, tls, udp), where it addresses the server itself; on a
    // serial framing it is the broadcast address, which nobody answers.
    [[nodiscard]] QString problem() const;
    [[nodiscard]] int idCount() const { return lastUnit - firstUnit + 1; }
    // Before the first probe: the longest the scan can take (every id silent).
    [[nodiscard]] qint64 worstCaseMs() const { return qint64(idCount()) * (timeoutMs + gapMs); }
    // The gap the scan keeps: the longer of gapMs and the target's own gap= (which the engine
    // holds anyway), so that what the scan says and estimates is what it does.
    void keepTargetPace() { gapMs = std::max<int>(gapMs, int(url.gap.count())); }
};

} // namespace mbscope
