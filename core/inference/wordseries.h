#pragma once

#include "blocksamples.h"

#include "protocol/registerformat.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace mbscope {

// Small measures over the samples of one register or one value, shared by the inferrers.
namespace WordSeries {

// Every sample of the value at offset read with format (empty when a sample is too short).
[[nodiscard]] QList<double> decode(const BlockSamples &block, int offset, RegisterFormat format);
[[nodiscard]] bool isConstant(const QList<quint16> &words, std::optional<quint16> value = std::nullopt);
[[nodiscard]] bool isConstant(const QList<double> &values);
// The sum of the sizes of the changes from sample to sample.
[[nodiscard]] double totalVariation(const QList<quint16> &words);
[[nodiscard]] double totalVariation(const QList<double> &values);
// The bits of the largest change of one word from sample to sample (0: never changes).
[[nodiscard]] int largestJumpBits(const QList<quint16> &words);
// The median size of a change (0 when nothing changes).
[[nodiscard]] double medianStep(const QList<double> &values);
// ", smooth" when the changes are small against the range, else ", jumpy".
[[nodiscard]] QString smoothness(const QList<double> &values);
// Whether a moving float series moves as measurements do: the binary exponent jumps by 2 or
// more (a factor of 4) in at most a fifth of the steps (zeros and sign changes aside).
[[nodiscard]] bool smoothExponent(const QList<double> &values);
// The significant digits of the shortest text that reads back to value (as a float when single).
[[nodiscard]] int significantDigits(double value, bool single);
// Never falls and rises at least once (a counter's low word between carries).
[[nodiscard]] bool countsUp(const QList<quint16> &words);
// A number as a person writes it: at most 7 significant digits.
[[nodiscard]] QString number(double value);

enum class Strength : quint8 { None, Weak, Medium, Strong };
// Whether hi and lo (already in natural significance) are the words of one integer, and why.
struct PairEvidence {
    Strength strength = Strength::None;
    bool negative = false; // the integer is signed: negative values seen
    QString text;
};
[[nodiscard]] PairEvidence pairEvidence(const QList<quint16> &hi, const QList<quint16> &lo);

} // namespace WordSeries

} // namespace mbscope
