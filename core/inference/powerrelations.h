#pragma once

#include "blocksamples.h"
#include "valueguess.h"

#include <QtCore/QList>

namespace mbscope {

// Scales that the physics of an electricity meter fixes, from relations between the registers
// of one block (read together, so every sample is one moment), once ScaleInferrer has recognised
// the phase voltages and power factors:
// - apparent power S = V x I: a moving register y whose ratio to a voltage times another moving
//   register x stays at one power of ten over the samples (within 2 %) makes x a current and y an
//   apparent power; with a power factor register, P = V x I x PF makes y an active power;
// - reactive power: |Q| = sqrt(S^2 - P^2) of a phase whose S and P are known;
// - totals: a register equal to the sum of three values of one quantity (W, VA, var, A).
// The relations fix the ratio of a current's scale to its power's, not the pair: the power takes
// the voltage's scale (a meter computes it from the voltage, in the same steps), said in the
// evidence with a lower confidence. Only integer measurements still at scale 1 with no quantity
// are given one; floats get the quantity and unit alone.
class PowerRelations
{
public:
    static void apply(QList<ValueGuess> &guesses, const BlockSamples &block);
};

} // namespace mbscope
