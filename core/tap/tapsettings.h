#pragma once

#include "taproute.h"

#include "engine/engineoptions.h"

#include <QtCore/QList>

namespace mbscope {

// How the inline tap forwards (TapForwarder; `mbscope tap`'s options).
struct TapSettings {
    // What a master gets when the tap has nothing to give it: its device did not answer (or the
    // link to it failed, or its answer was damaged on the way), or no route serves the unit.
    enum class NoAnswer : quint8 {
        Auto,      // exceptions to Modbus/TCP and UDP masters, silence to serial masters (a serial
                   // master cannot tell a gateway from the device it asked)
        Exception, // 0B gateway target device failed to respond; 0A gateway path unavailable
        Silence,   // nothing: the master times out as if it talked to the device directly
    };
    // What a write gets in read-only mode.
    enum class Refusal : quint8 {
        Exception, // 01 illegal function: the master learns that writes are not allowed here
        Silence,   // nothing
    };

    QList<TapRoute> routes;    // the first that serves a unit takes it
    int timeoutMs = 1000;      // response timeout of a request, unless its route's URL gives timeout=
    int retries = 0;           // further attempts after a timeout or an unusable answer; reads only:
                               // a write is sent once, as its master sent it
    NoAnswer noAnswer = NoAnswer::Auto;
    // Writes (and the Diagnostics sub-functions that change a device, RecordedWrite) are not
    // forwarded: a tap on a production line cannot change a device by accident.
    bool readOnly = false;
    Refusal refusal = Refusal::Exception;
    // The engine of each target: pipelineDepth above 1 lets several requests be in flight on a
    // Modbus/TCP target (the masters' requests then wait for one another less).
    EngineOptions engine;

    // The route serving a master's unit id, nullptr when none does.
    [[nodiscard]] const TapRoute *routeFor(int unit) const
    {
        for (const TapRoute &route : routes) {
            if (route.serves(unit))
                return &route;
        }
        return nullptr;
    }
};

// What the tap has done since it started (the end line of `mbscope tap`, its metrics).
struct TapCounters {
    quint64 requests = 0;      // taken from masters
    quint64 forwarded = 0;     // sent on to a device
    quint64 answered = 0;      // normal answers passed back
    quint64 exceptions = 0;    // exception answers of devices passed back
    quint64 noAnswer = 0;      // devices that did not answer in time (after retries)
    quint64 linkErrors = 0;    // a target's link failed
    quint64 damaged = 0;       // answers not passed back whole: a bad checksum on the way
    quint64 noRoute = 0;       // units no route serves
    quint64 refusedWrites = 0; // writes refused by read-only mode
    quint64 broadcasts = 0;    // serial broadcasts forwarded (nobody answers them)
    quint64 resent = 0;        // reads sent once more after the link failed under them
    quint64 deviceLatencyNsSum = 0; // of the answered and the exceptions: the devices' own time
    quint64 deviceLatencyCount = 0;
};

} // namespace mbscope
