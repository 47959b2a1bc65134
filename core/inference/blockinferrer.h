#pragma once

#include "blocksamples.h"
#include "valueguess.h"

#include <QtCore/QList>

namespace mbscope {

// Everything inference proposes for one sampled block: TypeInferrer cuts it into typed values,
// each value's kind is read from how it moved, ScaleInferrer adds scale and unit. Bits (01, 02)
// are one guess each: still (constant) or changing (status). A pure function of the samples.
class BlockInferrer
{
public:
    [[nodiscard]] static QList<ValueGuess> infer(const BlockSamples &block);
    // Every block of one unit, then what crosses blocks (ScaleInferrer::applyNeighbours): the
    // guesses of each block, in the blocks' order. What `mbscope infer` and the window's Infer run.
    [[nodiscard]] static QList<QList<ValueGuess>> inferUnit(const QList<BlockSamples> &blocks);
    // How a series of values moved: constant, counter, measurement or status bits (words: the raw
    // words of a one-register value, for the bit test; empty for wider values).
    [[nodiscard]] static ValueKind kindOf(const QList<double> &values, const QList<quint16> &words, QString *why);
};

} // namespace mbscope
