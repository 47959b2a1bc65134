#pragma once

#include "watch/watchdefinition.h"
#include "watch/watchpointvalue.h"

#include <QtCore/QList>

namespace mbscope {

// Reads one answer of a watch into values, address by address: where a point starts, with its
// format and byte order, scale, offset, unit and bit fields; every other address as an unnamed
// u16 (an Enron watch: u32, each address holding a 32-bit value in two registers) or bit.
// A point whose registers run past the words given is left out (a short FIFO answer).
// Pure: the runner, the window and the tests use it alike.
class WatchDecoder
{
public:
    [[nodiscard]] static QList<WatchPointValue> decode(const WatchDefinition &watch, const QList<quint16> &words,
                                                       const QList<bool> &bits);
    // The value of a bit field of a raw register.
    [[nodiscard]] static quint32 bitFieldValue(const WatchBitField &field, quint64 raw);
    // "123.4": a number with at most ten significant digits, no trailing zeros.
    [[nodiscard]] static QString numberText(double value);
};

} // namespace mbscope
