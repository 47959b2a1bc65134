#pragma once

#include "common/requestoptions.h"

#include <QtCore/QMap>
#include <QtCore/QStringList>

namespace mbscope {
class LinkUrl;
}

namespace mbscope::app {

// What poll and sweep do with a device's largest request (a profile's limits.maxQuantity, given
// with --profile; docs/guide/poll.md, "The device's pace"). The pace itself (limits.minGapMs and
// warmUpMs, or --gap and --warm-up) is the engine's: EngineOptions::requestGap and warmUp.
class DevicePace
{
public:
    // Cuts each read the read options built (--function or -t, --address, --quantity) that asks more than
    // maxQuantity of its function into consecutive reads of at most that many, each ending on a
    // whole value of every --format, sent one after the other in the cycle. Requests sent as typed
    // (--hex) and writes are sent as given. Returns a line for each request it cut and each it
    // left over the device's limit, for standard error; source names where the limits came from.
    struct Fit {
        QStringList notes;
        int cut = 0;        // requests cut into several
        int sentOver = 0;   // requests over the limit sent as given
        int unchecked = 0;  // requests sent as typed that are no frame of the link's framing
    };
    [[nodiscard]] static Fit fitReads(RequestPlan &plan, const QMap<quint8, int> &maxQuantity, const LinkUrl &url,
                                      const QString &source);
};

} // namespace mbscope::app
