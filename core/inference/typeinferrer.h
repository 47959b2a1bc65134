#pragma once

#include "blocksamples.h"
#include "typedfield.h"

#include <QtCore/QList>

namespace mbscope {

// Cuts a block of registers into values and names each one's type and order, from the samples
// alone (pure functions: no I/O):
// - strings first: runs of constant registers whose bytes are printable ASCII, with their NUL padding;
// - then, for each of the four orders, the best cover of the rest by values, found by dynamic
//   programming over the block: an f32 or f64 whose every sample is finite and of a plausible
//   size, a u32/i32 (u64) whose high word moves only with the low word's carries, is a sign
//   extension, or is small and still while the low word moves, and u16/i16 for what is left. A
//   device uses one order for all its wide values, so the block's order is the one whose cover
//   scores best;
// - registers that stay 0 in a block of two-register values are taken as such values too.
class TypeInferrer
{
public:
    [[nodiscard]] static QList<TypedField> infer(const BlockSamples &block);

    // The IEEE value is finite and of a size a device plausibly reports (0, or 1e-5 to 1e9 in magnitude).
    [[nodiscard]] static bool plausibleFloat(double value);
};

} // namespace mbscope
