#pragma once

#include "valueguess.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

namespace mbscope {

// Inference's guesses as a device profile draft (docs/profiles.md) that `mbscope simulate
// --profile FILE` serves: one unit, a table entry per guessed value with its type, scale, unit and
// the last value read, a generator that moves it as it moved (a random walk within the range seen,
// a counter at the rate seen), and every guess marked as one: each entry's description starts
// "guess" and says the kind, the confidence and the evidence, or "confirmed" when a person
// confirmed or corrected it (the window's Infer). The unit answers the read functions sampled.
class InferenceDraft
{
public:
    [[nodiscard]] static QByteArray toJson(const QList<ValueGuess> &guesses, quint8 unit, const QString &name,
                                           const QString &source, int intervalMs);
};

} // namespace mbscope
