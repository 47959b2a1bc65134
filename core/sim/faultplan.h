#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QStringList>

namespace mbscope {

// What the simulator does with one answer after the fault rules have spoken: the endpoint
// executes the plan, the fault injector (FaultInjector) makes it. A plan without faults is one
// chunk holding the whole answer with the unit's response delay.
struct ResponseChunk {
    QByteArray bytes;   // bytes to write (may be junk, a duplicate answer, or part of the answer)
    qint64 delayNs = 0; // wait this long after the previous chunk (the first: after the request)
};

struct FaultPlan {
    bool drop = false;            // no answer at all
    bool closeBefore = false;     // close the connection instead of answering
    bool closeAfter = false;      // close the connection after the last chunk
    QList<ResponseChunk> chunks;  // in order; empty when drop or closeBefore
    QStringList faults;           // the rules that fired (their names, else their kinds), for logs
    QString closeReason;          // why it closes, for the log; empty: a fault rule
    // The id the Simulator logged the request with (Simulator::setTrafficLog), so that the
    // answer's frames carry it too and a journal pairs them; 0 when no traffic log is set.
    quint64 trafficId = 0;
};

} // namespace mbscope
