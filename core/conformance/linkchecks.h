#pragma once

#include "conformancecheck.h"

#include <QtCore/QList>

namespace mbscope {

// What the link and the line ask of a device whatever its functions: on serial framings no
// answer to a broadcast, to a reserved unit id or to a frame whose checksum is wrong (Serial Line
// V1.02); on connections, the connection kept open across requests, a second client served, a
// new connection after the master closed one (TCP/IP Guide V1.0b, 4.2); everywhere, one answer per
// request, silence or an exception for a request cut short, and the distribution of response times.
class LinkChecks
{
public:
    [[nodiscard]] static QList<ConformanceCheck> checks();
    // Run last, over every frame the battery read: answers that came after their timeout, and
    // frames that answered nothing (a second copy, bytes no request asked for).
    [[nodiscard]] static QList<ConformanceCheck> afterChecks();
};

} // namespace mbscope
