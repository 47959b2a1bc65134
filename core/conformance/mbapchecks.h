#pragma once

#include "conformancecheck.h"

#include <QtCore/QList>

namespace mbscope {

// MODBUS Messaging on TCP/IP V1.0b: the MBAP header of an answer (transaction id and unit id
// echoed, protocol id 0, length right), a request of another protocol discarded, unit 0xFF
// answered, pipelined requests each answered by its transaction id.
class MbapChecks
{
public:
    [[nodiscard]] static QList<ConformanceCheck> checks();
};

} // namespace mbscope
