#pragma once

#include "conformancecheck.h"

#include <QtCore/QList>

namespace mbscope {

// Diagnostics (08) and Read Device Identification (2B/0E): sub-function 0000 echoes its data,
// the sub-functions offered, the three mandatory basic objects (read in stream access, following
// "more follows"), one object by individual access, and exception 03 for an unknown access code.
class IdentityChecks
{
public:
    [[nodiscard]] static QList<ConformanceCheck> checks();
};

} // namespace mbscope
