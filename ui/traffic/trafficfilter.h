#pragma once

#include "exchange/responsematcher.h"
#include "exchange/trafficentry.h"

namespace mbscope {

// Which traffic rows are shown: by unit, function code, direction and verdict. Everything passes
// by default; a filter that passes everything lets the model skip its index of shown rows.
class TrafficFilter
{
public:
    static constexpr quint32 kAllVerdicts = (quint32(1) << kTrafficVerdictCount) - 1;

    int unit = -1;      // -1: any unit
    int function = -1;  // -1: any; a code matches its exception responses too (0x83 for 0x03)
    int direction = -1; // -1: both, else a TrafficDirection
    quint32 verdicts = kAllVerdicts; // one bit per TrafficVerdict

    void setVerdict(TrafficVerdict verdict, bool shown);
    [[nodiscard]] bool showsVerdict(TrafficVerdict verdict) const;
    [[nodiscard]] bool acceptsAll() const;
    // A frame with its unit and function code (for an empty frame in: its request's).
    [[nodiscard]] bool accepts(const TrafficEntry &frame, const FrameKeys &keys) const;

    friend bool operator==(const TrafficFilter &, const TrafficFilter &) = default;
};

} // namespace mbscope
