#pragma once

#include <QtCore/QList>
#include <QtCore/QtGlobal>

namespace mbscope {

// How an endpoint behaves beyond its URL.
struct SimEndpointOptions {
    // A request to a unit id no unit has (Messaging on TCP/IP V1.0b 4.4.1.1; V1.1b3 section 7):
    // Auto answers exception 0B (gateway target device failed to respond) on network endpoints
    // and stays silent on serial lines, where other devices may own the id. FirstUnit answers as
    // the endpoint's first unit on network endpoints, as many TCP servers do (serial lines: silent).
    enum class UnknownUnit : quint8 { Auto, Exception, Ignore, FirstUnit };
    UnknownUnit unknownUnit = UnknownUnit::Auto;
    // Units served here; empty: every unit of the simulator (a gateway to all of them).
    QList<quint8> units;
    // MBAP framings: unit id 0 and 0xFF address "the server itself" (V1.0b 4.4.1.1): when no unit
    // has that id, the lowest unit id of the endpoint answers.
    bool directUnitIds = true;
    // Serial framings: a broadcast (unit 0) answered by the endpoint's first unit, as a request
    // to it, the answer carrying unit 0: the deviation Serial Line V1.02, 2.1 forbids (a profile's
    // "answersBroadcasts", for testing masters and the conformance battery).
    bool answerBroadcasts = false;
    int maxConnections = 64;      // stream endpoints: more are accepted and closed at once; 0: no limit
    // Stream endpoints at maxConnections: a new client knocks the oldest off instead of being refused.
    bool dropOldestConnection = false;
    int idleTimeoutMs = 0;        // stream endpoints: close a client silent this long; 0: never
    int streamSilenceMs = 1000;   // stream endpoints: drop an unfinished frame after this quiet
};

} // namespace mbscope
