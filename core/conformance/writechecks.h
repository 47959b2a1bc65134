#pragma once

#include "conformancecheck.h"

#include <QtCore/QList>

namespace mbscope {

// The write functions, run only on the addresses the user named writable (--writable), each
// putting back the value it found: 05 echoes and takes only FF00/0000, 06 echoes, 0F and 10 echo
// address and quantity and check the byte count against the quantity, 16 masks, 17 writes before
// it reads.
class WriteChecks
{
public:
    [[nodiscard]] static QList<ConformanceCheck> checks();
};

} // namespace mbscope
