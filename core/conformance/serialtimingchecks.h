#pragma once

#include "conformancecheck.h"

#include <QtCore/QList>

namespace mbscope {

// The line timing a slave keeps on an RTU serial port (Serial Line V1.02, 2.5.1.1): its answer
// starts no sooner than t3.5 after the request, and no silence inside the answer exceeds t1.5.
// Judged from the times the engine records for each answer (the request's computed end on the
// line, the first and the last read of the answer); the host's reads can only make a byte look
// later than it came, so a violation those times prove fails, and what they cannot show (a pseudo
// terminal that outruns the line, an answer gathered into one read) is "not judged" with why.
class SerialTimingChecks
{
public:
    [[nodiscard]] static QList<ConformanceCheck> checks();
};

} // namespace mbscope
