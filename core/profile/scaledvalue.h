#pragma once

#include "protocol/registerformat.h"
#include "protocol/registervalue.h"

#include <QtCore/QList>

#include <span>
#include <utility>

namespace mbscope {

// A register value with engineering meaning, as device profiles describe it:
//   value = raw * scale + offset        raw = (value - offset) / scale
// where raw is the number the format holds. Integer formats round raw to the nearest integer
// (halves away from zero); hex, bin and ascii formats are 16-bit unsigned numbers here.
struct ScaledValue {
    RegisterFormat format;
    double scale = 1;
    double offset = 0;

    // Fails with a message when the raw value is out of the format's range (or not finite for an
    // integer format). With clamp, out-of-range values take the nearest end instead (generators).
    [[nodiscard]] RegisterValueResult encode(double value, bool clamp = false) const;
    [[nodiscard]] double decode(std::span<const quint16> registers) const;
    // The engineering values the format can hold, lowest first.
    [[nodiscard]] std::pair<double, double> range() const;
    // The raw range of the format as numbers.
    [[nodiscard]] static std::pair<double, double> rawRange(RegisterFormat format);
};

} // namespace mbscope
