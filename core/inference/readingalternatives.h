#pragma once

#include "valueguess.h"

#include "protocol/registerformat.h"

#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// One way to read a guess's words: a format and a power of ten.
struct Reading {
    RegisterFormat format;
    double scale = 1;

    [[nodiscard]] QString label() const; // "f32-cdab", "i16 x0.1"
    // The words (wire order) read this way, as a person writes the number; "" when they are too few.
    [[nodiscard]] QString valueText(const QList<quint16> &words) const;
    friend bool operator==(const Reading &, const Reading &) = default;
};

// The readings the window's Infer shows side by side under a guess, so that a person picks the one
// whose numbers they recognise: the guess first, then the other readings of the same registers
// (one register: u16 and i16 at x1, x0.1, x0.01, x0.001; two: u32, i32 and f32 in ABCD and CDAB,
// the integers at the guess's scale; four: u64 and f64 in ABCD and DCBA). Strings and bits have
// none but the guess.
class ReadingAlternatives
{
public:
    static constexpr int kMost = 8;
    [[nodiscard]] static QList<Reading> of(const ValueGuess &guess);
};

} // namespace mbscope
