#pragma once

#include "dissection.h"

#include <QtCore/QByteArray>

namespace mbscope {

struct DissectOptions {
    Framing framing = Framing::Auto;
    Direction direction = Direction::Auto;
    QByteArray request; // the matching request, in the same framing; empty when unknown
};

// Bytes in, fields out. Pure: no I/O, no globals; never throws, crashes or loops on any input.
class Dissector
{
public:
    [[nodiscard]] static Dissection dissect(const QByteArray &frame, const DissectOptions &options = {});
    // Reuses out's capacity: no allocation per frame once warmed up (explicit framing and direction).
    static void dissect(const QByteArray &frame, const DissectOptions &options, Dissection &out);
};

} // namespace mbscope
