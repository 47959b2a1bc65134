#pragma once

#include "transport/linkurl.h"

#include <QtCore/QtGlobal>

#include <algorithm>

#include <chrono>

namespace mbscope {

// How the engine talks on a link, beyond what the target URL says.
struct EngineOptions {
    // Requests in flight at once. Above 1 only on MBAP links (tcp, tls, udp), where transaction
    // ids tell answers apart (Messaging on TCP/IP V1.0b, 4.2: a client may send several requests
    // without waiting); the engine then gives each request a transaction id of its own and marks
    // the record (Transaction::transactionIdRewritten). Serial framings carry one at a time.
    int pipelineDepth = 1;
    // After a broadcast (unit 0 on a serial framing) the client waits this long before the next
    // request so that every server has acted on it (Serial Line V1.02, 2.4.1: "turnaround delay",
    // typically 100 to 200 ms).
    int broadcastTurnaroundMs = 100;
    // RTU over TCP has no line silence to end a frame the length rule cannot; bytes still waiting
    // in the framer after this much quiet are taken as ended, as a serial line's t3.5 would end
    // them (a gateway forwards a frame whole, so a gap this long is never inside one). Serial links
    // use t3.5 from the baud rate (Serial Line V1.02, 2.5.1.1); datagrams end at their boundary.
    int streamSilenceMs = 50;
    // How many timed-out requests wait for a late answer (oldest forgotten first).
    int lateWindow = 32;
    // How often observers get batched updates, at most (~30 a second).
    int batchIntervalMs = 33;
    // The device's pace (a profile's limits.minGapMs and warmUpMs, or poll's --gap and --warm-up):
    // no request is written sooner than requestGap after the one before it was written, nor
    // sooner than requestGap after the previous exchange ended (its answer's last byte, its
    // timeout, its link error); none sooner than warmUp after the link opened (every time it
    // opens: a device that hangs up after each answer warms up again). Zero: no wait.
    std::chrono::nanoseconds requestGap{0};
    std::chrono::nanoseconds warmUp{0};
    // The device hangs up after each answer (a profile's limits.closesAfterAnswer): once an
    // exchange ends with nothing else in flight the engine closes the link itself, and opens a new
    // one for the next request, instead of writing into a connection the device is closing. One
    // request in flight at a time.
    bool closeAfterAnswer = false;

    // These options holding at least the target's own pace (its gap=, warmup=, close=each): the
    // longer of each wait, a new connection for each request when either asks for it.
    [[nodiscard]] EngineOptions withPaceOf(const LinkUrl &url) const
    {
        EngineOptions paced = *this;
        paced.requestGap = std::max<std::chrono::nanoseconds>(requestGap, url.gap);
        paced.warmUp = std::max<std::chrono::nanoseconds>(warmUp, url.warmUp);
        paced.closeAfterAnswer = closeAfterAnswer || url.closeAfterAnswer;
        return paced;
    }
};

} // namespace mbscope
