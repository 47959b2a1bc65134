#pragma once

#include "blocksamples.h"
#include "valueguess.h"

#include <QtCore/QList>

namespace mbscope {

// Proposes each value's scale (a power of ten) and unit:
// - a scale-factor register, as SunSpec devices have: a register that stays at a small negative
//   number (-1 to -6 as i16) right after moving values scales those values by 10^n; counted only
//   when a block has two or more such registers;
// - else a quantity the values are recognised as at one power of ten: 230 V mains voltage
//   (207-253 V, 380-420 V line to line, within 5 %), frequency (45-65 Hz, within 1 %), power
//   factor (0.3-1), temperature (-40 to 90 degC, tenths of one register only); tenths are tried
//   first, as devices send them most;
// - else 1. Floats keep scale 1; their unit is named the same way.
class ScaleInferrer
{
public:
    // Sets scale, unit, quantity, scaleRegister and scaleEvidence of the guesses of one block (in
    // address order), and their engineering minimum, maximum, last and typical step.
    static void apply(QList<ValueGuess> &guesses, const BlockSamples &block);
    // Across a unit's blocks: a still register of 5.0-90.0 at x0.1 beside temperatures in tenths
    // (16 addresses at most, same table), or among still settings of a device that measures
    // temperatures in tenths, is taken as a temperature in tenths too (a setpoint).
    static void applyNeighbours(QList<ValueGuess> &guesses);
};

} // namespace mbscope
